#include "coupler/handshake/index_box.hpp"

#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "coupler/handshake/fields.hpp"

namespace mpfd::coupler::handshake {

void require_length(std::size_t got, std::size_t expected, const char* what, const char* quantity) {
  if (got != expected)
    throw Error(std::string(what) + ": " + quantity + " must have " + std::to_string(expected) +
                " entries, got " + std::to_string(got));
}

template <int Dim>
void IndexBox<Dim>::check(const char* what) const {
  for (int a = 0; a < Dim; ++a)
    if (lo[a] >= hi[a])
      throw Error(std::string(what) + ": box axis " + std::to_string(a) +
                  " must have lo < hi, got lo " + std::to_string(lo[a]) + ", hi " +
                  std::to_string(hi[a]));
}

template <int Dim>
void CellGeometry<Dim>::check() const {
  for (int a = 0; a < Dim; ++a)
    require(spacing(a) > 0, "handshake grid", "spacing", spacing(a), "> 0");
  require(cell_volume > 0, "handshake grid", "cell_volume", cell_volume, "> 0");
}

template <int Dim>
void check_face(const ZoneFace& face) {
  if (face.axis < 0 || face.axis >= Dim || (face.side != 1 && face.side != -1))
    throw Error("MPM zone face: axis must be in [0, " + std::to_string(Dim) +
                ") and side +1 or -1, got axis " + std::to_string(face.axis) + ", side " +
                std::to_string(face.side));
}

template struct IndexBox<1>;
template struct IndexBox<2>;
template struct IndexBox<3>;
template struct CellGeometry<1>;
template struct CellGeometry<2>;
template struct CellGeometry<3>;
template void check_face<1>(const ZoneFace&);
template void check_face<2>(const ZoneFace&);
template void check_face<3>(const ZoneFace&);

}  // namespace mpfd::coupler::handshake
