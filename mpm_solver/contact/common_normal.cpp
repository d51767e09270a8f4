#include "mpm_solver/contact/common_normal.hpp"

namespace mpfd::mpm::contact {

template <int Dim>
std::optional<Vec<Dim>> common_normal(std::span<const Vec<Dim>> mass_gradient,
                                      std::size_t normal_body) {
  const Vec<Dim>& own = mass_gradient[normal_body];
  if (const double length = own.norm(); length > 0) return Vec<Dim>(own / length);  // T (2-23)
  Vec<Dim> others = Vec<Dim>::Zero();
  for (std::size_t b = 0; b < mass_gradient.size(); ++b) {
    if (b != normal_body) others -= mass_gradient[b];  // n^A = -n^B, T (2-24)
  }
  if (const double length = others.norm(); length > 0) return Vec<Dim>(others / length);
  return std::nullopt;
}

template std::optional<Vec<1>> common_normal<1>(std::span<const Vec<1>>, std::size_t);
template std::optional<Vec<2>> common_normal<2>(std::span<const Vec<2>>, std::size_t);
template std::optional<Vec<3>> common_normal<3>(std::span<const Vec<3>>, std::size_t);

}  // namespace mpfd::mpm::contact
