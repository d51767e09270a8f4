#pragma once
// The run-long conservation audit of an AFDMP run (summary.json
// "conservation", as CFDMP's; docs/afdmp.md "Run-long audit"):
//   initial   what the run holds at t = 0: the MPM's particles (start: mpm),
//             or the 1D stage's shells inside the grid plus the ambient fill
//             the 1D -> 3D handoff gives the rest of the grid (start:
//             spherical), plus the FSI zone's particles the MPM keeps;
//   current   what the holders hold now, each counted once:
//               1D stage (inside the grid) + ambient fill
//             + FDM cells - the FSI-zone placeholder (the MPM's FSI particles
//               stand for that zone until phase 3; the placeholder is the
//               ambient state the MPM -> FDM handoff puts there, or the
//               1D -> 3D remap's ambient fill after a 1D start)
//             + MPM particles (all of them in phases 1 and 3; the frozen FSI
//               zone in phase 2);
//   outflow   the solvers' ledgers (v1.1 outflow_*, since Setup, momentum
//             also minus the impulse of walls and mirror planes; taken as 0
//             for a solver that does not offer boundary_outflow), plus what a
//             handoff drops on purpose, as named terms: the FSI-face leak at
//             fdm_to_mpm (the FDM's placeholder cells' gain, T §3.2.3), and,
//             for momentum only, the vector momentum the 1D -> 3D remap gives
//             the cells (the 1D stage holds a radial impulse, not a vector
//             momentum; its mirror planes' impulse is booked nowhere else).
// The 1D stage books no outflow: its particles do not leave, and its
// transmitting surface does no work until the wave reaches it.
// The readings travel as whole-field exports (proto/README.md §15) in chunks
// of max_chunk_bytes, as the handoffs' fields do.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/io/run_summary.hpp"
#include "cosim/message.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/handoff_audit.hpp"
#include "coupler/run/restart_file.hpp"
#include "coupler/run/spherical_stage.hpp"

namespace mpfd::coupler {

/// One audit export's reading: what the solver holds and its outflow ledger.
struct AuditReading {
  Conserved held;
  Conserved outflow;
};

/// The whole-field names of the FDM's audit reading (audit_cells): contents,
/// and outflow_* when the solver offers boundary_outflow.
[[nodiscard]] std::vector<std::string> fdm_audit_fields(bool outflow);
/// The same of the MPM's (audit_particles).
[[nodiscard]] std::vector<std::string> mpm_audit_fields(bool outflow);
/// The FDM's audit_cells of an export (`cells` cells of volume `cell_volume`;
/// outflow 0 without `outflow`). Throws mpfd::Error naming the array whose
/// row count differs.
[[nodiscard]] AuditReading fdm_audit_reading(const cosim::Message& fields, std::size_t cells,
                                             double cell_volume, bool outflow);
/// The MPM's audit_particles of an export (outflow 0 without `outflow`).
[[nodiscard]] AuditReading mpm_audit_reading(const cosim::Message& fields, bool outflow);

/// What a spherical_to_fdm handoff now would give the grid: the 1D stage's
/// shells inside it (mass, energy; momentum zero, see above) plus the scene's
/// `initial` state in the rest of the grid (the handoff's ambient fill).
[[nodiscard]] Conserved stage_and_fill(const config::Scene& scene, const SphericalStage& stage);

/// A Conserved as "/<owner>/<name>" of a coupled checkpoint, and back.
void save_conserved(RestartWriter& out, const std::string& owner, const std::string& name,
                    const Conserved& amount);
[[nodiscard]] Conserved restored_conserved(const RestartReader& in, const std::string& owner,
                                           const std::string& name);

class RunLongAudit {
 public:
  /// Takes what the holders hold now as the initial totals.
  void start();

  void set_fdm(const AuditReading& reading);
  void set_mpm(const AuditReading& reading);
  /// What the 1D stage and the ambient fill hold inside the grid.
  void set_stage(const Conserved& stage_and_fill);
  /// The FSI-zone placeholder the FDM holds (counted by the MPM's particles).
  void set_placeholder(const Conserved& placeholder);
  /// The holder handed its state over: it holds nothing from now (its outflow stays).
  void clear_fdm();
  void clear_mpm();
  void clear_stage();
  /// Drops `amount` on purpose at a handoff, booked as the named term `name`.
  void drop(const std::string& name, const Conserved& amount);
  /// Books the vector momentum `momentum` the 1D -> 3D remap gave the cells.
  void book_remap_momentum(const std::array<double, 3>& momentum);

  [[nodiscard]] Conserved current() const;
  /// Solver outflows plus the named terms (the entries' boundary_outflow).
  [[nodiscard]] Conserved outflow() const;
  [[nodiscard]] const Conserved& initial() const { return initial_; }

  /// mass, momentum_x/y/z, energy for RunSummary::set_conservation.
  [[nodiscard]] std::vector<io::ConservationEntry> entries() const;
  /// Each term, the holders' parts and the momentum errors relative to
  /// sqrt(2 M E) (details.afdmp.audit).
  [[nodiscard]] nlohmann::json summary() const;

  /// Every term, in a coupled checkpoint (restart_file.hpp), and back.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);

 private:
  /// The terms held whole, by name, as a checkpoint writes them (const or not with `Audit`).
  template <class Audit>
  static auto named_terms(Audit& audit);

  Conserved initial_;
  Conserved fdm_, mpm_, stage_, placeholder_;
  Conserved fdm_outflow_, mpm_outflow_;
  std::map<std::string, Conserved> dropped_;  ///< the named terms, summed per name
};

}  // namespace mpfd::coupler
