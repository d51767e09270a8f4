// afdmp_v3_metrics: the V3 interface measures (v3_interface.hpp) of finished
// runs, one CSV line per source and time, for bench/afdmp/run_v3.sh.
// Usage: afdmp_v3_metrics afdmp|mpm RUN_DIR H_M PRODUCTS_INDEX PRODUCTS_NAME AIR_NAME TIME_S...
// Prints: source,time_s,mean_radius_m,anisotropy,air_inside,products_outside
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "tests/verification/afdmp/v3_interface.hpp"

int main(int argc, char** argv) {
  using namespace mpfd::verification;
  if (argc < 8) {
    std::fprintf(
        stderr, "usage: %s afdmp|mpm RUN_DIR H_M PRODUCTS_INDEX PRODUCTS_NAME AIR_NAME TIME_S...\n",
        argv[0]);
    return 2;
  }
  try {
    const std::string kind = argv[1];
    const std::vector<V3Source> sources =
        kind == "afdmp" ? std::vector<V3Source>{V3Source::afdmp_cells}
                        : std::vector<V3Source>{V3Source::mpm_cells, V3Source::mpm_particles};
    const double h = std::stod(argv[3]);
    const int products = std::stoi(argv[4]);
    std::printf("source,time_s,mean_radius_m,anisotropy,air_inside,products_outside\n");
    for (int a = 7; a < argc; ++a)
      for (const V3Source source : sources) {
        const double time = std::stod(argv[a]);
        const auto s = v3_measure(argv[2], source, time, h, products, argv[5], argv[6]);
        std::printf("%s,%.9g,%.9g,%.9g,%.9g,%.9g\n", source_name(source).c_str(), time,
                    s.mean_radius, s.anisotropy, s.air_inside, s.products_outside);
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "afdmp_v3_metrics: %s\n", e.what());
    return 1;
  }
  return 0;
}
