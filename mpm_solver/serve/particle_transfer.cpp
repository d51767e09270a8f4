#include "mpm_solver/serve/particle_transfer.hpp"

#include <cmath>
#include <unordered_map>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::mpm {
namespace {

[[noreturn]] void malformed(const std::string& what) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED, what);
}

/// The array `group`/`name`, checked for dtype T and n x components values
/// (n = 0: any whole multiple of components, which sets n).
template <typename T>
std::vector<T> read_array(const cosim::Message& request, const std::string& operation,
                          const std::string& group, const std::string& name, std::size_t components,
                          std::size_t& n) {
  const cosim::v1::ArrayDescriptor* found = nullptr;
  for (const auto& array : request.header.arrays())
    if (array.group() == group && array.name() == name) found = &array;
  if (found == nullptr)
    malformed(operation + " group '" + group + "': array '" + name + "' is missing");
  if (found->dtype() != cosim::DTypeOf<T>::value)
    malformed(operation + " group '" + group + "': array '" + name + "' must have dtype " +
              cosim::v1::DType_Name(cosim::DTypeOf<T>::value) + ", got " +
              cosim::v1::DType_Name(found->dtype()));
  const cosim::ArrayView<T> view(*found, request.frames.at(found->frame_index()));
  const auto values = view.values();
  if (n == 0 && values.size() % components == 0) n = values.size() / components;
  if (values.size() != n * components)
    malformed(operation + " group '" + group + "': array '" + name + "' has " +
              std::to_string(values.size()) + " values; expected " + std::to_string(n) +
              " particles x " + std::to_string(components));
  return {values.begin(), values.end()};
}

bool has_array(const cosim::Message& request, const std::string& group, const std::string& name) {
  for (const auto& array : request.header.arrays())
    if (array.group() == group && array.name() == name) return true;
  return false;
}

/// flags[p] = 1 for each particle outside the region's box (active axes), else
/// 0 (`flags` is the zone's scratch: no allocation once grown); returns how
/// many are outside.
std::size_t mark_outside(const ParticleSet& ps, const RegionExtent& extent,
                         std::vector<std::uint8_t>& flags) {
  flags.resize(ps.size());
  std::size_t outside = 0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
    flags[p] = extent.contains(x) ? 0 : 1;
    outside += flags[p];
  }
  return outside;
}

void append_batch(const ParticleBatch& batch, const std::string& group, cosim::Message& reply) {
  const std::uint64_t n = batch.size();
  const auto add = [&](const char* name, const auto& values, std::uint64_t components,
                       const char* units) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    cosim::ArraySpec spec{group, name, {}, units};
    if (components > 1) spec.shape = {n, components};
    cosim::add_array(reply, spec, std::span<const T>(values));
  };
  add("id", batch.id, 1, "1");
  add("position", batch.position, 3, "m");
  add("velocity", batch.velocity, 3, "m/s");
  add("mass", batch.mass, 1, "kg");
  add("volume", batch.volume, 1, "m^3");
  add("internal_energy", batch.internal_energy, 1, "J");
  add("material", batch.material, 1, "1");
  add("stress", batch.stress, kVoigt, "Pa");
}

}  // namespace

ParticleBatch read_particle_batch(const cosim::Message& message, const std::string& operation,
                                  const std::string& group) {
  std::size_t n = 0;
  ParticleBatch batch;
  batch.id = read_array<std::uint64_t>(message, operation, group, "id", 1, n);
  batch.position = read_array<double>(message, operation, group, "position", 3, n);
  batch.velocity = read_array<double>(message, operation, group, "velocity", 3, n);
  batch.mass = read_array<double>(message, operation, group, "mass", 1, n);
  batch.volume = read_array<double>(message, operation, group, "volume", 1, n);
  batch.internal_energy = read_array<double>(message, operation, group, "internal_energy", 1, n);
  batch.material = read_array<std::uint32_t>(message, operation, group, "material", 1, n);
  if (has_array(message, group, "stress"))
    batch.stress = read_array<double>(message, operation, group, "stress", kVoigt, n);
  return batch;
}

std::uint64_t inject_particles(MpmSolver& solver, const cosim::v1::InjectParticles& op,
                               const cosim::Message& request) {
  const std::string& group = op.group();
  const std::string operation = "InjectParticles";
  const ParticleBatch batch = read_particle_batch(request, operation, group);
  try {
    solver.inject_particles(batch);
  } catch (const cosim::ProtocolError&) {
    throw;
  } catch (const Error& error) {
    malformed(operation + " group '" + group + "': " + error.what());
  }
  return batch.size();
}

std::uint64_t remove_particles(MpmSolver& solver, const ZoneRegion* left_region,
                               const cosim::v1::RemoveParticles& op, const cosim::Message& request,
                               cosim::Message& reply, ParticleScratch& scratch) {
  const ParticleSet& ps = solver.particles();
  auto& flags = scratch.flags;
  if (left_region != nullptr) {
    if (left_region->kind != cosim::v1::REGION_KIND_PARTICLES)
      throw cosim::ProtocolError(
          cosim::v1::ERROR_CODE_UNKNOWN_REGION,
          "RemoveParticles: left_region '" + left_region->name + "' is not a PARTICLES region");
    const RegionExtent extent(*left_region, solver.grid());
    if (mark_outside(ps, extent, flags) == 0) {  // the usual step: nothing to collect
      if (!op.discard()) append_batch(ParticleBatch{}, op.group(), reply);
      return 0;
    }
  } else {
    std::size_t n = 0;
    const auto ids = read_array<std::uint64_t>(request, "RemoveParticles", op.group(), "id", 1, n);
    flags.assign(ps.size(), 0);
    std::unordered_map<std::uint64_t, std::size_t> index;
    index.reserve(ps.size());
    for (std::size_t p = 0; p < ps.size(); ++p) index.emplace(ps.id[p], p);
    for (const std::uint64_t id : ids) {
      const auto found = index.find(id);
      if (found == index.end())
        malformed("RemoveParticles group '" + op.group() + "': array 'id' names particle " +
                  std::to_string(id) + ", which this zone does not hold");
      flags[found->second] = 1;
    }
  }
  const ParticleBatch removed = solver.remove_particles(flags);
  if (!op.discard()) append_batch(removed, op.group(), reply);
  return removed.size();
}

std::uint64_t export_particle_region(const MpmSolver& solver, const ZoneRegion& region,
                                     const cosim::v1::ExportRegion& request, cosim::Message& reply,
                                     ParticleScratch& scratch) {
  std::vector<std::string> names(request.quantities().begin(), request.quantities().end());
  if (names.empty()) names = region.quantities;
  for (const auto& name : names)
    if (!region.declares(name))
      throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                                 "region '" + region.name + "', quantity '" + name +
                                     "': not declared for it in Setup, so it cannot be exported");
  const ParticleSet& ps = solver.particles();
  auto& members = scratch.members;
  members.clear();
  const RegionExtent extent(region, solver.grid());
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
    if (extent.contains(x)) members.push_back(p);
  }
  const std::uint64_t n = members.size();
  for (const auto& name : names) {
    if (name.starts_with("outflow_")) {  // v1.1: the zone's ledger, one row
      const BoundaryLedger& ledger = solver.boundary_ledger();
      if (name == "outflow_momentum")
        cosim::add_array(reply, {region.name, name, {1, 3}, "kg*m/s"},
                         std::vector<double>(ledger.momentum.begin(), ledger.momentum.end()));
      else
        cosim::add_array(reply, {region.name, name, {}, name == "outflow_mass" ? "kg" : "J"},
                         std::vector<double>{name == "outflow_mass" ? ledger.mass : ledger.energy});
      continue;
    }
    if (name == "id" || name == "material") {
      if (name == "id") {
        std::vector<std::uint64_t> values(n);
        for (std::size_t i = 0; i < n; ++i) values[i] = ps.id[members[i]];
        cosim::add_array(reply, {region.name, name, {}, "1"}, std::move(values));
      } else {
        std::vector<std::uint32_t> values(n);
        for (std::size_t i = 0; i < n; ++i) values[i] = ps.material[members[i]];
        cosim::add_array(reply, {region.name, name, {}, "1"}, std::move(values));
      }
      continue;
    }
    const std::size_t components = name == "position" || name == "velocity" ? 3
                                   : name == "stress"                       ? kVoigt
                                                                            : 1;
    std::vector<double> values(n * components);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t p = members[i];
      double* out = values.data() + i * components;
      if (name == "position" || name == "velocity") {
        const auto& field = name == "position" ? ps.position : ps.velocity;
        for (std::size_t a = 0; a < 3; ++a) out[a] = field[a][p];
      } else if (name == "stress") {
        const double pq = ps.pressure[p] + ps.bulk_viscosity[p];  // sigma = s - (p + q) I
        for (std::size_t c = 0; c < kVoigt; ++c)
          out[c] = ps.deviatoric_stress[kFromVoigt[c]][p] - (c < 3 ? pq : 0.0);
      } else if (name == "mass") {
        out[0] = ps.mass[p];
      } else if (name == "volume") {
        out[0] = ps.mass[p] / ps.density[p];
      } else if (name == "internal_energy") {
        out[0] = ps.mass[p] * ps.specific_internal_energy[p];
      } else {
        out[0] = solver.burn_fraction(p);
      }
    }
    cosim::ArraySpec spec{region.name, name, {}, ""};
    if (components > 1) spec.shape = {n, components};
    cosim::add_array(reply, spec, std::move(values));
  }
  return n;
}

}  // namespace mpfd::mpm
