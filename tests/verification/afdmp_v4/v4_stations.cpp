#include "tests/verification/afdmp_v4/v4_stations.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/io/hdf5_file.hpp"

namespace mpfd::verification {

std::vector<Station> read_stations(const std::filesystem::path& gauges_h5,
                                   const config::Scene& scene, double mass, const std::string& name,
                                   bool radial) {
  const io::Hdf5File gauges(gauges_h5, io::Hdf5File::Mode::read);
  const auto t = gauges.read_dataset("/time").values;
  const double cube_root = std::cbrt(mass);
  std::vector<Station> stations;
  for (const auto& g : scene.gauges) {
    const auto p = gauges.read_dataset("/gauges/" + g.name + "/pressure").values;
    const double distance =
        radial ? g.position[0] : std::hypot(g.position[0], g.position[1], g.position[2]);
    Station s{g.name, distance};
    s.peak = *std::max_element(p.begin(), p.end()) - p.front();
    const double threshold = p.front() + 0.1 * s.peak;
    for (std::size_t k = 1; k < p.size(); ++k)
      if (p[k] > threshold) {
        s.arrival = t[k - 1] + (threshold - p[k - 1]) / (p[k] - p[k - 1]) * (t[k] - t[k - 1]);
        break;
      }
    if (s.distance / cube_root >= 0.5) s.kb = kingery_bulmash_free_air(mass, s.distance);
    std::printf("%s %-5s R %.3f m Z %.3f  peak %.4f MPa  arrival %.2f us", name.c_str(),
                s.gauge.c_str(), s.distance, s.distance / cube_root, s.peak / 1e6, s.arrival * 1e6);
    if (s.kb.overpressure > 0)
      std::printf("  KB %.4f MPa (%+5.1f %%), %.2f us (%+5.1f %%)", s.kb.overpressure / 1e6,
                  100 * (s.peak / s.kb.overpressure - 1), s.kb.arrival_time * 1e6,
                  100 * (s.arrival / s.kb.arrival_time - 1));
    std::printf("\n");
    stations.push_back(s);
  }
  return stations;
}

}  // namespace mpfd::verification
