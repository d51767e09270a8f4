#include "fdm_solver/serve/region_transfer.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/flux_quantities.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void reject(cosim::v1::ErrorCode code, const CellRegion& region,
                         std::string_view quantity, const std::string& rule) {
  throw cosim::ProtocolError(
      code, "region '" + region.name + "', quantity '" + std::string(quantity) + "': " + rule);
}

/// The quantity an apply array carries, after checking it against the region.
Quantity checked_apply_array(const CellRegion& region, const cosim::v1::ArrayDescriptor& array,
                             unsigned& seen) {
  const auto q = find_quantity(array.name());
  if (!q || !info(*q).writable)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "ApplyRegion accepts only rho, momentum and E");
  if (!region.declares(*q))
    reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION, region, array.name(),
           "not declared for it in Setup");
  const unsigned bit = 1U << static_cast<unsigned>(*q);
  if ((seen & bit) != 0)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(), "given twice");
  seen |= bit;
  if (array.dtype() != cosim::v1::DTYPE_F64)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "dtype must be DTYPE_F64, got " + cosim::v1::DType_Name(array.dtype()));
  std::uint64_t count = 1;
  for (const auto extent : array.shape()) count *= extent;
  const std::size_t expected = region.cell_count() * info(*q).components;
  if (count != expected)
    reject(cosim::v1::ERROR_CODE_MALFORMED, region, array.name(),
           "expected " + std::to_string(expected) + " values (" +
               std::to_string(region.cell_count()) + " cells x " +
               std::to_string(info(*q).components) + " components), got " + std::to_string(count));
  return *q;
}

}  // namespace

void apply_region(EulerSolver& solver, const CellRegion& region, cosim::v1::ApplyRegion::Mode mode,
                  const cosim::Message& request) {
  if (mode != cosim::v1::ApplyRegion::MODE_SET && mode != cosim::v1::ApplyRegion::MODE_ADD)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "ApplyRegion on region '" + region.name + "' needs mode MODE_SET or MODE_ADD");
  unsigned seen = 0;
  for (const auto& array : request.header.arrays())
    if (array.group() == region.name) checked_apply_array(region, array, seen);
  if (seen == 0)
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                               "ApplyRegion on region '" + region.name +
                                   "' carries no array of group '" + region.name + "'");

  EulerState& state = solver.state_for_update(region.box);
  for (const auto& array : request.header.arrays()) {
    if (array.group() != region.name) continue;
    const Quantity q = *find_quantity(array.name());
    const std::size_t components = info(q).components;
    const cosim::ArrayView<double> view(array, request.frames.at(array.frame_index()));
    const auto values = view.values();
    for (std::size_t c = 0; c < components; ++c) {
      auto& target = conserved_array(state, q, c);
      for_each_transfer_cell(state.grid, region.box, [&](std::size_t n, std::size_t cell) {
        const double value = values[n * components + c];
        target[cell] = mode == cosim::v1::ApplyRegion::MODE_SET ? value : target[cell] + value;
      });
    }
  }
}

std::uint64_t export_region(EulerSolver& solver, const CellRegion& region,
                            const cosim::v1::ExportRegion& request, cosim::Message& reply) {
  const auto export_one = [&](Quantity q) {
    const std::size_t components = info(q).components;
    const std::size_t count = region.cell_count();
    zmq::message_t frame(count * components * sizeof(double));
    auto* out = static_cast<std::byte*>(frame.data());
    std::array<double, 3> values{};
    for_each_transfer_cell(solver.state().grid, region.box, [&](std::size_t n, std::size_t cell) {
      cell_values(solver.state(), solver.materials(), q, cell, values);
      std::memcpy(out + n * components * sizeof(double), values.data(),
                  components * sizeof(double));
    });
    cosim::ArraySpec spec{region.name, info(q).name, {}, info(q).units};
    if (components > 1) spec.shape = {count, components};
    cosim::append_frame(reply, spec, cosim::v1::DTYPE_F64, count * components, std::move(frame));
  };
  if (request.quantities().empty()) {
    for (const Quantity q : region.quantities) export_one(q);
    for (const FluxQuantity q : region.fluxes) export_flux(solver, region, q, reply);
    for (const MaterialQuantity q : region.material_fields)
      export_material_quantity(solver, region.name, region.box, q, reply);
  }
  for (const auto& name : request.quantities()) {
    if (const auto flux = find_flux_quantity(name);
        flux &&
        std::find(region.fluxes.begin(), region.fluxes.end(), *flux) != region.fluxes.end()) {
      export_flux(solver, region, *flux, reply);
      continue;
    }
    if (const auto m = find_material_quantity(name); m && region.declares(*m)) {
      export_material_quantity(solver, region.name, region.box, *m, reply);
      continue;
    }
    const auto q = find_quantity(name);
    if (!q || !region.declares(*q))
      reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION, region, name,
             "not declared for it in Setup, so it cannot be exported");
    export_one(*q);
  }
  // v1.1: a FACES export hands over what crossed since the last one.
  if (region.face_axis >= 0) solver.clear_watched_crossing();
  return region.cell_count();
}

}  // namespace mpfd::fdm
