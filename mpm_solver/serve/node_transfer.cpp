#include "mpm_solver/serve/node_transfer.hpp"

#include <chrono>
#include <cstring>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::mpm {
namespace {

[[noreturn]] void reject(cosim::v1::ErrorCode code, const ZoneRegion& region,
                         std::string_view quantity, const std::string& rule) {
  throw cosim::ProtocolError(
      code, "region '" + region.name + "', quantity '" + std::string(quantity) + "': " + rule);
}

/// Components per node of an apply quantity; 0 when it cannot be applied.
std::size_t apply_components(std::string_view name) {
  if (name == "mass") return 1;
  if (name == "momentum" || name == "internal_force") return 3;
  return 0;
}

NodeLoad::Quantity load_quantity(std::string_view name) {
  if (name == "mass") return NodeLoad::Quantity::mass;
  return name == "momentum" ? NodeLoad::Quantity::momentum : NodeLoad::Quantity::force;
}

void check_apply_array(const ZoneRegion& region, const cosim::v1::ArrayDescriptor& array,
                       std::vector<std::string>& seen) {
  const std::size_t components = apply_components(array.name());
  if (components == 0)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "ApplyRegion on nodes accepts only mass, momentum and internal_force");
  if (!region.declares(array.name()))
    reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION, region, array.name(),
           "not declared for it in Setup");
  if (std::find(seen.begin(), seen.end(), array.name()) != seen.end())
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(), "given twice");
  seen.push_back(array.name());
  if (array.dtype() != cosim::v1::DTYPE_F64)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "dtype must be DTYPE_F64, got " + cosim::v1::DType_Name(array.dtype()));
  std::uint64_t count = 1;
  for (const auto extent : array.shape()) count *= extent;
  const std::size_t expected = region.box_count() * components;
  if (count != expected)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "expected " + std::to_string(expected) + " values (" +
               std::to_string(region.box_count()) + " nodes x " + std::to_string(components) +
               " components), got " + std::to_string(count));
}

/// e_c of T (4-3) per cell of the region's node box, in box C order: the
/// nodal internal energies e_I = sum_p N_Ip m_p e_p at the cell centre, with the
/// weights N_Ic = 2^-Dim of the nodal mass and momentum (4-1), (4-2). T sums the
/// particles inside the cell; that is a different support from (4-1): a cell
/// whose particles had left while its corner nodes kept mass from its
/// neighbours' got e_c = 0, p = 0 (the 2D blast, docs/coupler.md), and the
/// ratio e_c / m_c jumped tenfold between neighbours. With one support
/// e_c / m_c is a mass-weighted mean of the particles' e_p.
std::vector<double> cell_internal_energy(const MpmSolver& solver, const ZoneRegion& region,
                                         std::span<const double> node_energy) {
  const auto& g = solver.grid();
  grid::Index3 nodes{}, cells{};
  int corners = 1;
  for (int a = 0; a < 3; ++a) {
    nodes[a] = region.hi[a] - region.lo[a];
    cells[a] = g.is_active(a) ? nodes[a] - 1 : 1;
    if (g.is_active(a)) corners *= 2;
  }
  const double weight = 1.0 / corners;  // N_Ic at the cell centre
  std::vector<double> energy(region.cell_count(g), 0.0);
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k) {
        double sum = 0.0;
        for (int q = 0; q < 8; ++q) {
          const int di = q & 1, dj = (q >> 1) & 1, dk = (q >> 2) & 1;
          if ((di != 0 && !g.is_active(0)) || (dj != 0 && !g.is_active(1)) ||
              (dk != 0 && !g.is_active(2)))
            continue;
          sum += node_energy[static_cast<std::size_t>(((i + di) * nodes[1] + j + dj) * nodes[2] +
                                                      k + dk)];
        }
        energy[static_cast<std::size_t>((i * cells[1] + j) * cells[2] + k)] = weight * sum;
      }
  return energy;
}

}  // namespace

void apply_node_region(MpmSolver& solver, const ZoneRegion& region,
                       cosim::v1::ApplyRegion::Mode mode, const cosim::Message& request) {
  if (region.kind != cosim::v1::REGION_KIND_NODES)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_UNEXPECTED,
        "ApplyRegion on region '" + region.name +
            "': only NODES regions of an MPM zone take values (particles come "
            "through InjectParticles)");
  if (mode != cosim::v1::ApplyRegion::MODE_SET && mode != cosim::v1::ApplyRegion::MODE_ADD)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "ApplyRegion on region '" + region.name + "' needs mode MODE_SET or MODE_ADD");
  std::vector<std::string> seen;
  for (const auto& array : request.header.arrays())
    if (array.group() == region.name) check_apply_array(region, array, seen);
  if (seen.empty())
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                               "ApplyRegion on region '" + region.name +
                                   "' carries no array of group '" + region.name + "'");
  for (const auto& array : request.header.arrays()) {
    if (array.group() != region.name) continue;
    const std::size_t components = apply_components(array.name());
    const cosim::ArrayView<double> view(array, request.frames.at(array.frame_index()));
    const auto values = view.values();
    for_each_box_index(region.lo, region.hi, [&](std::size_t n, const grid::Index3& node) {
      NodeLoad load{
          node, load_quantity(array.name()), mode == cosim::v1::ApplyRegion::MODE_SET, {}};
      for (std::size_t c = 0; c < components; ++c) load.value[c] = values[n * components + c];
      solver.queue_node_load(load);
    });
  }
}

std::uint64_t export_node_region(MpmSolver& solver, const ZoneRegion& region,
                                 const cosim::v1::ExportRegion& request, NodeBoxMap& map,
                                 double* next_step_map_seconds, cosim::Message& reply) {
  std::vector<std::string> names(request.quantities().begin(), request.quantities().end());
  if (names.empty()) names = region.quantities;
  for (const auto& name : names)
    if (!region.declares(name) || name == "internal_force")
      reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION, region, name,
             name == "internal_force" ? "is applied, not exported"
                                      : "not declared for it in Setup, so it cannot be exported");
  if (next_step_map_seconds != nullptr && !solver.has_next_step_map()) {
    const auto start = std::chrono::steady_clock::now();
    solver.map_next_step(region.lo, region.hi);
    *next_step_map_seconds =  // a map dropped before it was used was overhead
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (solver.next_step_mapped(region.lo, region.hi))
    solver.read_next_step_box(region.lo, region.hi, map);
  else
    solver.map_particles_to_node_box(region.lo, region.hi, map);
  const std::size_t count = region.box_count();
  for (const auto& name : names) {
    if (name == "internal_energy") {
      cosim::add_array(reply, {region.name, name, {}, "J"},
                       cell_internal_energy(solver, region, map.internal_energy));
    } else if (name == "mass") {
      cosim::add_array(reply, {region.name, name, {}, "kg"}, std::span<const double>(map.mass));
    } else {
      cosim::add_array(reply, {region.name, name, {count, 3}, "kg*m/s"},
                       std::span<const double>(map.momentum));
    }
  }
  return count;
}

}  // namespace mpfd::mpm
