#include "tests/verification/afdmp/v3_interface.hpp"

#include <numbers>

namespace mpfd::verification {

InterfaceSharpness v3_sharpness(const PointSet& points, double h) {
  return interface_sharpness(points.view(), 0.0, 0.0, 0.0, 0.5 * std::numbers::pi, kV3Sectors,
                             kV3BandCells * h);
}

std::string source_name(V3Source source) {
  switch (source) {
    case V3Source::afdmp_cells:
      return "afdmp_cells";
    case V3Source::mpm_cells:
      return "mpm_cells";
    case V3Source::mpm_particles:
      return "mpm_particles";
  }
  return "";
}

InterfaceSharpness v3_measure(const std::filesystem::path& dir, V3Source source, double time,
                              double h, int products, const std::string& products_name,
                              const std::string& air_name) {
  const double tolerance = 1e-9;
  const PlaneGrid grid{{0.0, 0.0}, {h, h}};
  const std::string products_fraction = "volume_fraction_" + products_name;
  const std::string air_fraction = "volume_fraction_" + air_name;
  switch (source) {
    case V3Source::afdmp_cells:
      return v3_sharpness(cell_points(snapshot_nearest(dir / "fdm" / "snapshots", time, tolerance),
                                      products_fraction, air_fraction, grid),
                          h);
    case V3Source::mpm_cells:
      return v3_sharpness(cell_points(snapshot_nearest(dir / "snapshots", time, tolerance),
                                      products_fraction, air_fraction, grid),
                          h);
    case V3Source::mpm_particles:
      return v3_sharpness(
          particle_points(snapshot_nearest(dir / "snapshots", time, tolerance), products), h);
  }
  return {};
}

}  // namespace mpfd::verification
