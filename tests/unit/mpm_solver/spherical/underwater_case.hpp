#pragma once
// The underwater explosion of seed S (METHOD.md V10): a TNT sphere of radius
// a = 0.1 m (T Table 3.1) centre-initiated in water (AUTODYN polynomial water),
// peak pressures against Cole's law. configs/underwater_1d.yaml is the same
// case as a scene; scene_layers_test.cpp holds the two equal bit for bit.

#include <cmath>
#include <numbers>
#include <vector>

#include "mpm_solver/spherical/spherical_mpm.hpp"

namespace mpfd::mpm::spherical::testing {

inline constexpr double kChargeRadius = 0.1;  // a [m], S
inline constexpr double kTntDensity = 1630.0;

/// TNT, T Table 3.1 in SI.
inline config::Material tnt() {
  config::Material m;
  m.name = "tnt";
  m.eos = eos::Jwl{kTntDensity, 3.712e11, 3.21e9, 4.15, 0.95, 0.3, 6.993e9};
  m.explosive = config::Explosive{6930.0};
  return m;
}

/// Water, AUTODYN material library polynomial EOS (rho0 1000 kg/m^3, A1 2.2 GPa,
/// A2 9.54 GPa, A3 14.57 GPa, B0 = B1 = 0.28, T1 2.2 GPa, T2 0), the values
/// common/eos/polynomial.hpp and configs/SCENE-REFERENCE.md quote.
inline config::Material water() {
  config::Material m;
  m.name = "water";
  m.eos = eos::Polynomial{1000.0, 2.2e9, 9.54e9, 1.457e10, 0.28, 0.28, 2.2e9, 0.0};
  return m;
}

inline std::vector<RadialLayer> underwater_layers(double water_radius) {
  return {{tnt(), kChargeRadius, kTntDensity, 6.993e9 / kTntDensity, true},
          {water(), water_radius, 1000.0, 0.0, false}};
}

/// Cole (1948): Pm = 52.4 (W^(1/3) / R)^1.13 MPa, W [kg TNT], R [m]; returns Pa.
inline double cole_peak_pressure(double charge_mass, double range) {
  return 52.4e6 * std::pow(std::cbrt(charge_mass) / range, 1.13);
}

inline double charge_mass() {
  return 4.0 / 3.0 * std::numbers::pi * std::pow(kChargeRadius, 3) * kTntDensity;
}

struct PeakRecord {
  std::vector<double> stations;  ///< R [m]
  std::vector<double> peaks;     ///< max over time of p(R, t) [Pa]
};

/// Runs to end_time recording the peak EOS pressure at each station.
inline PeakRecord run_peaks(SphericalMpm& mpm, const std::vector<double>& stations,
                            double end_time) {
  PeakRecord record{stations, std::vector<double>(stations.size(), 0.0)};
  while (mpm.time() < end_time) {
    mpm.advance(std::min(mpm.stable_dt(), end_time - mpm.time() + 1e-12));
    for (std::size_t i = 0; i < stations.size(); ++i)
      record.peaks[i] = std::max(record.peaks[i], mpm.pressure_at(stations[i]));
  }
  return record;
}

}  // namespace mpfd::mpm::spherical::testing
