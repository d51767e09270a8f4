#include "mpm_solver/snapshot_particles.hpp"

namespace mpfd::mpm {

std::vector<io::FieldView> SnapshotParticles::views(const MpmSolver& solver) {
  const ParticleSet& ps = solver.particles();
  const std::size_t n = ps.size();
  for (auto& s : stress_) s.resize(n);
  material_.resize(n);
  body_.resize(n);
  burn_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    // Cauchy stress sigma = s - (p + q) I, tension positive.
    const double pq = ps.pressure[p] + ps.bulk_viscosity[p];
    for (std::size_t c = 0; c < 6; ++c)
      stress_[c][p] = ps.deviatoric_stress[c][p] - (c < 3 ? pq : 0.0);
    material_[p] = ps.material[p];
    body_[p] = ps.body[p];
    burn_[p] = solver.burn_fraction(p);
  }
  return {{"position", "m", {ps.position[0], ps.position[1], ps.position[2]}},
          {"velocity", "m/s", {ps.velocity[0], ps.velocity[1], ps.velocity[2]}},
          {"mass", "kg", {ps.mass}},
          {"density", "kg/m^3", {ps.density}},
          {"pressure", "Pa", {ps.pressure}},
          {"specific_internal_energy", "J/kg", {ps.specific_internal_energy}},
          {"sound_speed", "m/s", {ps.sound_speed}},
          {"stress_xx", "Pa", {stress_[kXX]}},
          {"stress_yy", "Pa", {stress_[kYY]}},
          {"stress_zz", "Pa", {stress_[kZZ]}},
          {"stress_xy", "Pa", {stress_[kXY]}},
          {"stress_yz", "Pa", {stress_[kYZ]}},
          {"stress_zx", "Pa", {stress_[kZX]}},
          {"plastic_strain", "", {ps.equivalent_plastic_strain}},
          {"damage", "", {ps.damage}},
          {"burn_fraction", "", {burn_}},
          {"material", "", {material_}},
          {"body", "", {body_}}};
}

}  // namespace mpfd::mpm
