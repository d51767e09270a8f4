#include "common/io/xdmf.hpp"

#include <cstdio>
#include <sstream>

#include "common/core/require.hpp"

namespace mpfd::io {
namespace {

std::string number(double x) {
  return number_text(x, 17);
}

void open_document(std::ostringstream& x, const char* name) {
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

void close_document(std::ostringstream& x) {
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
}

void attribute(std::ostringstream& x, const XdmfStep& s, const std::string& group,
               const std::string& name, int components, const std::string& dims,
               const char* center) {
  x << "    <Attribute Name=\"" << name << "\" AttributeType=\""
    << (components == 3 ? "Vector" : "Scalar") << "\" Center=\"" << center << "\">\n"
    << "     <DataItem Dimensions=\"" << dims << (components == 3 ? " 3" : "")
    << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << s.file << ":/" << group << "/"
    << name << "</DataItem>\n    </Attribute>\n";
}

}  // namespace

std::string cells_xdmf(const grid::UniformGrid& grid, const std::vector<XdmfStep>& steps) {
  const auto& n = grid.cells();
  const auto& o = grid.origin();
  const auto& h = grid.spacing();
  // XDMF orders everything slowest axis first: z, y, x.
  const std::string cell_dims =
      std::to_string(n[2]) + " " + std::to_string(n[1]) + " " + std::to_string(n[0]);
  const std::string node_dims =
      std::to_string(n[2] + 1) + " " + std::to_string(n[1] + 1) + " " + std::to_string(n[0] + 1);
  std::ostringstream x;
  open_document(x, "cells");
  for (const auto& s : steps) {
    x << "   <Grid Name=\"cells\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << number(s.time) << "\"/>\n"
      << "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << node_dims << "\"/>\n"
      << "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      << "     <DataItem Dimensions=\"3\" Format=\"XML\">" << number(o[2]) << " " << number(o[1])
      << " " << number(o[0]) << "</DataItem>\n"
      << "     <DataItem Dimensions=\"3\" Format=\"XML\">" << number(h[2]) << " " << number(h[1])
      << " " << number(h[0]) << "</DataItem>\n    </Geometry>\n";
    for (const auto& [name, components] : s.fields)
      attribute(x, s, "cells", name, components, cell_dims, "Cell");
    x << "   </Grid>\n";
  }
  close_document(x);
  return x.str();
}

std::string particles_xdmf(const std::vector<XdmfStep>& steps) {
  std::ostringstream x;
  open_document(x, "particles");
  for (const auto& s : steps) {
    const std::string count = std::to_string(s.particle_count);
    x << "   <Grid Name=\"particles\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << number(s.time) << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << count << "\"/>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n     <DataItem Dimensions=\"" << count
      << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << s.file
      << ":/particles/position</DataItem>\n    </Geometry>\n";
    for (const auto& [name, components] : s.fields)
      if (name != "position") attribute(x, s, "particles", name, components, count, "Node");
    x << "   </Grid>\n";
  }
  close_document(x);
  return x.str();
}

}  // namespace mpfd::io
