#include "mpm_solver/mpm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/initial/initial_cells.hpp"
#include "mpm_solver/program_burn.hpp"

namespace mpfd::mpm {
namespace {

using config::BoundaryKind;

/// Runs fn(p) for every particle, block by block in colour order: blocks of one
/// colour share no node, so their scatters run in parallel without races.
template <class Fn>
void for_each_particle_by_colour(const SparseGrid& grid, std::size_t particles, const Fn& fn) {
  const bool parallel = static_cast<std::ptrdiff_t>(particles) >= kMinParallelCount;
#pragma omp parallel if (parallel)
  for (int c = 0; c < SparseGrid::kColours; ++c) {
    const auto slots = grid.colour(c);
    const auto count = static_cast<std::ptrdiff_t>(slots.size());
#pragma omp for schedule(dynamic, 4)
    for (std::ptrdiff_t b = 0; b < count; ++b)
      for (const std::int32_t p : grid.bucket(slots[static_cast<std::size_t>(b)]))
        fn(static_cast<std::size_t>(p));
  }
}

/// Runs fn(n) for every node of the grid.
template <class Fn>
void for_each_node(std::size_t nodes, const Fn& fn) {
  parallel_for(nodes, fn);
}

}  // namespace

MpmSettings MpmSettings::from_scene(const config::Scene& scene) {
  return {.cfl = scene.time.cfl,
          .shape_function = scene.solver.mpm.shape_function,
          .update = scene.solver.mpm.update,
          .bulk_viscosity_quadratic = scene.solver.mpm.bulk_viscosity_quadratic,
          .bulk_viscosity_linear = scene.solver.mpm.bulk_viscosity_linear};
}

MpmSolver::MpmSolver(const config::Scene& scene, MpmSettings settings)
    : settings_(settings), faces_(scene.boundaries.faces), grid_(initial::scene_grid(scene)) {
  const auto& g = grid_.grid();
  min_spacing_ = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    geometry_.origin[a] = g.origin()[a];
    geometry_.inverse_spacing[a] = 1.0 / g.spacing()[a];
    geometry_.offset[a] = grid_.offset()[a];
    if (g.is_active(a)) {
      axis_mask_ |= 1 << a;
      min_spacing_ = std::min(min_spacing_, g.spacing()[a]);
    }
  }
  if (axis_mask_ == 0)
    throw Error("scene '" + scene.name +
                "': mpm needs at least one axis with more than one cell, got cells 1 x 1 x 1");
  viscosity_ = {settings.bulk_viscosity_quadratic, settings.bulk_viscosity_linear, min_spacing_};

  GeneratedParticles generated = generate_particles(scene, g);
  particles_ = std::move(generated.particles);
  bodies_ = std::move(generated.bodies);
  scene_bodies_ = bodies_.size();
  materials_ = scene.materials;
  for (std::size_t p = 0; p < particles_.size(); ++p) particles_.id[p] = kSceneParticleIdBase + p;

  models_.resize(scene.materials.size());
  for (const auto& body : bodies_)
    if (!models_[body.material])
      models_[body.material] = make_constitutive_model(scene.materials[body.material]);
  std::size_t stride = 0;
  for (const auto& m : models_)
    if (m) stride = std::max(stride, static_cast<std::size_t>(m->history_count()));
  particles_.history_stride = stride;
  particles_.history.assign(particles_.size() * stride, 0.0);

  for (std::size_t p = 0; p < particles_.size(); ++p) {
    Tensor3 s = Tensor3::Zero();
    MaterialPoint point = particles_.material_point(p, s);
    models_[particles_.material[p]]->initialise(particles_.density[p], point);
    particles_.pressure[p] *= burn_fraction(p);  // T (3-1)
    particles_.set_deviator(p, s);
  }
  home_slot_.reserve(particles_.size());
  leaving_.reserve(particles_.size());
  compute_stable_dt();
}

MpmSolver::~MpmSolver() = default;

double MpmSolver::burn_fraction(std::size_t p) const {
  return mpm::burn_fraction(time_, particles_.lighting_time[p],
                            bodies_[particles_.body[p]].burn_rate);
}

double MpmSolver::step_toward(double target) const {
  const double left = target - time_;
  if (left <= stable_dt_) return left;
  return left < 2.0 * stable_dt_ ? 0.5 * left : stable_dt_;
}

void MpmSolver::advance_to(double end) {
  while (time_ < end) advance(step_toward(end));
}

void MpmSolver::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error("mpm: time step must be positive and finite, got " + std::to_string(dt));
  rebuild_grid();
  particles_to_grid();
  added_node_state_.clear();  // only this step's loads enter the remap
  if (!node_loads_.empty()) apply_node_loads();
  integrate_nodes(dt);
  if (settings_.update == config::MpmUpdate::musl) {
    update_and_remap_velocities(dt);
  }
  update_particles(dt);
  particle_updates_ += static_cast<double>(particles_.size());
  time_ += dt;
  ++steps_;
  remove_outflow();
  compute_stable_dt();
}

void MpmSolver::rebuild_grid() {
  const std::size_t n = particles_.size();
  home_slot_.resize(n);
  grid_.clear();
  const auto& g = grid_.grid();
  const bool active[3] = {g.is_active(0), g.is_active(1), g.is_active(2)};
  const int width = settings_.shape_function != config::ShapeFunction::linear ? 3 : 2;
  for (std::size_t p = 0; p < n; ++p) {
    grid::Index3 lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      const double x = particles_.position[a][p];
      lo[a] = width == 3 ? first_node<3>(x, a, active[a], geometry_)
                         : first_node<2>(x, a, active[a], geometry_);
      hi[a] = active[a] ? lo[a] + width - 1 : lo[a];
    }
    home_slot_[p] = grid_.activate(lo, hi);
  }
  for (const NodeLoad& load : node_loads_) {  // a coupler's node may lie beyond every stencil
    grid::Index3 node{};
    for (int a = 0; a < 3; ++a) node[a] = load.node[a] + grid_.offset()[a];
    grid_.activate(node, node);
  }
  grid_.allocate_nodes();
  grid_.bin_particles(home_slot_);
}

void MpmSolver::particle_half_width(std::size_t p, double half_width[3]) const {
  const BodyInfo& body = bodies_[particles_.body[p]];
  for (int a = 0; a < 3; ++a) {
    half_width[a] = body.half_width[a];
    // cpGIMP (W §2.3): the domain follows F_aa; at most half a cell, so that
    // three nodes per axis still hold the stencil, and not degenerate.
    if (settings_.shape_function == config::ShapeFunction::cpgimp && grid_.grid().is_active(a))
      half_width[a] = std::clamp(half_width[a] * particles_.stretch[a][p], 1e-3, 0.5);
  }
}

void MpmSolver::particles_to_grid() {
  const auto& ps = particles_;
  double* node_mass = grid_.mass.data();
  double* node_momentum[3] = {grid_.momentum[0].data(), grid_.momentum[1].data(),
                              grid_.momentum[2].data()};
  double* node_force[3] = {grid_.force[0].data(), grid_.force[1].data(), grid_.force[2].data()};
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        using S = Stencil<decltype(width)::value, decltype(mask)::value>;
        for_each_particle_by_colour(grid_, ps.size(), [&](std::size_t p) {
          const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
          S s;
          double half_width[3];
          particle_half_width(p, half_width);
          compute_stencil(x, half_width, geometry_, grid_, s);
          const double m = ps.mass[p];
          const double volume = m / ps.density[p];
          const double v[3] = {ps.velocity[0][p], ps.velocity[1][p], ps.velocity[2][p]};
          // sigma = s - (p + q) I, tension positive.
          const double pq = ps.pressure[p] + ps.bulk_viscosity[p];
          const auto& d = ps.deviatoric_stress;
          const double sigma[3][3] = {{d[kXX][p] - pq, d[kXY][p], d[kZX][p]},
                                      {d[kXY][p], d[kYY][p] - pq, d[kYZ][p]},
                                      {d[kZX][p], d[kYZ][p], d[kZZ][p] - pq}};
          for (int c = 0; c < S::kCount; ++c) {
            const std::size_t node = s.node[c];
            const double wm = s.weight[c] * m;
            node_mass[node] += wm;  // (2-12)
            const double* gr = s.gradient[c];
            for (int i = 0; i < 3; ++i) {
              node_momentum[i][node] += wm * v[i];  // (2-9)
              node_force[i][node] -=                // (2-10)
                  volume * (sigma[i][0] * gr[0] + sigma[i][1] * gr[1] + sigma[i][2] * gr[2]);
            }
          }
        });
      });
}

void MpmSolver::integrate_nodes(double dt) {
  const std::size_t nodes = grid_.node_count();
  auto& momentum = grid_.momentum;
  auto& force = grid_.force;
  for_each_node(nodes, [&](std::size_t n) {
    for (int a = 0; a < 3; ++a) momentum[a][n] += force[a][n] * dt;  // (2-13)
  });
  apply_face_conditions(momentum, &force, dt);
  // From here on the arrays hold velocities and accelerations, p / m and f / m,
  // so the particle passes only multiply. Only massless nodes are skipped: a
  // light node's f / m is large but its weight N_Ip is as small, so N f / m
  // stays bounded, and a relative cut-off (tried: 1e-10 of the lightest
  // particle) broke the momentum balance by 1e-10 with GIMP.
  for_each_node(nodes, [&](std::size_t n) {
    const double m = grid_.mass[n];
    const double inverse = m > 0.0 ? 1.0 / m : 0.0;
    for (int a = 0; a < 3; ++a) {
      momentum[a][n] *= inverse;
      force[a][n] *= inverse;
    }
  });
}

void MpmSolver::apply_face_conditions(std::array<std::vector<double>, 3>& field,
                                      std::array<std::vector<double>, 3>* force, double dt) {
  const auto& g = grid_.grid();
  const std::size_t per_block = grid_.block_nodes();
  for (std::size_t slot = 0; slot < grid_.block_count(); ++slot) {
    const grid::Index3 corner = grid_.node_coordinates(slot * per_block);
    bool touches = false;
    for (int a = 0; a < 3 && !touches; ++a) {
      if (!g.is_active(a)) continue;
      const int reach = 1 << SparseGrid::kBlockShift;
      touches = corner[a] <= 1 || corner[a] + reach - 1 >= g.cells()[a] + 1;
    }
    if (!touches) continue;
    for (std::size_t n = slot * per_block; n < (slot + 1) * per_block; ++n) {
      const grid::Index3 at = grid_.node_coordinates(n);
      for (int a = 0; a < 3; ++a) {
        if (!g.is_active(a)) continue;
        // Storage coordinate <= 1: the node on the lower face or the ghost beyond it.
        const int side = at[a] <= 1 ? 0 : at[a] >= g.cells()[a] + 1 ? 1 : -1;
        if (side < 0) continue;
        const BoundaryKind kind = faces_[static_cast<std::size_t>(2 * a + side)];
        if (kind == BoundaryKind::outflow) continue;
        // wall: fixed, every component zero; symmetry: the normal component zero.
        for (int c = 0; c < 3; ++c) {
          if (kind == BoundaryKind::symmetry && c != a) continue;
          if (force != nullptr) {
            const double before = field[c][n] - (*force)[c][n] * dt;  // p^n
            ledger_.momentum[c] += field[c][n];  // the wall's impulse is -p^{n+1}
            (*force)[c][n] = -before / dt;       // so that (2-15) agrees with (2-13)
          }
          field[c][n] = 0.0;
        }
      }
    }
  }
}

void MpmSolver::update_and_remap_velocities(double dt) {
  auto& ps = particles_;
  const auto& accel = grid_.force;
  double* remapped[3] = {grid_.remapped[0].data(), grid_.remapped[1].data(),
                         grid_.remapped[2].data()};
  // One pass: a particle's v^{n+1} needs only the nodal accelerations (read)
  // and its remap writes only the remapped momenta, so the two share a stencil.
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        using S = Stencil<decltype(width)::value, decltype(mask)::value>;
        for_each_particle_by_colour(grid_, ps.size(), [&](std::size_t p) {
          const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
          S s;
          double half_width[3];
          particle_half_width(p, half_width);
          compute_stencil(x, half_width, geometry_, grid_, s);
          double v[3] = {0.0, 0.0, 0.0};
          for (int c = 0; c < S::kCount; ++c)
            for (int i = 0; i < 3; ++i) v[i] += s.weight[c] * accel[i][s.node[c]];
          for (int i = 0; i < 3; ++i) {
            v[i] = ps.velocity[i][p] + v[i] * dt;  // (2-15)
            ps.velocity[i][p] = v[i];
          }
          const double m = ps.mass[p];
          for (int c = 0; c < S::kCount; ++c) {
            const double wm = s.weight[c] * m;
            for (int i = 0; i < 3; ++i) remapped[i][s.node[c]] += wm * v[i];  // (2-17)
          }
        });
      });
  // The mass and momentum a coupler added (T (4-7), (4-8): the FDM cells next
  // to the zone as particles) move with the node's acceleration like any
  // particle; without them the remapped velocity of such a node is the
  // particles' momentum over particles + FDM mass, about half the flow speed
  // at the CFDMP face, and the particles next to it expand spuriously.
  for (const auto& added : added_node_state_)
    for (int a = 0; a < 3; ++a)
      remapped[a][added.node] += added.momentum[a] + added.mass * accel[a][added.node] * dt;
  for_each_node(grid_.node_count(), [&](std::size_t n) {
    const double m = grid_.mass[n];
    const double inverse = m > 0.0 ? 1.0 / m : 0.0;
    for (int a = 0; a < 3; ++a) remapped[a][n] *= inverse;
  });
  apply_face_conditions(grid_.remapped, nullptr, 0.0);
}

void MpmSolver::update_particles(double dt) {
  auto& ps = particles_;
  const bool musl = settings_.update == config::MpmUpdate::musl;
  const auto& position_velocity = grid_.momentum;  // p^{n+1} / m, (2-16)
  const auto& strain_velocity = musl ? grid_.remapped : grid_.momentum;
  const auto& accel = grid_.force;
  const auto& g = grid_.grid();
  const bool active[3] = {g.is_active(0), g.is_active(1), g.is_active(2)};
  const double t1 = time_ + dt;
  std::size_t collapsed = 0;
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        using S = Stencil<decltype(width)::value, decltype(mask)::value>;
        collapsed = parallel_sum(ps.size(), [&](std::size_t p) -> std::size_t {
          const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
          S s;
          const BodyInfo& body = bodies_[ps.body[p]];
          double half_width[3];
          particle_half_width(p, half_width);
          compute_stencil(x, half_width, geometry_, grid_, s);
          double dx[3] = {0.0, 0.0, 0.0};
          double dv[3] = {0.0, 0.0, 0.0};
          Tensor3 l = Tensor3::Zero();  // velocity gradient sum_I v_iI N_I,j
          for (int c = 0; c < S::kCount; ++c) {
            const std::size_t node = s.node[c];
            for (int i = 0; i < 3; ++i) {
              dx[i] += s.weight[c] * position_velocity[i][node];
              if (!musl) dv[i] += s.weight[c] * accel[i][node];
              for (int j = 0; j < 3; ++j) l(i, j) += strain_velocity[i][node] * s.gradient[c][j];
            }
          }
          for (int i = 0; i < 3; ++i) {
            if (active[i]) ps.position[i][p] += dx[i] * dt;  // (2-16)
            if (!musl) ps.velocity[i][p] += dv[i] * dt;      // (2-15), USL
          }
          StrainStep step;
          step.strain_increment = 0.5 * (l + l.transpose()) * dt;  // (2-18)
          const Tensor3 spin = 0.5 * (l - l.transpose()) * dt;     // (2-19)
          const double volumetric = step.strain_increment.trace();
          if (!(1.0 + volumetric > 0.0)) return 1;
          for (int i = 0; i < 3; ++i)  // F_ii, the cpGIMP domain stretch
            ps.stretch[i][p] *= 1.0 + step.strain_increment(i, i);
          step.dt = dt;
          step.density_old = ps.density[p];
          step.density_new = ps.density[p] / (1.0 + volumetric);  // (2-20)
          step.bulk_viscosity = viscosity_(volumetric / dt, step.density_new, ps.sound_speed[p]);
          step.burn_fraction = mpm::burn_fraction(t1, ps.lighting_time[p], body.burn_rate);
          // (2-21): the Jaumann rotation of the deviator, sigma_ik dW_jk + sigma_jk dW_ik;
          // the isotropic part of sigma is unchanged by it.
          Tensor3 dev = ps.deviator(p);
          dev += dev * spin.transpose() + spin * dev;
          MaterialPoint point = ps.material_point(p, dev);
          models_[ps.material[p]]->update(step, point);
          ps.set_deviator(p, dev);
          ps.density[p] = step.density_new;
          ps.bulk_viscosity[p] = step.bulk_viscosity;
          return 0;
        });
      });
  if (collapsed > 0)
    throw Error("mpm: " + std::to_string(collapsed) +
                " particle(s) collapsed (1 + tr(d eps) <= 0) at t = " + std::to_string(t1) +
                " s; lower time.cfl");
}

void MpmSolver::remove_outflow() {
  auto& ps = particles_;
  const auto& g = grid_.grid();
  leaving_.assign(ps.size(), 0);
  const grid::Vec3 upper = g.upper();
  const std::size_t leaving = parallel_sum(ps.size(), [&](std::size_t p) -> std::size_t {
    for (int a = 0; a < 3; ++a) {
      if (!g.is_active(a)) continue;
      double& x = ps.position[a][p];
      const int side = x < g.origin()[a] ? 0 : x >= upper[a] ? 1 : -1;
      if (side < 0) continue;
      if (faces_[static_cast<std::size_t>(2 * a + side)] == BoundaryKind::outflow) {
        leaving_[p] = 1;
        return 1;
      }
      // A closed face: the nodal condition keeps particles in; round-off may not.
      x = side == 0 ? g.origin()[a] : upper[a] - 1e-9 * g.spacing()[a];
    }
    return 0;
  });
  if (leaving == 0) return;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    if (leaving_[p] == 0) continue;
    const double m = ps.mass[p];
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      ledger_.momentum[a] += m * ps.velocity[a][p];
      v2 += ps.velocity[a][p] * ps.velocity[a][p];
    }
    ledger_.mass += m;
    ledger_.energy += m * (0.5 * v2 + ps.specific_internal_energy[p]);
  }
  ledger_.particles_removed += static_cast<std::int64_t>(ps.remove_flagged(leaving_));
}

void MpmSolver::compute_stable_dt() {
  const auto& ps = particles_;
  double fastest = 0.0;
  const auto count = static_cast<std::ptrdiff_t>(ps.size());
#pragma omp parallel for schedule(static) reduction(max : fastest) if (count >= kMinParallelCount)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const auto p = static_cast<std::size_t>(i);
    const double v2 = ps.velocity[0][p] * ps.velocity[0][p] +
                      ps.velocity[1][p] * ps.velocity[1][p] + ps.velocity[2][p] * ps.velocity[2][p];
    fastest = std::max(fastest, ps.sound_speed[p] + std::sqrt(v2));
  }
  stable_dt_ = fastest > 0.0 ? settings_.cfl * min_spacing_ / fastest
                             : std::numeric_limits<double>::infinity();
}

MpmTotals MpmSolver::totals() const {
  const auto& ps = particles_;
  MpmTotals t;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double m = ps.mass[p];
    t.mass += m;
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      t.momentum[a] += m * ps.velocity[a][p];
      v2 += ps.velocity[a][p] * ps.velocity[a][p];
    }
    t.kinetic_energy += 0.5 * m * v2;
    t.internal_energy += m * ps.specific_internal_energy[p];
  }
  return t;
}

}  // namespace mpfd::mpm
