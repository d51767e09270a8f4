#pragma once
// A named region of FDM cells declared in Setup (proto/README.md §4): a
// half-open index box [lo, hi) of interior cells and the quantities a coupler
// exchanges through it. Values travel in box C order over (i, j, k): k (z)
// varies fastest, unlike the grid's storage (x fastest).

#include <string>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "cosim/message.hpp"
#include "fdm_solver/active_box.hpp"
#include "fdm_solver/serve/cell_quantities.hpp"
#include "fdm_solver/serve/flux_quantities_fwd.hpp"
#include "fdm_solver/serve/material_quantities.hpp"

namespace mpfd::fdm {

struct CellRegion {
  std::string name;
  ActiveBox box;  ///< FACES: the cells above the faces (one layer along face_axis)
  std::vector<Quantity> quantities;
  std::vector<FluxQuantity> fluxes;               ///< v1.1 amounts (flux_quantities.hpp)
  std::vector<MaterialQuantity> material_fields;  ///< v1.2 (import: §15 rule 8)
  int face_axis = -1;  ///< REGION_KIND_FACES: the faces' normal; CELLS: -1

  [[nodiscard]] std::size_t cell_count() const { return static_cast<std::size_t>(box.cells()); }
  [[nodiscard]] bool declares(Quantity q) const;
  [[nodiscard]] bool declares(MaterialQuantity q) const;
};

/// Checks a Setup region against `grid`: kind CELLS, a box of 1 to 3 axes
/// (axes it leaves out must have one cell) with 0 <= lo < hi <= cells, and
/// known quantities (none given: rho, momentum, E; v1.2 adds the per-material
/// ones of material_quantities.hpp); or kind FACES (v1.1): a
/// box one thick along an active face_axis, 0 < lo there (faces between two
/// cells), with crossed_* quantities only (none given: all three). Throws
/// cosim::ProtocolError{UNKNOWN_REGION} naming the region, its box and the grid.
[[nodiscard]] CellRegion make_cell_region(const cosim::v1::Region& region,
                                          const grid::UniformGrid& grid);

/// Calls f(n, cell) for each cell of `box`: n its position in box C order,
/// cell its index in the grid's storage order.
template <typename F>
void for_each_transfer_cell(const grid::UniformGrid& grid, const ActiveBox& box, F&& f) {
  std::size_t n = 0;
  for (int i = box.lower[0]; i < box.upper[0]; ++i)
    for (int j = box.lower[1]; j < box.upper[1]; ++j)
      for (int k = box.lower[2]; k < box.upper[2]; ++k) f(n++, grid.cell_index(i, j, k));
}

}  // namespace mpfd::fdm
