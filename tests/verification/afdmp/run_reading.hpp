#pragma once
// Reading an AFDMP or MPM output folder (docs/output.md) for the V3 and V5
// checks: the snapshot nearest a time, the charge's products/air as weighted
// points (tests/verification/support/interface_sharpness.hpp) and one gauge
// column of gauges.csv.

#include <filesystem>
#include <string>
#include <vector>

#include "tests/verification/support/interface_sharpness.hpp"

namespace mpfd::verification {

/// The snapshot_*.h5 in `snapshots` whose time attribute is nearest `time` [s];
/// throws mpfd::Error when the folder holds none or the nearest is further than
/// `tolerance` [s] from `time`.
[[nodiscard]] std::filesystem::path snapshot_nearest(const std::filesystem::path& snapshots,
                                                     double time, double tolerance);

/// Owns the arrays a WeightedPoints views.
struct PointSet {
  std::vector<double> x, y, products, air;
  [[nodiscard]] WeightedPoints view() const { return {x, y, products, air}; }
};

/// The snapshot's MPM particles, each weighted by its volume mass / density:
/// products weight if its material index is `products_material`, air weight
/// otherwise. Throws mpfd::Error when the snapshot has no particles.
[[nodiscard]] PointSet particle_points(const std::filesystem::path& snapshot,
                                       int products_material);

/// The x-y cell layout of a 2D snapshot (its /grid attributes; the scene's domain).
struct PlaneGrid {
  double origin[2];   ///< [m]
  double spacing[2];  ///< [m]
};

/// The snapshot's cells (one layer): products weight θ_p V_cell, air θ_a V_cell,
/// with θ_p, θ_a the cell fields `products_fraction`, `air_fraction` (e.g.
/// "volume_fraction_tnt"; an MPM's empty cell has both 0 and weighs nothing).
[[nodiscard]] PointSet cell_points(const std::filesystem::path& snapshot,
                                   const std::string& products_fraction,
                                   const std::string& air_fraction, const PlaneGrid& grid);

/// The handoffs of an AFDMP summary.json (details.afdmp.handoffs).
struct HandoffErrors {
  /// The largest relative error (mass, momentum, energy; sent vs received and solver vs sent).
  double worst = 0;
  /// Round-off of the audit's sums: two recursive sums of n positive terms
  /// differ by up to 2 (n − 1) u relative (u = 2^-53; Higham, Accuracy and
  /// Stability, §4.2), n the most cells or particles a handoff moved.
  double roundoff = 0;
};

/// Throws mpfd::Error when the summary lists no handoff.
[[nodiscard]] HandoffErrors handoff_errors(const std::filesystem::path& summary_json);

struct GaugeColumn {
  std::vector<double> time;   ///< [s]
  std::vector<double> value;  ///< in the column's units
};

/// Column `header` (e.g. "plate_centre.mises_stress[Pa]") of a gauges.csv;
/// throws mpfd::Error naming the header and the file when it is absent.
[[nodiscard]] GaugeColumn read_gauge_column(const std::filesystem::path& csv,
                                            const std::string& header);

}  // namespace mpfd::verification
