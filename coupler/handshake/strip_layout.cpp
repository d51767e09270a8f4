#include "coupler/handshake/strip_layout.hpp"

#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
StripLayout<Dim> make_strip_layout(const IndexBox<Dim>& strip, const ZoneFace& face) {
  check_face<Dim>(face);
  strip.check("strip cells");
  const int axis = face.axis;
  if (strip.hi[axis] - strip.lo[axis] != 2)
    throw Error("strip cells: the box must be 2 cells thick along the face normal (axis " +
                std::to_string(axis) + "), got " + std::to_string(strip.hi[axis] - strip.lo[axis]));
  StripLayout<Dim> layout{face, strip, {}, {}, {}};
  IndexBox<Dim> layer = strip;
  layer.hi[axis] = layer.lo[axis] + 1;
  const std::int64_t outer_layer = face.side > 0 ? strip.lo[axis] : strip.lo[axis] + 1;
  const std::int64_t inner_layer = face.side > 0 ? strip.lo[axis] + 1 : strip.lo[axis];
  for (std::size_t t = 0; t < layer.count(); ++t) {
    Index<Dim> outer = layer.at(t);
    Index<Dim> inner = outer;
    outer[axis] = outer_layer;
    inner[axis] = inner_layer;
    layout.outer.push_back(strip.flat(outer));
    layout.inner.push_back(strip.flat(inner));
    layout.inner_cell.push_back(inner);
  }
  return layout;
}

template StripLayout<1> make_strip_layout<1>(const IndexBox<1>&, const ZoneFace&);
template StripLayout<2> make_strip_layout<2>(const IndexBox<2>&, const ZoneFace&);
template StripLayout<3> make_strip_layout<3>(const IndexBox<3>&, const ZoneFace&);

}  // namespace mpfd::coupler::handshake
