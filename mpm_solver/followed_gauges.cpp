#include "mpm_solver/followed_gauges.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::mpm {
namespace {

std::string point_text(const config::Vec3& x) {
  return "(" + shortest_text(x[0]) + ", " + shortest_text(x[1]) + ", " + shortest_text(x[2]) +
         ") m";
}

}  // namespace

double binding_reach(const grid::UniformGrid& grid) {
  double reach = 0.0;
  for (int a = 0; a < 3; ++a)
    if (grid.cells()[a] > 1) reach = std::max(reach, grid.spacing()[a]);
  return reach > 0.0 ? reach : std::max({grid.spacing()[0], grid.spacing()[1], grid.spacing()[2]});
}

std::uint64_t bind_to_particle(const ParticleSet& ps, const config::Gauge& gauge, double reach) {
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double dx = ps.position[0][p] - gauge.position[0],
                 dy = ps.position[1][p] - gauge.position[1],
                 dz = ps.position[2][p] - gauge.position[2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 < best_d2 || (d2 == best_d2 && ps.id[p] < ps.id[best])) {
      best_d2 = d2;
      best = p;
    }
  }
  const double distance = std::sqrt(best_d2);
  if (!(distance <= reach))
    throw Error("gauge '" + gauge.name + "' at " + point_text(gauge.position) +
                " follows the material, but " +
                (ps.size() == 0
                     ? std::string("there is no particle")
                     : "the nearest particle is " + shortest_text(distance) + " m away") +
                "; expected one within one cell (" + shortest_text(reach) + " m)");
  return ps.id[best];
}

FollowedGauges::FollowedGauges(std::span<const config::Gauge> gauges, const ParticleSet& ps,
                               double reach) {
  for (const config::Gauge& g : gauges) {
    if (g.follow != config::GaugeFollow::material) continue;
    const std::uint64_t id = bind_to_particle(ps, g, reach);
    const auto at = std::find(ps.id.begin(), ps.id.end(), id);
    bindings_.push_back({g.name, id, static_cast<std::size_t>(at - ps.id.begin())});
  }
}

bool FollowedGauges::follows(std::string_view name) const {
  return std::any_of(bindings_.begin(), bindings_.end(),
                     [&](const Binding& b) { return b.name == name; });
}

std::size_t FollowedGauges::binding(std::string_view name) const {
  for (std::size_t k = 0; k < bindings_.size(); ++k)
    if (bindings_[k].name == name) return k;
  throw Error("gauge '" + std::string(name) + "' does not follow a particle");
}

std::uint64_t FollowedGauges::id(std::string_view name) const {
  return bindings_[binding(name)].id;
}

std::size_t FollowedGauges::particle(std::string_view name, const ParticleSet& ps) {
  Binding& b = bindings_[binding(name)];
  if (b.hint < ps.size() && ps.id[b.hint] == b.id) return b.hint;
  // Removal never moves a kept particle up (ParticleSet::remove_flagged), so look below first.
  const auto end = ps.id.begin() + static_cast<std::ptrdiff_t>(std::min(b.hint, ps.size()));
  auto at = std::find(ps.id.begin(), end, b.id);
  if (at == end) at = std::find(end, ps.id.end(), b.id);
  if (at == ps.id.end()) return kLeft;
  b.hint = static_cast<std::size_t>(at - ps.id.begin());
  return b.hint;
}

}  // namespace mpfd::mpm
