#include "tests/verification/support/cole_underwater.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

TEST(Cole, One_kilogram_at_one_metre_is_52_4_MPa) {
  EXPECT_NEAR(cole_peak_pressure(1.0, 1.0), 52.4e6, 1e-9 * 52.4e6);
}

TEST(Cole, Obeys_similitude_and_the_1_13_decay) {
  EXPECT_NEAR(cole_peak_pressure(8.0, 2.0), 52.4e6, 1e-9 * 52.4e6);  // same W^(1/3)/R
  EXPECT_NEAR(cole_peak_pressure(1.0, 1.0) / cole_peak_pressure(1.0, 2.0), std::pow(2.0, 1.13),
              1e-12);
}

TEST(Cole, Seed_S_charge_at_ten_radii) {
  // S: TNT sphere of radius a = 0.1 m (rho = 1630 kg/m^3, W = 6.828 kg) at R = 10 a:
  // 52.4 (1.8975)^1.13 = 108.1 MPa.
  const double w = 1630.0 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
  EXPECT_NEAR(cole_peak_pressure(w, 1.0), 108.1e6, 0.1e6);
}

TEST(Cole, Non_positive_distance_is_an_error) {
  EXPECT_THROW((void)cole_peak_pressure(1.0, 0.0), Error);
}

}  // namespace
}  // namespace mpfd::verification
