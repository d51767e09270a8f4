#pragma once
// `coupler run` on an AFDMP scene (T chapter 3): one solver is stepped at a
// time and the state changes hands at the phase triggers (afdmp_phase.hpp):
//   phase 1  the MPM detonates the charge (or the 1D spherical MPM does, in
//            this process, seed S);
//   phase 2  the FDM carries the blast, the particles become its tracers;
//   phase 3  (scenes with an FSI zone) the MPM takes the fluid zone back as
//            particles beside the structure it kept.
// An idle solver gets Pings (keep-alive); a solver with no further role gets
// Shutdown at once. Handoffs are audited and listed in summary.json
// (details.afdmp), and so is the whole run (summary.json "conservation",
// afdmp_audit.hpp); gauges are sampled by the active phase's solver. On any
// failure it names the solver, shuts the others down, keeps what was written,
// writes summary.json with status "failed" and throws.

#include <memory>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "cosim/hub.hpp"
#include "coupler/run/coupled_run.hpp"
#include "coupler/run/solver_handle.hpp"

namespace mpfd::coupler {

/// Runs the afdmp `scene` (text `scene_text`, sent to both solvers in Setup)
/// with the solvers "fdm" and "mpm" connecting to `hub`; `options.out_dir`
/// must have been prepared. Throws mpfd::Error.
CoupledRunReport run_afdmp(const config::Scene& scene, const std::string& scene_text,
                           cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                           const CoupledRunOptions& options);

}  // namespace mpfd::coupler
