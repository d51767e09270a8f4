#include "coupler/run/afdmp_run.hpp"

#include <set>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "coupler/run/afdmp_loop.hpp"
#include "coupler/run/session.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

std::vector<cosim::Message> setups(const config::Scene& scene, const std::string& text,
                                   const AfdmpRegions& regions, const std::filesystem::path& out) {
  std::vector<cosim::Message> messages(2);
  const char* names[2] = {"fdm", "mpm"};
  const v1::ZoneKind kinds[2] = {v1::ZONE_KIND_EULER, v1::ZONE_KIND_MPM};
  const std::vector<v1::Region>* lists[2] = {&regions.fdm, &regions.mpm};
  for (int s = 0; s < 2; ++s) {
    auto& setup = *messages[s].header.mutable_setup();
    setup.mutable_zone()->set_name(names[s]);
    setup.mutable_zone()->set_kind(kinds[s]);
    *setup.mutable_zone()->mutable_grid() = wire_grid(scene);
    setup.set_scene_fragment(text);
    for (const auto& r : *lists[s]) *setup.add_regions() = r;
    setup.set_output_dir((out / names[s]).string());
  }
  return messages;
}

/// Refuses solvers that lack what the scene needs, naming the capability.
void check_capabilities(const std::vector<v1::Hello>& hellos, bool mpm_needed, bool fsi_zone) {
  const auto need = [&](std::size_t s, const char* capability) {
    if (!offers(hellos[s], capability))
      throw Error("solver '" + kAfdmpPeers[s] + "' lacks capability '" + capability +
                  "' that solver.method afdmp needs (proto/README.md §15)");
  };
  need(0, "field_chunks");
  need(0, "tracer_regions");
  if (fsi_zone) need(0, "material_fields");
  if (mpm_needed) {
    need(1, "field_chunks");
    need(1, "particles");
  }
}

/// The run-long audit's outflow ledgers (v1.1 boundary_outflow): a solver that
/// does not offer them keeps the v1.0 behaviour (proto/README.md §14), its
/// outflow taken as 0 with a warning; summary.json details.protocol says so.
AuditOutflow audit_outflow(const std::vector<v1::Hello>& hellos, bool mpm_needed) {
  const AuditOutflow outflow{.fdm = offers(hellos[0], "boundary_outflow"),
                             .mpm = !mpm_needed || offers(hellos[1], "boundary_outflow")};
  const Logger logger("coupler");
  for (std::size_t s = 0; s < 2; ++s)
    if (!(s == 0 ? outflow.fdm : outflow.mpm))
      logger.warn("AFDMP: solver '", kAfdmpPeers[s],
                  "' does not offer boundary_outflow (proto/README.md §14): the run-long audit "
                  "takes its outflow as 0, so what leaves through open faces counts as an error");
  return outflow;
}

}  // namespace

CoupledRunReport run_afdmp(const config::Scene& scene, const std::string& scene_text,
                           cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                           const CoupledRunOptions& options) {
  const AfdmpLayout layout = make_afdmp_layout(scene);
  const AfdmpStart start = afdmp_start(scene);
  const auto body = [&](const std::vector<v1::Hello>& hellos, io::RunSummary& summary,
                        std::set<std::string>& retired) {
    const bool mpm_needed = start == AfdmpStart::mpm || layout.fsi_cells.has_value();
    check_capabilities(hellos, mpm_needed, layout.fsi_cells.has_value());
    const AuditOutflow outflow = audit_outflow(hellos, mpm_needed);
    // v1.2 additive (proto/README.md §15 rule 8): without it, today's cell-state start.
    // The 1D start's remap sends it only if the scene asks (solver.afdmp.spherical).
    const bool material_import =
        offers(hellos[0], "material_import") &&
        (start == AfdmpStart::mpm || scene.solver.afdmp.spherical.material_start);
    auto messages =
        setups(scene, scene_text, afdmp_setup_regions(layout, start, outflow, material_import),
               options.out_dir);
    hub.send("fdm", std::move(messages[0]));
    hub.send("mpm", std::move(messages[1]));
    hub.gather(kAfdmpPeers);
    AfdmpLoop loop(scene, scene_text, layout, outflow, material_import, hub, summary, options);
    try {
      const CoupledRunReport report = loop.run();
      retired = loop.retired();
      return report;
    } catch (...) {
      retired = loop.retired();
      try {
        if (loop.summary_ready()) loop.record_summary("failed", 0);
      } catch (const std::exception&) {
        // The run's own error is the one to report; run_session writes the summary's status.
      }
      throw;
    }
  };
  const CoupledRunReport report = run_session(scene, hub, solvers, options, body);
  Logger("coupler").info("done: ", report.steps, " steps to t = ", report.time, " s in ",
                         report.wall_seconds, " s; run-long mass error ", report.mass_error,
                         ", energy error ", report.energy_error);
  return report;
}

}  // namespace mpfd::coupler
