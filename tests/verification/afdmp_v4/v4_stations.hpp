#pragma once
// V4 gauge readings against Kingery-Bulmash, shared by the 0.25 m octant
// (v4_free_air_test.cpp) and the far-field octant (v4_far_field_test.cpp).
// Per gauge: peak overpressure = max p - p(0); arrival = first time p - p(0)
// exceeds 10 % of that peak (linear interpolation between samples).
#include <filesystem>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "tests/verification/support/kingery_bulmash.hpp"
#include "tests/verification/support/scene_text.hpp"

namespace mpfd::verification {

/// The V4 sphere: r = 12.41 mm of TNT at 1630 kg/m^3 (the thesis cube's 13.04 g).
inline constexpr double kSphereMass = 0.0130494;  // kg

struct Station {
  std::string gauge;
  double distance = 0;  ///< R [m]
  double peak = 0;      ///< max p - p(0) [Pa]
  double arrival = 0;   ///< s
  FreeAirBlast kb{};    ///< zero for Z < 0.5
};

/// Every gauge of `scene` read from `gauges_h5` (charge at the origin: R =
/// |position|; with `radial`, R = position x, as a 1D spherical scene's), against
/// KB for `mass` [kg]; prints one line per gauge tagged `name`.
std::vector<Station> read_stations(const std::filesystem::path& gauges_h5,
                                   const config::Scene& scene, double mass, const std::string& name,
                                   bool radial = false);

}  // namespace mpfd::verification
