#pragma once
// XDMF 3 text for a time series of snapshot files: cell fields on a
// 3DCoRectMesh, particles as a Polyvertex cloud. Pure text builders.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::io {

struct XdmfStep {
  std::string file;  // HDF5 file, relative to the .xmf
  double time;
  std::vector<std::pair<std::string, int>> fields;  // name, components (1 or 3)
  std::size_t particle_count = 0;
};

std::string cells_xdmf(const grid::UniformGrid& grid, const std::vector<XdmfStep>& steps);
std::string particles_xdmf(const std::vector<XdmfStep>& steps);

}  // namespace mpfd::io
