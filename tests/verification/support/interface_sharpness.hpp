#pragma once
// How sharp and how round a charge's products/air interface is (V3, T §3.4.2,
// Figs. 3.8–3.9: AFDMP keeps a sharp circle, pure MPM lets air particles into
// the products). Input is weighted points around the charge centre: MPM
// particles or FDM tracers (weight 1 for their own material), or FDM cells
// (products weight θ V, air weight (1 − θ) V).
// The quarter plane around the centre is cut into angular sectors; in each,
// the interface radius r_i is the one that misplaces the least weight
// (products beyond it plus air inside it). Then
//   anisotropy        = (max r_i − min r_i) / mean r_i over the sectors;
//   air_inside        = air weight closer than r_i − band / all air weight
//                       within r_i + band (both per sector, summed);
//   products_outside  = products weight beyond r_i + band / all products weight.

#include <span>
#include <vector>

namespace mpfd::verification {

struct WeightedPoints {
  std::span<const double> x;         ///< [m]
  std::span<const double> y;         ///< [m]
  std::span<const double> products;  ///< weight of detonation products at the point (>= 0)
  std::span<const double> air;       ///< weight of air at the point (>= 0)
};

struct InterfaceSharpness {
  std::vector<double> radius;   ///< r_i of each sector [m]
  double mean_radius = 0;       ///< [m]
  double anisotropy = 0;        ///< (max − min) / mean of r_i
  double air_inside = 0;        ///< fraction, see above
  double products_outside = 0;  ///< fraction, see above
};

/// Sectors of equal angle over [angle_min, angle_max] (radians, measured from +x around
/// (cx, cy)); `band` [m] >= 0. Throws mpfd::Error on arrays of different sizes, no
/// sectors, an empty sector (no products or no air weight in it) or a negative weight.
[[nodiscard]] InterfaceSharpness interface_sharpness(const WeightedPoints& points, double cx,
                                                     double cy, double angle_min, double angle_max,
                                                     int sectors, double band);

}  // namespace mpfd::verification
