#include "mpm_solver/serve/served_zone.hpp"

#include <cmath>

#include "common/config/scene_loader.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::mpm {
namespace {

[[noreturn]] void reject(cosim::v1::ErrorCode code, const std::string& rule) {
  throw cosim::ProtocolError(code, "Setup: " + rule);
}

config::Scene parse_fragment(const cosim::v1::Setup& setup) {
  if (setup.zone().kind() == cosim::v1::ZONE_KIND_EULER)
    reject(cosim::v1::ERROR_CODE_UNEXPECTED,
           "zone '" + setup.zone().name() + "' is an EULER zone; mpm_solver serves MPM zones");
  if (!std::isfinite(setup.start_time()))
    reject(cosim::v1::ERROR_CODE_MALFORMED, "start_time must be finite");
  try {
    return config::parse_scene(setup.scene_fragment(), "Setup.scene_fragment");
  } catch (const Error& error) {
    reject(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
}

/// A zone grid given in Setup must have the scene's cells (axes it leaves out: one cell).
void check_zone_grid(const cosim::v1::UniformGrid& zone, const grid::UniformGrid& scene) {
  if (zone.cells().empty()) return;
  bool same = zone.cells_size() <= 3;
  for (int a = 0; a < 3 && same; ++a)
    same = (a < zone.cells_size() ? zone.cells(a) : 1U) == std::uint64_t(scene.cells()[a]);
  if (same) return;
  std::string given;
  for (const auto n : zone.cells()) given += (given.empty() ? "" : ", ") + std::to_string(n);
  const auto& n = scene.cells();
  reject(cosim::v1::ERROR_CODE_MALFORMED,
         "zone grid cells [" + given + "] differ from the scene's [" + std::to_string(n[0]) + ", " +
             std::to_string(n[1]) + ", " + std::to_string(n[2]) + "]");
}

}  // namespace

ServedZone::ServedZone(config::Scene scene_in, const cosim::v1::Setup& setup)
    : scene(std::move(scene_in)),
      scene_text(setup.scene_fragment()),
      output_dir(setup.output_dir()),
      solver(scene, MpmSettings::from_scene(scene)),
      followed_gauges(scene.gauges, solver.particles(), binding_reach(solver.grid())),
      setup_start_time(setup.start_time()),
      start_time(setup.start_time()),
      dormant(setup.zone().dormant()) {}

const ZoneRegion& ServedZone::region(const std::string& name, std::string_view operation) const {
  if (const auto found = regions.find(name); found != regions.end()) return found->second;
  std::string known;
  for (const auto& [key, value] : regions) known += (known.empty() ? "" : ", ") + key;
  throw cosim::ProtocolError(
      cosim::v1::ERROR_CODE_UNKNOWN_REGION,
      std::string(operation) + ": region '" + name +
          "' was not declared in Setup; declared: " + (known.empty() ? "none" : known));
}

std::unique_ptr<ServedZone> set_up_zone(const cosim::v1::Setup& setup) {
  auto scene = parse_fragment(setup);
  std::unique_ptr<ServedZone> zone;
  try {
    zone = std::make_unique<ServedZone>(std::move(scene), setup);
  } catch (const Error& error) {
    reject(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
  const auto& grid = zone->solver.grid();
  check_zone_grid(setup.zone().grid(), grid);
  for (const auto& region : setup.regions()) {
    ZoneRegion made = make_zone_region(region, grid);
    if (zone->regions.contains(made.name))
      reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION, "region '" + made.name + "' is declared twice");
    zone->regions.emplace(made.name, std::move(made));
  }
  return zone;
}

cosim::v1::SetupAck setup_ack(const cosim::v1::Setup& setup, const ServedZone& zone) {
  cosim::v1::SetupAck ack;
  for (const auto& declared : setup.regions()) {
    auto& echo = *ack.add_regions();
    echo = declared;
    echo.clear_quantities();
    for (const auto& q : zone.regions.at(declared.name()).quantities) echo.add_quantities(q);
  }
  ack.set_stable_dt(zone.solver.stable_dt());
  return ack;
}

}  // namespace mpfd::mpm
