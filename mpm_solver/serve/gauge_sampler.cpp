#include "mpm_solver/serve/gauge_sampler.hpp"

#include <array>
#include <limits>
#include <string_view>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "mpm_solver/material/solid_response.hpp"

namespace mpfd::mpm {
namespace {

struct GaugeQuantity {
  std::string_view name;
  std::string_view units;
  double (*read)(const ParticleSet&, std::size_t);
};

constexpr std::array<GaugeQuantity, 10> kQuantities = {{
    {"density", "kg/m^3", [](const ParticleSet& ps, std::size_t p) { return ps.density[p]; }},
    {"pressure", "Pa", [](const ParticleSet& ps, std::size_t p) { return ps.pressure[p]; }},
    {"velocity_x", "m/s", [](const ParticleSet& ps, std::size_t p) { return ps.velocity[0][p]; }},
    {"velocity_y", "m/s", [](const ParticleSet& ps, std::size_t p) { return ps.velocity[1][p]; }},
    {"velocity_z", "m/s", [](const ParticleSet& ps, std::size_t p) { return ps.velocity[2][p]; }},
    {"specific_internal_energy", "J/kg",
     [](const ParticleSet& ps, std::size_t p) { return ps.specific_internal_energy[p]; }},
    {"position_x", "m", [](const ParticleSet& ps, std::size_t p) { return ps.position[0][p]; }},
    {"position_y", "m", [](const ParticleSet& ps, std::size_t p) { return ps.position[1][p]; }},
    {"position_z", "m", [](const ParticleSet& ps, std::size_t p) { return ps.position[2][p]; }},
    // The structure's yield measure (V5): sqrt(3/2 s:s) of the deviator.
    {"mises_stress", "Pa",
     [](const ParticleSet& ps, std::size_t p) { return von_mises_stress(ps.deviator(p)); }},
}};

const GaugeQuantity& find(const std::string& name) {
  for (const auto& q : kQuantities)
    if (q.name == name) return q;
  std::string known;
  for (const auto& q : kQuantities) known += (known.empty() ? "" : ", ") + std::string(q.name);
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                             "SampleGauges: unknown quantity '" + name + "'; known: " + known);
}

}  // namespace

std::uint64_t sample_gauges(const MpmSolver& solver, FollowedGauges& followed,
                            const cosim::v1::SampleGauges& request, cosim::Message& reply) {
  const auto gauges = static_cast<std::size_t>(request.gauge_names_size());
  if (static_cast<std::size_t>(request.positions_size()) != 3 * gauges)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "SampleGauges group '" + request.group() + "': " + std::to_string(gauges) +
            " gauges need " + std::to_string(3 * gauges) + " position values (x, y, z each), got " +
            std::to_string(request.positions_size()));
  const ParticleSet& ps = solver.particles();
  if (ps.size() == 0 && gauges > 0)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "SampleGauges group '" + request.group() + "': the MPM zone holds no particle to read");
  std::vector<std::size_t> nearest(gauges);
  for (std::size_t g = 0; g < gauges; ++g) {
    const std::string& name = request.gauge_names(static_cast<int>(g));
    nearest[g] = followed.follows(name)
                     ? followed.particle(name, ps)
                     : nearest_particle(ps, {request.positions(static_cast<int>(3 * g)),
                                             request.positions(static_cast<int>(3 * g + 1)),
                                             request.positions(static_cast<int>(3 * g + 2))});
  }
  for (const auto& name : request.quantities()) {
    const GaugeQuantity& q = find(name);
    std::vector<double> values(gauges);
    for (std::size_t g = 0; g < gauges; ++g)
      values[g] = nearest[g] == FollowedGauges::kLeft ? std::numeric_limits<double>::quiet_NaN()
                                                      : q.read(ps, nearest[g]);
    cosim::add_array(reply, {request.group(), q.name, {}, q.units}, std::move(values));
  }
  return gauges;
}

}  // namespace mpfd::mpm
