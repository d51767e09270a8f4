#include "fdm_solver/serve/served_zone.hpp"

#include <cmath>

#include "common/config/scene_loader.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/flux_quantities.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void reject(cosim::v1::ErrorCode code, const std::string& rule) {
  throw cosim::ProtocolError(code, "Setup: " + rule);
}

/// A served Euler zone is coupled to an MPM that owns the structures (T §3.2.3,
/// §4.3): a body with a strength model would put tension the FDM cannot hold
/// into cells it never exchanges and stop it at step 0. Its cells keep the
/// scene's initial state instead.
void without_structures(config::Scene& scene) {
  std::erase_if(scene.bodies, [&](const config::Body& body) {
    const config::Material* m = config::find_material(scene, body.state.material);
    return m != nullptr && config::has_strength(*m);
  });
}

config::Scene parse_fragment(const cosim::v1::Setup& setup) {
  if (setup.zone().kind() == cosim::v1::ZONE_KIND_MPM)
    reject(cosim::v1::ERROR_CODE_UNEXPECTED,
           "zone '" + setup.zone().name() + "' is an MPM zone; fdm_solver serves EULER zones");
  if (!std::isfinite(setup.start_time()))
    reject(cosim::v1::ERROR_CODE_MALFORMED, "start_time must be finite");
  config::Scene scene;
  try {
    scene = config::parse_scene(setup.scene_fragment(), "Setup.scene_fragment");
  } catch (const Error& error) {
    reject(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
  without_structures(scene);
  return scene;
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
      solver(scene, SolverOptions::from_scene(scene)),
      output(setup.output_dir(), scene),
      setup_start_time(setup.start_time()),
      start_time(setup.start_time()) {}

const CellRegion& ServedZone::region(const std::string& name, std::string_view operation) const {
  if (const auto found = regions.find(name); found != regions.end()) return found->second;
  unknown_region(name, operation);
}

const TracerRegion* ServedZone::tracer_region(std::string_view name) const {
  const auto found = tracer_regions.find(name);
  return found == tracer_regions.end() ? nullptr : &found->second;
}

void ServedZone::unknown_region(std::string_view name, std::string_view operation,
                                bool fatal) const {
  std::string known;
  for (const auto& [key, value] : regions) known += (known.empty() ? "" : ", ") + key;
  for (const auto& [key, value] : tracer_regions) known += (known.empty() ? "" : ", ") + key;
  throw cosim::ProtocolError(
      cosim::v1::ERROR_CODE_UNKNOWN_REGION,
      std::string(operation) + ": region '" + std::string(name) +
          "' was not declared in Setup; declared: " + (known.empty() ? "none" : known),
      fatal);
}

std::unique_ptr<ServedZone> set_up_zone(const cosim::v1::Setup& setup) {
  auto scene = parse_fragment(setup);
  std::unique_ptr<ServedZone> zone;
  try {
    zone = std::make_unique<ServedZone>(std::move(scene), setup);
  } catch (const cosim::ProtocolError&) {
    throw;
  } catch (const Error& error) {
    reject(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
  const auto& grid = zone->solver.state().grid;
  check_zone_grid(setup.zone().grid(), grid);
  for (const auto& region : setup.regions()) {
    if (zone->regions.contains(region.name()) || zone->tracer_regions.contains(region.name()))
      reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
             "region '" + region.name() + "' is declared twice");
    if (region.kind() == cosim::v1::REGION_KIND_TRACERS) {  // v1.2
      zone->tracer_regions.emplace(region.name(), make_tracer_region(region, grid));
      continue;
    }
    CellRegion cells = make_cell_region(region, grid);
    if (cells.face_axis >= 0) {  // v1.1: the solver counts what crosses these faces
      if (!zone->solver.watched_crossing().empty())
        reject(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
               "region '" + cells.name + "': fdm_solver serves one FACES region per zone");
      zone->solver.watch_face(cells.face_axis, cells.box.lower[cells.face_axis]);
    }
    zone->regions.emplace(cells.name, std::move(cells));
  }
  return zone;
}

cosim::v1::SetupAck setup_ack(const cosim::v1::Setup& setup, const ServedZone& zone) {
  cosim::v1::SetupAck ack;
  for (const auto& declared : setup.regions()) {
    auto& echo = *ack.add_regions();
    echo = declared;
    echo.clear_quantities();
    if (const TracerRegion* tracers = zone.tracer_region(declared.name())) {
      for (const TracerQuantity q : tracers->quantities)
        echo.add_quantities(std::string(tracer_quantity_name(q)));
      continue;
    }
    const CellRegion& region = zone.regions.at(declared.name());
    for (const Quantity q : region.quantities) echo.add_quantities(std::string(info(q).name));
    for (const FluxQuantity q : region.fluxes) echo.add_quantities(std::string(info(q).name));
    for (const MaterialQuantity q : region.material_fields)
      echo.add_quantities(std::string(material_quantity_name(q)));
  }
  ack.set_stable_dt(zone.solver.stable_dt());
  return ack;
}

}  // namespace mpfd::fdm
