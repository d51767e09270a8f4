#include "coupler/handshake/interface_nodes.hpp"

#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handshake {
namespace {

// The transverse axes of a face normal to `axis`, in increasing order.
template <int Dim>
std::array<int, Dim - 1> transverse_axes(int axis) {
  std::array<int, Dim - 1> axes{};
  int b = 0;
  for (int a = 0; a < Dim; ++a)
    if (a != axis) axes[b++] = a;
  return axes;
}

// The face cells t around each node of `nodes`, a box on node layer `layer` along the normal.
template <int Dim>
InterfaceStencil<Dim> stencil_on_layer(const StripLayout<Dim>& strip, const IndexBox<Dim>& nodes,
                                       std::int64_t layer, const char* what) {
  nodes.check(what);
  const int axis = strip.face.axis;
  if (nodes.lo[axis] != layer || nodes.hi[axis] != layer + 1)
    throw Error(std::string(what) + ": the box must be the node layer " + std::to_string(layer) +
                " along axis " + std::to_string(axis) + ", got [" + std::to_string(nodes.lo[axis]) +
                ", " + std::to_string(nodes.hi[axis]) + ")");
  IndexBox<Dim> face_cells = strip.box;
  face_cells.hi[axis] = face_cells.lo[axis] + 1;
  const auto axes = transverse_axes<Dim>(axis);
  InterfaceStencil<Dim> stencil;
  stencil.cells.resize(nodes.count());
  for (std::size_t n = 0; n < nodes.count(); ++n) {
    const Index<Dim> node = nodes.at(n);
    for (int q = 0; q < kFaceCorners<Dim>; ++q) {
      Index<Dim> cell = node;
      cell[axis] = face_cells.lo[axis];
      for (int b = 0; b < Dim - 1; ++b) cell[axes[b]] -= (q >> b) & 1;
      stencil.cells[n][q] =
          face_cells.contains(cell) ? static_cast<std::int64_t>(face_cells.flat(cell)) : -1;
    }
  }
  return stencil;
}

// ∇N_Ic at a cell centre for a node on the cell's side `normal` (+1: upper) along `axis`
// and, across, on the sides that bit b of slot q says.
template <int Dim>
Vec<Dim> centre_gradient(int axis, int normal, int q, const CellGeometry<Dim>& geometry) {
  const auto axes = transverse_axes<Dim>(axis);
  Vec<Dim> gradient;
  gradient(axis) = normal / (geometry.spacing(axis) * kFaceCorners<Dim>);
  for (int b = 0; b < Dim - 1; ++b)
    gradient(axes[b]) =
        (((q >> b) & 1) != 0 ? 1.0 : -1.0) / (geometry.spacing(axes[b]) * kFaceCorners<Dim>);
  return gradient;
}

}  // namespace

template <int Dim>
InterfaceStencil<Dim> make_interface_stencil(const StripLayout<Dim>& strip,
                                             const IndexBox<Dim>& nodes) {
  return stencil_on_layer(strip, nodes, strip.face_node_layer(), "interface nodes (the face)");
}

template <int Dim>
InterfaceStencil<Dim> make_outer_node_stencil(const StripLayout<Dim>& strip,
                                              const IndexBox<Dim>& nodes) {
  return stencil_on_layer(strip, nodes, strip.face_node_layer() - strip.face.side,
                          "outer nodes (one cell outside the face)");
}

template <int Dim>
void interface_node_terms(const CellStates<Dim>& strip, std::span<const double> strip_pressure,
                          double reference_pressure, const StripLayout<Dim>& layout,
                          const InterfaceStencil<Dim>& stencil, const CellGeometry<Dim>& geometry,
                          const NodeOutputs<Dim>& add, std::span<const double> force_volume) {
  geometry.check();
  if (!force_volume.empty())
    require_length(force_volume.size(), layout.face_cells(), "interface nodes", "force_volume");
  require_lengths(strip, layout.box.count(), "strip cells");
  require_length(strip_pressure.size(), layout.box.count(), "strip cells", "pressure");
  require_node_lengths(add, stencil.cells.size(), "interface nodes");
  const int axis = layout.face.axis;
  const double volume = geometry.cell_volume;
  const double weight = 1.0 / (1 << Dim);  // N_Ic at the cell centre
  for (std::size_t n = 0; n < stencil.cells.size(); ++n) {
    double mass = 0;
    Vec<Dim> momentum = Vec<Dim>::Zero();
    Vec<Dim> force = Vec<Dim>::Zero();
    for (int q = 0; q < kFaceCorners<Dim>; ++q) {
      const std::int64_t t = stencil.cells[n][q];
      if (t < 0) continue;
      const std::size_t c = layout.outer[static_cast<std::size_t>(t)];
      // The face node is on cell k-w's side towards the zone.
      const Vec<Dim> gradient = centre_gradient<Dim>(axis, layout.face.side, q, geometry);
      mass += weight * strip.rho[c] * volume;           // T (4-7)
      momentum += weight * volume * strip.momentum[c];  // T (4-8)
      const double pushing =
          force_volume.empty() ? volume : force_volume[static_cast<std::size_t>(t)];
      force += (strip_pressure[c] - reference_pressure) * pushing * gradient;  // T (4-9)
    }
    add.mass[n] = mass;
    add.momentum[n] = momentum;
    add.internal_force[n] = force;
  }
}

template <int Dim>
void outer_node_terms(const CellStates<Dim>& strip, std::span<const double> strip_pressure,
                      const CellStates<Dim>& beyond, std::span<const double> beyond_pressure,
                      double reference_pressure, const StripLayout<Dim>& layout,
                      const InterfaceStencil<Dim>& stencil, const CellGeometry<Dim>& geometry,
                      const NodeOutputs<Dim>& add) {
  geometry.check();
  require_lengths(strip, layout.box.count(), "strip cells");
  require_length(strip_pressure.size(), layout.box.count(), "strip cells", "pressure");
  require_lengths(beyond, layout.face_cells(), "beyond cells (k-w-1)");
  require_length(beyond_pressure.size(), layout.face_cells(), "beyond cells (k-w-1)", "pressure");
  require_node_lengths(add, stencil.cells.size(), "outer nodes");
  const int axis = layout.face.axis;
  const double volume = geometry.cell_volume;
  const double weight = 1.0 / (1 << Dim);  // N_Ic at the cell centre
  for (std::size_t n = 0; n < stencil.cells.size(); ++n) {
    double mass = 0;
    Vec<Dim> momentum = Vec<Dim>::Zero();
    Vec<Dim> force = Vec<Dim>::Zero();
    for (int q = 0; q < kFaceCorners<Dim>; ++q) {
      const std::int64_t t = stencil.cells[n][q];
      if (t < 0) continue;
      const auto b = static_cast<std::size_t>(t);
      const std::size_t c = layout.outer[b];
      // The node is on cell k-w's side away from the zone and on cell k-w-1's side towards it.
      const Vec<Dim> outer_gradient = centre_gradient<Dim>(axis, -layout.face.side, q, geometry);
      const Vec<Dim> beyond_gradient = centre_gradient<Dim>(axis, layout.face.side, q, geometry);
      mass += weight * volume * (strip.rho[c] + beyond.rho[b]);                // T (4-7)
      momentum += weight * volume * (strip.momentum[c] + beyond.momentum[b]);  // T (4-8)
      force += volume * ((strip_pressure[c] - reference_pressure) * outer_gradient +
                         (beyond_pressure[b] - reference_pressure) * beyond_gradient);  // T (4-9)
    }
    add.mass[n] = mass;
    add.momentum[n] = momentum;
    add.internal_force[n] = force;
  }
}

template <int Dim>
void face_push_volume(std::span<const double> face_mass, std::span<const double> solid_volume,
                      std::span<const double> strip_rho, const StripLayout<Dim>& layout,
                      double cell_volume, std::span<double> volume) {
  const std::size_t n = layout.face_cells();
  require_length(face_mass.size(), n, "face push volume", "face_mass");
  require_length(solid_volume.size(), n, "face push volume", "solid_volume");
  require_length(strip_rho.size(), layout.box.count(), "face push volume", "strip rho");
  require_length(volume.size(), n, "face push volume", "volume");
  for (std::size_t t = 0; t < n; ++t) {
    const double rho = strip_rho[layout.outer[t]];
    if (!(rho > 0))
      throw Error("face push volume: face cell " + std::to_string(t) +
                  " needs an outer cell with rho > 0, got " + shortest_text(rho));
    // No particle in the face cell (an emptied zone edge): nothing resists,
    // and a zero volume would switch the FDM's pressure off there; T's V_c.
    const bool held = face_mass[t] > 0 || solid_volume[t] > 0;
    volume[t] = held ? face_mass[t] / rho + solid_volume[t] : cell_volume;
  }
}

#define MPFD_INSTANTIATE_INTERFACE(Dim)                                                            \
  template InterfaceStencil<Dim> make_interface_stencil<Dim>(const StripLayout<Dim>&,              \
                                                             const IndexBox<Dim>&);                \
  template void interface_node_terms<Dim>(const CellStates<Dim>&, std::span<const double>, double, \
                                          const StripLayout<Dim>&, const InterfaceStencil<Dim>&,   \
                                          const CellGeometry<Dim>&, const NodeOutputs<Dim>&,       \
                                          std::span<const double>);                                \
  template InterfaceStencil<Dim> make_outer_node_stencil<Dim>(const StripLayout<Dim>&,             \
                                                              const IndexBox<Dim>&);               \
  template void outer_node_terms<Dim>(const CellStates<Dim>&, std::span<const double>,             \
                                      const CellStates<Dim>&, std::span<const double>, double,     \
                                      const StripLayout<Dim>&, const InterfaceStencil<Dim>&,       \
                                      const CellGeometry<Dim>&, const NodeOutputs<Dim>&);          \
  template void face_push_volume<Dim>(std::span<const double>, std::span<const double>,            \
                                      std::span<const double>, const StripLayout<Dim>&, double,    \
                                      std::span<double>);
MPFD_INSTANTIATE_INTERFACE(1)
MPFD_INSTANTIATE_INTERFACE(2)
MPFD_INSTANTIATE_INTERFACE(3)
#undef MPFD_INSTANTIATE_INTERFACE

}  // namespace mpfd::coupler::handshake
