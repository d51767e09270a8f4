#include "coupler/run/strip_step_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/eos/any_eos.hpp"

namespace mpfd::coupler {

template <int Dim>
double strip_step_limit(std::span<const double> rho, std::span<const handshake::Vec<Dim>> momentum,
                        std::span<const double> energy, std::span<const double> pressure,
                        const InjectedMaterial& materials, const config::Scene& scene, double cfl,
                        double spacing) {
  double fastest = 0;
  for (std::size_t c = 0; c < rho.size(); ++c) {
    if (!(rho[c] > 0)) continue;
    const double u = momentum[c].norm() / rho[c];
    const double e = energy[c] / rho[c] - 0.5 * u * u;
    const auto m = materials.choose(rho[c], e, pressure[c]);
    const double speed = eos::sound_speed(scene.materials[m].eos, rho[c], e) + u;
    if (std::isfinite(speed)) fastest = std::max(fastest, speed);
  }
  return fastest > 0 ? cfl * spacing / fastest : std::numeric_limits<double>::infinity();
}

template double strip_step_limit<1>(std::span<const double>, std::span<const handshake::Vec<1>>,
                                    std::span<const double>, std::span<const double>,
                                    const InjectedMaterial&, const config::Scene&, double, double);
template double strip_step_limit<2>(std::span<const double>, std::span<const handshake::Vec<2>>,
                                    std::span<const double>, std::span<const double>,
                                    const InjectedMaterial&, const config::Scene&, double, double);
template double strip_step_limit<3>(std::span<const double>, std::span<const handshake::Vec<3>>,
                                    std::span<const double>, std::span<const double>,
                                    const InjectedMaterial&, const config::Scene&, double, double);

}  // namespace mpfd::coupler
