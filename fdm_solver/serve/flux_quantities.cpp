#include "fdm_solver/serve/flux_quantities.hpp"

#include <array>
#include <cstring>

#include "cosim/arrays.hpp"

namespace mpfd::fdm {
namespace {

constexpr std::array<FluxQuantityInfo, 6> kFluxQuantities{{
    {"crossed_mass", 1, "kg", kDensity, true},
    {"crossed_momentum", 3, "kg*m/s", kMomentumX, true},
    {"crossed_energy", 1, "J", kEnergy, true},
    {"outflow_mass", 1, "kg", kDensity, false},
    {"outflow_momentum", 3, "kg*m/s", kMomentumX, false},
    {"outflow_energy", 1, "J", kEnergy, false},
}};

/// Line of a face normal to `axis` that `cell` lies on (QuietFaceFlux numbering).
std::size_t face_line(const grid::UniformGrid& grid, int axis, int i, int j, int k) {
  const std::array<int, 3> cell{i, j, k};
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  return static_cast<std::size_t>(cell[a1] + grid.cells()[a1] * cell[a2]);
}

}  // namespace

const FluxQuantityInfo& info(FluxQuantity q) {
  return kFluxQuantities[static_cast<std::size_t>(q)];
}

std::optional<FluxQuantity> find_flux_quantity(std::string_view name) {
  for (std::size_t i = 0; i < kFluxQuantities.size(); ++i)
    if (kFluxQuantities[i].name == name) return static_cast<FluxQuantity>(i);
  return std::nullopt;
}

std::string flux_quantity_names() {
  std::string names;
  for (const auto& q : kFluxQuantities) names += (names.empty() ? "" : ", ") + std::string(q.name);
  return names;
}

std::uint64_t export_flux(const EulerSolver& solver, const CellRegion& region, FluxQuantity q,
                          cosim::Message& reply) {
  const auto& grid = solver.state().grid;
  const FluxQuantityInfo& about = info(q);
  const std::size_t components = about.components;
  const std::size_t rows = about.on_faces ? region.cell_count() : 1;
  zmq::message_t frame(rows * components * sizeof(double));
  auto* out = static_cast<double*>(frame.data());
  std::fill(out, out + rows * components, 0.0);
  const auto& box = region.box;
  if (about.on_faces) {
    const auto& crossed = solver.watched_crossing();
    std::size_t n = 0;
    for (int i = box.lower[0]; i < box.upper[0]; ++i)
      for (int j = box.lower[1]; j < box.upper[1]; ++j)
        for (int k = box.lower[2]; k < box.upper[2]; ++k, ++n) {
          const std::size_t line = face_line(grid, region.face_axis, i, j, k);
          for (std::size_t c = 0; c < components; ++c)
            out[n * components + c] = crossed[line * kVariables + about.variable + c];
        }
  } else {
    // The domain faces the box touches, and of each the lines within the box.
    for (int axis = 0; axis < 3; ++axis) {
      if (!grid.is_active(axis)) continue;
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (const int side : {0, 1}) {
        const bool touches =
            side == 0 ? box.lower[axis] == 0 : box.upper[axis] == grid.cells()[axis];
        if (!touches) continue;
        const auto& cells = solver.face_outflow(2 * axis + side);
        for (int l2 = box.lower[a2]; l2 < box.upper[a2]; ++l2)
          for (int l1 = box.lower[a1]; l1 < box.upper[a1]; ++l1) {
            const auto line = static_cast<std::size_t>(l1 + grid.cells()[a1] * l2);
            for (std::size_t c = 0; c < components; ++c)
              out[c] += cells[line * kVariables + about.variable + c];
          }
      }
    }
  }
  cosim::ArraySpec spec{region.name, about.name, {}, about.units};
  if (components > 1) spec.shape = {rows, components};
  cosim::append_frame(reply, spec, cosim::v1::DTYPE_F64, rows * components, std::move(frame));
  return rows;
}

}  // namespace mpfd::fdm
