#include "mpm_solver/serve/zone_region.hpp"

#include <algorithm>
#include <array>

#include "cosim/serving/protocol_error.hpp"

namespace mpfd::mpm {
namespace {

constexpr std::array<std::string_view, 4> kNodeQuantities = {"mass", "momentum", "internal_force",
                                                             "internal_energy"};
constexpr std::array<std::string_view, 12> kParticleQuantities = {
    "id",       "position", "velocity",      "mass",         "volume",           "internal_energy",
    "material", "stress",   "burn_fraction", "outflow_mass", "outflow_momentum", "outflow_energy"};

template <typename Values>
std::string index_text(const Values& values) {
  std::string text = "[";
  for (const auto v : values) text += (text.size() > 1 ? ", " : "") + std::to_string(v);
  return text + "]";
}

template <std::size_t N>
std::string names_text(const std::array<std::string_view, N>& names) {
  std::string text;
  for (const auto name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

[[noreturn]] void reject(const cosim::v1::Region& region, const grid::UniformGrid& grid,
                         const std::string& rule) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                             "Setup region '" + region.name() + "' (box lo " +
                                 index_text(region.box().lo()) + ", hi " +
                                 index_text(region.box().hi()) + "): " + rule +
                                 "; the MPM grid has cells " + index_text(grid.cells()));
}

}  // namespace

bool node_quantity_known(std::string_view name) {
  return std::find(kNodeQuantities.begin(), kNodeQuantities.end(), name) != kNodeQuantities.end();
}

bool particle_quantity_known(std::string_view name) {
  return std::find(kParticleQuantities.begin(), kParticleQuantities.end(), name) !=
         kParticleQuantities.end();
}

bool ZoneRegion::declares(std::string_view quantity) const {
  return std::find(quantities.begin(), quantities.end(), quantity) != quantities.end();
}

std::size_t ZoneRegion::box_count() const {
  std::size_t n = 1;
  for (int a = 0; a < 3; ++a) n *= static_cast<std::size_t>(hi[a] - lo[a]);
  return n;
}

std::size_t ZoneRegion::cell_count(const grid::UniformGrid& grid) const {
  std::size_t n = 1;
  for (int a = 0; a < 3; ++a)
    n *= static_cast<std::size_t>(grid.is_active(a) ? hi[a] - lo[a] - 1 : 1);
  return n;
}

RegionExtent::RegionExtent(const ZoneRegion& region, const grid::UniformGrid& grid) {
  for (int a = 0; a < 3; ++a) {
    active_[a] = grid.is_active(a);
    lower_[a] = grid.origin()[a] + region.lo[a] * grid.spacing()[a];
    upper_[a] = grid.origin()[a] + region.hi[a] * grid.spacing()[a];
  }
}

ZoneRegion make_zone_region(const cosim::v1::Region& region, const grid::UniformGrid& grid) {
  if (region.name().empty()) reject(region, grid, "a region needs a name");
  const bool nodes = region.kind() == cosim::v1::REGION_KIND_NODES;
  if (!nodes && region.kind() != cosim::v1::REGION_KIND_PARTICLES)
    reject(region, grid,
           "kind " + cosim::v1::RegionKind_Name(region.kind()) +
               " is not served; an MPM zone has REGION_KIND_NODES and REGION_KIND_PARTICLES");
  if (region.flat_indices_size() > 0)
    reject(region, grid, "flat_indices are not served; give the region as a box");
  const auto& lo = region.box().lo();
  const auto& hi = region.box().hi();
  if (lo.size() != hi.size() || lo.empty() || lo.size() > 3)
    reject(region, grid, "lo and hi must both have 1 to 3 indices");
  ZoneRegion out{region.name(), region.kind(), {}, {}, {}};
  for (int a = 0; a < 3; ++a) {
    const bool active = grid.is_active(a);
    // An active axis has cells + 1 nodes; an inactive one a single node and cell.
    const long long extent = active ? grid.cells()[a] + (nodes ? 1 : 0) : 1;
    const bool given = a < lo.size();
    const long long l = given ? lo[a] : 0;
    const long long h = given ? hi[a] : 1;
    if (!given && active)
      reject(region, grid, "the box leaves out axis " + std::to_string(a) + ", which is active");
    if (l < 0 || h > extent || l >= h)
      reject(region, grid,
             "axis " + std::to_string(a) + " needs 0 <= lo < hi <= " + std::to_string(extent) +
                 (nodes ? " (node indices)" : " (cell indices)"));
    out.lo[a] = static_cast<int>(l);
    out.hi[a] = static_cast<int>(h);
  }
  for (const auto& name : region.quantities()) {
    if (nodes ? !node_quantity_known(name) : !particle_quantity_known(name))
      reject(region, grid,
             "unknown quantity '" + name + "'; known for " +
                 (nodes ? "nodes: " + names_text(kNodeQuantities)
                        : "particles: " + names_text(kParticleQuantities)));
    out.quantities.push_back(name);
  }
  if (nodes && out.declares("internal_energy"))
    for (int a = 0; a < 3; ++a)
      if (grid.is_active(a) && out.hi[a] - out.lo[a] < 2)
        reject(region, grid,
               "internal_energy is per cell of the box's nodes, so axis " + std::to_string(a) +
                   " needs at least two nodes");
  if (out.quantities.empty())
    out.quantities = nodes
                         ? std::vector<std::string>{"mass", "momentum"}
                         : std::vector<std::string>{"id",     "position",        "velocity", "mass",
                                                    "volume", "internal_energy", "material"};
  return out;
}

}  // namespace mpfd::mpm
