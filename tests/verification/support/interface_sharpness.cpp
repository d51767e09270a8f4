#include "tests/verification/support/interface_sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

struct Sample {
  double r;
  double products;
  double air;
};

/// The radius that misplaces the least weight: between two neighbouring samples,
/// the split whose inner side holds least air and outer side least products.
double best_split(std::vector<Sample>& samples) {
  std::sort(samples.begin(), samples.end(),
            [](const Sample& a, const Sample& b) { return a.r < b.r; });
  double products_outside = 0;
  for (const auto& s : samples) products_outside += s.products;
  double air_inside = 0;
  double best = products_outside;  // split before the first sample
  double radius = samples.front().r;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    air_inside += samples[i].air;
    products_outside -= samples[i].products;
    const double misplaced = air_inside + products_outside;
    if (misplaced < best) {
      best = misplaced;
      radius = i + 1 < samples.size() ? 0.5 * (samples[i].r + samples[i + 1].r) : samples[i].r;
    }
  }
  return radius;
}

}  // namespace

InterfaceSharpness interface_sharpness(const WeightedPoints& points, double cx, double cy,
                                       double angle_min, double angle_max, int sectors,
                                       double band) {
  const std::size_t n = points.x.size();
  if (points.y.size() != n || points.products.size() != n || points.air.size() != n)
    throw Error("interface_sharpness: x, y, products and air must have the same size (x has " +
                std::to_string(n) + ")");
  if (sectors < 1 || !(angle_max > angle_min) || band < 0)
    throw Error("interface_sharpness: need sectors >= 1, angle_max > angle_min and band >= 0");
  std::vector<std::vector<Sample>> by_sector(static_cast<std::size_t>(sectors));
  const double width = (angle_max - angle_min) / sectors;
  for (std::size_t p = 0; p < n; ++p) {
    if (points.products[p] < 0 || points.air[p] < 0)
      throw Error("interface_sharpness: negative weight at point " + std::to_string(p));
    const double dx = points.x[p] - cx, dy = points.y[p] - cy;
    const double angle = std::atan2(dy, dx);
    if (angle < angle_min || angle > angle_max) continue;
    const int s = std::min(sectors - 1, static_cast<int>((angle - angle_min) / width));
    by_sector[static_cast<std::size_t>(s)].push_back(
        {std::hypot(dx, dy), points.products[p], points.air[p]});
  }
  InterfaceSharpness result;
  double air_near = 0, air_in = 0, products_all = 0, products_out = 0;
  for (std::size_t s = 0; s < by_sector.size(); ++s) {
    auto& samples = by_sector[s];
    double products = 0, air = 0;
    for (const auto& sample : samples) {
      products += sample.products;
      air += sample.air;
    }
    if (products <= 0 || air <= 0)
      throw Error("interface_sharpness: sector " + std::to_string(s) +
                  " holds no products or no air; use fewer sectors or more points");
    const double r_i = best_split(samples);
    result.radius.push_back(r_i);
    for (const auto& sample : samples) {
      if (sample.r <= r_i + band) air_near += sample.air;
      if (sample.r < r_i - band) air_in += sample.air;
      products_all += sample.products;
      if (sample.r > r_i + band) products_out += sample.products;
    }
  }
  const auto [lo, hi] = std::minmax_element(result.radius.begin(), result.radius.end());
  result.mean_radius = std::accumulate(result.radius.begin(), result.radius.end(), 0.0) /
                       static_cast<double>(result.radius.size());
  result.anisotropy = (*hi - *lo) / result.mean_radius;
  result.air_inside = air_near > 0 ? air_in / air_near : 0.0;
  result.products_outside = products_out / products_all;
  return result;
}

}  // namespace mpfd::verification
