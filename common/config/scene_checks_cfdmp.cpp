#include <string>

#include "common/config/check_text.hpp"
#include "common/config/scene_checks.hpp"

namespace mpfd::config {

void check_cfdmp_structures(const Scene& s, Diagnostics& d) {
  if (s.solver.method != Method::cfdmp || !s.zones || !s.zones->fdm || !s.zones->mpm) return;
  if (!d.clean("zones") || !d.clean("bodies")) return;
  const Zone& fdm = *s.zones->fdm;
  // What the FDM holds: its zone and the ghost layers it fills from the MPM's
  // nodes, whose outer corner nodes also gather the particles of the next cell
  // (linear and GIMP shapes alike): a solid there would be filled into a ghost
  // cell as fluid (random seed 38: +6.1 % energy).
  Vec3 lower = fdm.lower, upper = fdm.upper;
  std::string expected;
  for (int i = 0; i < 3; ++i) {
    if (!active(s.domain, i)) continue;
    const double reach = kFdmReachCells * cell_size(s.domain, i);
    const double tol = kGridTolerance * cell_size(s.domain, i);
    if (fdm.upper[i] < s.domain.upper[i] - tol) {
      upper[i] += reach;
      expected = std::string(kAxisNames[i]) + " >= " + num(upper[i]);
    }
    if (fdm.lower[i] > s.domain.lower[i] + tol) {
      lower[i] -= reach;
      expected = std::string(kAxisNames[i]) + " <= " + num(lower[i]);
    }
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Material* m = find_material(s, s.bodies[i].state.material);
    if (!m || !has_strength(*m)) continue;
    const Box box = bounding_box(s.bodies[i].shape);
    if (!overlap(s.domain, box, lower, upper)) continue;
    d.error(item("bodies", i) + ".shape",
            "expected a body with a strength model in zones.mpm at least " +
                std::to_string(kFdmReachCells) + " cells past zones.fdm (its " +
                std::to_string(kFdmGhostLayers) +
                " ghost layers and the cell whose particles reach the ghost cells' outer nodes: " +
                expected + " m), got '" + s.bodies[i].name + "' (material '" + m->name +
                "') from " + text(box.lower) + " to " + text(box.upper) + ", reaching into " +
                text(lower) + " to " + text(upper) +
                ": the FDM holds no solid (its cells take the scene's initial material and the "
                "MPM drops its particles outside zones.mpm), and a ghost cell filled from a "
                "solid's nodes is no fluid (structures live in the MPM zone, T §4.2)");
  }
}

}  // namespace mpfd::config
