#pragma once
// V3 (METHOD.md; T §3.4.2, Figs. 3.8–3.9): the interface measures of the
// charge's products against the air, on the quarter plane of
// configs/afdmp_blast_2d.yaml (charge centre at the origin), as the design's
// acceptance (notes §5.3) states them: 9 sectors of 10° over [0°, 90°], band 3 h.

#include <filesystem>
#include <string>

#include "tests/verification/afdmp/run_reading.hpp"
#include "tests/verification/support/interface_sharpness.hpp"

namespace mpfd::verification {

inline constexpr int kV3Sectors = 9;
inline constexpr double kV3BandCells = 3.0;

/// interface_sharpness of `points` around the origin over the quarter plane, band 3 h.
[[nodiscard]] InterfaceSharpness v3_sharpness(const PointSet& points, double h);

/// Where the points of a V3 run come from. AFDMP's FDM snapshots hold no
/// tracers (fdm serve's WriteOutput writes cells only), so AFDMP is measured on
/// its cells, and pure MPM on its binned cells (the same measure) and particles.
enum class V3Source {
  afdmp_cells,    ///< DIR/fdm/snapshots, the cells' volume_fraction_<products> (T (3-23))
  mpm_cells,      ///< DIR/snapshots of `mpm_solver run`: particle-volume shares per cell
  mpm_particles,  ///< the same snapshots' particles, weighted by volume
};

[[nodiscard]] std::string source_name(V3Source source);

/// The measures of run `dir` at `time` [s] (its snapshot within 1e-9 s), cell size `h` [m],
/// products material index `products`, the products' and the air's material names (for
/// the cells' volume_fraction_<name>).
[[nodiscard]] InterfaceSharpness v3_measure(const std::filesystem::path& dir, V3Source source,
                                            double time, double h, int products,
                                            const std::string& products_name,
                                            const std::string& air_name);

}  // namespace mpfd::verification
