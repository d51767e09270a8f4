#include "tests/verification/afdmp/oscillation.hpp"

#include <algorithm>
#include <vector>

namespace mpfd::verification {

std::vector<std::size_t> prominent_maxima(std::span<const double> v, double min_prominence) {
  std::vector<std::size_t> at;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    if (!(v[i] > v[i - 1] && v[i] >= v[i + 1])) continue;
    double left = v[i];
    for (std::size_t k = i; k-- > 0 && v[k] <= v[i];) left = std::min(left, v[k]);
    double right = v[i];
    for (std::size_t k = i + 1; k < v.size() && v[k] <= v[i]; ++k) right = std::min(right, v[k]);
    if (v[i] - std::max(left, right) > min_prominence) at.push_back(i);
  }
  return at;
}

int prominent_extrema(std::span<const double> values, double min_prominence) {
  std::vector<double> negated(values.size());
  std::transform(values.begin(), values.end(), negated.begin(), [](double x) { return -x; });
  return static_cast<int>(prominent_maxima(values, min_prominence).size() +
                          prominent_maxima(negated, min_prominence).size());
}

}  // namespace mpfd::verification
