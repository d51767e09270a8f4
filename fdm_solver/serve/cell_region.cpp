#include "fdm_solver/serve/cell_region.hpp"

#include <algorithm>

#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/flux_quantities.hpp"

namespace mpfd::fdm {
namespace {

template <typename Values>
std::string index_text(const Values& values) {
  std::string text = "[";
  for (const auto v : values) text += (text.size() > 1 ? ", " : "") + std::to_string(v);
  return text + "]";
}

[[noreturn]] void reject(const cosim::v1::Region& region, const grid::UniformGrid& grid,
                         const std::string& rule) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                             "Setup region '" + region.name() + "' (box lo " +
                                 index_text(region.box().lo()) + ", hi " +
                                 index_text(region.box().hi()) + "): " + rule +
                                 "; the grid's interior cells are [0, 0, 0] to " +
                                 index_text(grid.cells()) + " (exclusive)");
}

}  // namespace

bool CellRegion::declares(Quantity q) const {
  return std::find(quantities.begin(), quantities.end(), q) != quantities.end();
}

bool CellRegion::declares(MaterialQuantity q) const {
  return std::find(material_fields.begin(), material_fields.end(), q) != material_fields.end();
}

CellRegion make_cell_region(const cosim::v1::Region& region, const grid::UniformGrid& grid) {
  if (region.name().empty()) reject(region, grid, "a region needs a name");
  const bool faces = region.kind() == cosim::v1::REGION_KIND_FACES;
  if (region.kind() != cosim::v1::REGION_KIND_CELLS && !faces)
    reject(region, grid,
           "kind " + cosim::v1::RegionKind_Name(region.kind()) +
               " is not served; an FDM zone has REGION_KIND_CELLS and REGION_KIND_FACES");
  if (region.flat_indices_size() > 0)
    reject(region, grid, "flat_indices are not served; give the cells as a box");
  const auto& lo = region.box().lo();
  const auto& hi = region.box().hi();
  if (lo.size() != hi.size() || lo.empty() || lo.size() > 3)
    reject(region, grid, "lo and hi must both have 1 to 3 indices");
  CellRegion cells;
  cells.name = region.name();
  for (int a = 0; a < 3; ++a) {
    const long long extent = grid.cells()[a];
    const bool given = a < lo.size();
    const long long l = given ? lo[a] : 0;
    const long long h = given ? hi[a] : 1;
    if (!given && extent != 1)
      reject(region, grid,
             "the box leaves out axis " + std::to_string(a) + ", which has " +
                 std::to_string(extent) + " cells");
    if (l < 0 || h > extent || l >= h)
      reject(region, grid,
             "axis " + std::to_string(a) + " needs 0 <= lo < hi <= " + std::to_string(extent));
    cells.box.lower[a] = static_cast<int>(l);
    cells.box.upper[a] = static_cast<int>(h);
  }
  if (faces) {
    if (region.face_axis() > 2 || !grid.is_active(static_cast<int>(region.face_axis())))
      reject(region, grid,
             "face_axis " + std::to_string(region.face_axis()) + " is not an active axis");
    const auto axis = static_cast<int>(region.face_axis());
    if (cells.box.upper[axis] - cells.box.lower[axis] != 1 || cells.box.lower[axis] == 0)
      reject(region, grid,
             "a FACES box spans one index [f, f + 1) along face_axis " + std::to_string(axis) +
                 ", with 0 < f: the faces between cells f - 1 and f");
    cells.face_axis = axis;
  }
  for (const auto& name : region.quantities()) {
    if (const auto flux = find_flux_quantity(name)) {
      if (info(*flux).on_faces != faces)
        reject(region, grid,
               "quantity '" + name + "' belongs to " + (faces ? "CELLS" : "FACES") + " regions");
      cells.fluxes.push_back(*flux);
      continue;
    }
    if (const auto m = faces ? std::nullopt : find_material_quantity(name)) {
      cells.material_fields.push_back(*m);
      continue;
    }
    const auto q = faces ? std::nullopt : find_quantity(name);
    if (!q)
      reject(region, grid,
             "unknown quantity '" + name + "'; known: " +
                 (faces ? "crossed_mass, crossed_momentum, crossed_energy"
                        : quantity_names() +
                              ", outflow_mass, outflow_momentum, outflow_energy, cell_material, "
                              "volume_fraction, material_density, material_energy"));
    cells.quantities.push_back(*q);
  }
  if (faces && cells.fluxes.empty())
    cells.fluxes = {FluxQuantity::crossed_mass, FluxQuantity::crossed_momentum,
                    FluxQuantity::crossed_energy};
  if (!faces && cells.quantities.empty() && cells.fluxes.empty() && cells.material_fields.empty())
    cells.quantities = {Quantity::rho, Quantity::momentum, Quantity::energy};
  return cells;
}

}  // namespace mpfd::fdm
