#include "coupler/run/afdmp_run.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/core/progress.hpp"
#include "common/grid/uniform_grid.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "cosim/arrays.hpp"
#include "coupler/handoff/detonation_trigger.hpp"
#include "coupler/run/afdmp_audit.hpp"
#include "coupler/run/afdmp_handoffs.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/afdmp_phase.hpp"
#include "coupler/run/coupler_checkpoint.hpp"
#include "coupler/run/field_transfer.hpp"
#include "coupler/run/gauges.hpp"
#include "coupler/run/session.hpp"
#include "coupler/run/spherical_stage.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

using Clock = std::chrono::steady_clock;
namespace region = afdmp_region;
const std::vector<std::string> kAfdmpPeers = {"fdm", "mpm"};

AfdmpStart start_of(const config::Scene& scene) {
  return scene.solver.afdmp.start == config::AfdmpStart::spherical ? AfdmpStart::spherical
                                                                   : AfdmpStart::mpm;
}

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

double proposed_dt(const cosim::Message& reply, const std::string& peer) {
  for (const auto& result : reply.header.exchange_result().results())
    if (result.has_proposed()) return result.proposed().stable_dt();
  throw Error("solver '" + peer + "' answered without a ProposeDt result");
}

class AfdmpLoop {
 public:
  AfdmpLoop(const config::Scene& scene, const std::string& scene_text, const AfdmpLayout& layout,
            AuditOutflow outflow, bool material_import, cosim::Hub& hub, io::RunSummary& summary,
            const CoupledRunOptions& options)
      : scene_(scene),
        scene_text_(scene_text),
        layout_(layout),
        outflow_(outflow),
        start_(start_of(scene)),
        machine_({.start = start_,
                  .end_time = scene.time.end,
                  .fsi_zone = layout.fsi_cells.has_value(),
                  .activation_pressure = layout.activation_pressure,
                  .handoff_radius = scene.solver.afdmp.spherical.handoff_radius.value_or(0.0)}),
        explosive_(explosive_materials(scene)),
        gauges_(scene, options.out_dir,
                options.restart ? io::GaugeStart::restart : io::GaugeStart::fresh),
        hub_(hub),
        summary_(summary),
        options_(options),
        settings_{.max_chunk_bytes = options.max_chunk_bytes,
                  .timeout = options.handoff_timeout,
                  .material_import = material_import},
        grid_(grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper,
                                             scene.domain.cells)) {
    for (const auto& peer : kAfdmpPeers) contact_[peer] = Clock::now();
  }

  CoupledRunReport run() {
    const auto start = Clock::now();
    phase_start_ = start;
    const RunPosition at = options_.restart ? resume(*options_.restart) : begin();
    const auto wall = [&] { return checkpoints_.earlier_wall_seconds() + seconds_since(start); };
    ProgressLine progress(std::cerr, scene_.time.end, "coupler", options_.progress);
    const double interval = scene_.output.interval > 0 ? scene_.output.interval : scene_.time.end;
    int outputs = at.outputs;
    double t = at.time;
    std::int64_t n = at.step;
    while (machine_.phase() != AfdmpPhase::done) {
      if (n >= scene_.time.max_steps)
        throw Error("scene '" + scene_.name +
                    "': time.max_steps = " + std::to_string(scene_.time.max_steps) +
                    " reached at t = " + std::to_string(t) + " s");
      const double next_output = std::min(scene_.time.end, outputs * interval);
      double dt = dt_;
      bool output_now = false;
      if (t + dt >= next_output * (1 - 1e-12)) {
        dt = next_output - t;
        output_now = true;
      }
      ++n;
      hub_.set_clock(static_cast<std::uint64_t>(n), t);
      const double t_next = output_now ? next_output : t + dt;
      step(t, t_next, n);
      t = t_next;
      ++phase_steps_;
      report_.steps = n;
      report_.time = t;
      hub_.set_clock(static_cast<std::uint64_t>(n), t);
      handle(machine_.next(observation_), t, n);
      if (output_now) {
        write_output(outputs++);
        // Before the summary, which then names it (one rewrite of summary.json and gauges.h5).
        if (checkpoints_.due(outputs, machine_.phase() != AfdmpPhase::done))
          checkpoint({.time = t, .step = n, .outputs = outputs}, wall());
        record_summary("running", wall());
      }
      keep_idle_alive();
      progress.update(n, t);
    }
    progress.finish(n, t);
    report_.wall_seconds = wall();
    record_summary("completed", report_.wall_seconds);
    return report_;
  }

  void record_summary(const std::string& status, double wall) {
    gauges_.flush();
    summary_.set_detail("gauges", gauges_.listing());
    summary_.set_status(status);
    summary_.set_progress(report_.steps, report_.time, scene_.time.end, wall);
    const auto entries = audit_.entries();
    summary_.set_conservation(entries);
    report_.mass_error = entries[0].relative_error(0);
    report_.energy_error = entries[4].relative_error(0);
    nlohmann::json phases = phases_;
    phases.push_back({{"phase", phase_name(machine_.phase())},
                      {"start", phase_time_},
                      {"steps", phase_steps_},
                      {"wall_s", seconds_since(phase_start_)}});
    summary_.set_detail("afdmp", {{"start", start_ == AfdmpStart::mpm ? "mpm" : "spherical"},
                                  {"phases", phases},
                                  {"transitions", transitions_},
                                  {"handoffs", handoffs_},
                                  {"audit", audit_.summary()},
                                  {"outputs", outputs_}});
    summary_.set_detail("checkpoints", checkpoints_.summary());
    summary_.set_detail("protocol", {{"fdm_outflow", outflow_.fdm},
                                     {"mpm_outflow", outflow_.mpm},
                                     {"fdm_material_import", settings_.material_import}});
    summary_.write(options_.out_dir / "summary.json");
  }

  /// False while a restart has not yet restored the run: its summary would hold nothing
  /// yet and must not replace the stopped run's files (gauges.h5 among them).
  [[nodiscard]] bool summary_ready() const { return checkpoints_.summary_ready(); }

  /// The peers that have not been shut down (for the final shutdown).
  [[nodiscard]] const std::set<std::string>& retired() const { return retired_; }

 private:
  /// A new run: phase 1 (or the 1D stage) set up, the audit's start, output 0.
  RunPosition begin() {
    if (start_ == AfdmpStart::spherical) {
      stage_.emplace(scene_);
      holder_ = "spherical";
      if (layout_.fsi_cells) {
        discard_mpm_fluid();
        audit_holder("mpm");  // the FSI zone it keeps
        // The FDM will hold the placeholder there, counted by the MPM's particles.
        audit_.set_placeholder(placeholder_conserved(scene_, layout_));
      } else {
        retire("mpm", "the 1D start and the FDM carry this scene; no FSI zone");
      }
      observe_stage();
      sample_stage_gauges(0);
      audit_holder("spherical");
    } else {
      step_mpm_detonation(false, 0, 0);
      audit_holder("mpm");
    }
    audit_.start();
    handle(machine_.next(observation_), 0, 0);
    write_output(0);
    return {.time = 0, .step = 0, .outputs = 1};
  }

  /// A restarted run: the coupler's state from `from`, checked, then each solver's
  /// Restore, the solvers retired before it retired again, and gauges.csv as the
  /// checkpoint had it. Nothing in the folder changes before the checks pass.
  RunPosition resume(const CouplerCheckpoint& from) {
    // Retired before the checkpoint; this run's solvers are shut down only once it is restored
    // (a refused restart shuts down every solver it started).
    std::set<std::string> retired;
    from.read_state([&](const RestartReader& in) {
      retired = restore(in);
      for (const auto& [peer, checkpoint] :
           {std::pair{"fdm", from.fdm}, std::pair{"mpm", from.mpm}}) {
        const std::string name = peer;
        if (checkpoint.has_value() != checkpointed(name, retired))
          in.refuse("names " + std::string(checkpoint ? "a" : "no") + " checkpoint of solver '" +
                    name + "', which " +
                    (retired.contains(name)        ? "was retired"
                     : checkpointed(name, retired) ? "holds state"
                                                   : "holds only its Setup's state") +
                    " in phase " + std::string(phase_name(machine_.phase())) + " (attribute " +
                    name + "_path, /afdmp/" + name + "_retired, /phases)");
      }
    });
    restore_solvers(hub_, from, options_.handoff_timeout);
    report_.steps = from.step;
    report_.time = from.time;
    for (const auto& peer : kAfdmpPeers)
      if (retired.contains(peer))
        retire(peer, "retired before the checkpoint this run restarts from");
    gauges_.resume_files();
    for (const auto& peer : kAfdmpPeers) contact_[peer] = Clock::now();
    hub_.set_clock(static_cast<std::uint64_t>(from.step), from.time);
    checkpoints_.restarted(from);
    Logger("coupler").info("restarted from ", from.file.string(), ": phase ",
                           phase_name(machine_.phase()), ", step ", from.step, ", t = ", from.time,
                           " s, ", from.outputs, " outputs written");
    return from.position();
  }

  /// Whether `peer` writes a checkpoint now, with `retired` shut down: not once retired, and
  /// not the FDM before the blast is handed to it (in the MPM detonation and the 1D stage
  /// it holds only its Setup's state, which a restart's Setup makes again).
  [[nodiscard]] bool checkpointed(const std::string& peer,
                                  const std::set<std::string>& retired) const {
    const AfdmpPhase phase = machine_.phase();
    const bool before_fdm =
        phase == AfdmpPhase::mpm_detonation || phase == AfdmpPhase::spherical_detonation;
    return !retired.contains(peer) && !(peer == "fdm" && before_fdm);
  }

  /// Each solver that holds state checkpoints, then the coupler's file (with the 1D stage's
  /// particles while it runs) is renamed into place last.
  void checkpoint(const RunPosition& at, double wall) {
    const auto start = Clock::now();
    std::vector<std::string> peers;
    for (const auto& peer : kAfdmpPeers)
      if (checkpointed(peer, retired_)) peers.push_back(peer);
    const auto taken = take_checkpoint(
        hub_, at, wall, options_.out_dir, peers, options_.handoff_timeout, scene_text_,
        grid_dimension(scene_), [&](RestartWriter& out) { save(out); });
    for (const auto& peer : peers) contact_[peer] = Clock::now();
    checkpoints_.taken(taken);
    Logger("coupler").info("checkpoint at step ", taken.step, ", t = ", taken.time,
                           " s: ", taken.file.string(), " (", seconds_since(start), " s)");
  }

  void save(RestartWriter& out) const {
    out.text("afdmp", "holder", holder_);
    out.number("afdmp", "dt", dt_);
    out.number("afdmp", "fdm_retired", retired_.contains("fdm") ? 1 : 0);
    out.number("afdmp", "mpm_retired", retired_.contains("mpm") ? 1 : 0);
    save_conserved(out, "afdmp", "placeholder", placeholder_);
    out.text("afdmp", "phases", phases_.dump());
    out.text("afdmp", "transitions", transitions_.dump());
    out.text("afdmp", "handoffs", handoffs_.dump());
    out.text("afdmp", "outputs", outputs_.dump());
    out.number("afdmp", "phase_time", phase_time_);
    out.number("afdmp", "phase_steps", static_cast<double>(phase_steps_));
    out.number("afdmp", "phase_wall_seconds", seconds_since(phase_start_));
    // What the solvers offered decides the audit's outflow and the handoffs' material import.
    out.number("afdmp", "fdm_outflow", outflow_.fdm ? 1 : 0);
    out.number("afdmp", "mpm_outflow", outflow_.mpm ? 1 : 0);
    out.number("afdmp", "fdm_material_import", settings_.material_import ? 1 : 0);
    machine_.save(out);
    audit_.save(out);
    gauges_.save(out);
    if (holder_ == "spherical") stage_->save(out);
  }

  /// The coupler's state from `in`; returns the solvers retired before the checkpoint.
  [[nodiscard]] std::set<std::string> restore(const RestartReader& in) {
    const std::string holder = in.text("afdmp", "holder");
    if (holder != "fdm" && holder != "mpm" && holder != "spherical")
      in.refuse("holds '" + holder +
                "' as the state's holder (/afdmp/holder); expected 'fdm', 'mpm' or 'spherical'");
    holder_ = holder;
    dt_ = in.number("afdmp", "dt");
    std::set<std::string> retired;
    for (const auto& peer : kAfdmpPeers)
      if (in.number("afdmp", peer + "_retired") != 0) retired.insert(peer);
    placeholder_ = restored_conserved(in, "afdmp", "placeholder");
    phases_ = in.json("afdmp", "phases");
    transitions_ = in.json("afdmp", "transitions");
    handoffs_ = in.json("afdmp", "handoffs");
    outputs_ = in.json("afdmp", "outputs");
    phase_time_ = in.number("afdmp", "phase_time");
    phase_steps_ = static_cast<std::int64_t>(in.number("afdmp", "phase_steps"));
    phase_start_ =
        Clock::now() - std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(in.number("afdmp", "phase_wall_seconds")));
    const std::pair<const char*, bool> features[] = {
        {"fdm_outflow", outflow_.fdm},
        {"mpm_outflow", outflow_.mpm},
        {"fdm_material_import", settings_.material_import}};
    for (const auto& [name, now] : features)
      if ((in.number("afdmp", name) != 0) != now)
        in.refuse("was written with solvers " + std::string(now ? "without" : "with") + " '" +
                  name + "' (/afdmp/" + name + "); these " + (now ? "offer" : "lack") +
                  " it: restart with the solvers of that run");
    machine_.restore(in);
    const AfdmpPhase phase = machine_.phase();
    const std::string expected = phase == AfdmpPhase::spherical_detonation ? "spherical"
                                 : phase == AfdmpPhase::fdm_blast          ? "fdm"
                                                                           : "mpm";
    if (holder_ != expected)
      in.refuse("holds '" + holder_ + "' as the state's holder (/afdmp/holder) in phase " +
                std::string(phase_name(phase)) + " (/phases); expected '" + expected + "'");
    audit_.restore(in);
    gauges_.restore(in);
    if (holder_ == "spherical") {
      stage_.emplace(scene_);
      stage_->restore(in);
    }
    return retired;
  }

  /// One step of the current phase from t to t_next.
  void step(double t, double t_next, std::int64_t n) {
    observation_ = Observation{};
    observation_.time = t_next;
    observation_.step = n;
    switch (machine_.phase()) {
      case AfdmpPhase::mpm_detonation:
        step_mpm_detonation(true, t_next - t, t);
        break;
      case AfdmpPhase::spherical_detonation:
        stage_->advance(t_next - t);
        observe_stage();
        sample_stage_gauges(t_next);
        break;
      case AfdmpPhase::fdm_blast:
        step_solver("fdm", t_next - t, t, GaugeSamplers::fdm_only);
        break;
      case AfdmpPhase::mpm_fsi:
        step_solver("mpm", t_next - t, t, GaugeSamplers::mpm_only);
        break;
      case AfdmpPhase::done:
        break;
    }
  }

  /// Phase 1 by the MPM: advance (unless step 0), the charge's burn state, dt.
  void step_mpm_detonation(bool advance, double dt, double t) {
    clear_for_reuse(mpm_request_);
    clear_for_reuse(fdm_request_);
    if (advance) add_advance(mpm_request_, dt, t);
    const int burn_op = exchange_of(mpm_request_).operations_size();
    add_export(mpm_request_, region::kChargeParticles, {"burn_fraction", "material"});
    gauges_.add(advance, advance ? t + dt : t, GaugeSamplers::mpm_only, fdm_request_, mpm_request_);
    add_propose_dt(mpm_request_);
    const cosim::Message reply = send_and_receive("mpm", mpm_request_);
    (void)result_of(reply, "mpm", burn_op);
    observation_.charge_burn = burn_observation(reply, region::kChargeParticles);
    if (machine_.needs_fluid_burn_check(*observation_.charge_burn)) {
      cosim::Message check;
      add_export(check, region::kFluidParticles, {"burn_fraction", "material"});
      const cosim::Message fluid = send_and_receive("mpm", check);
      observation_.fluid_burn = burn_observation(fluid, region::kFluidParticles);
    }
    gauges_.read(cosim::Message{}, reply);
    dt_ = proposed_dt(reply, "mpm");
  }

  /// Phase 2 (fdm) or 3 (mpm): advance, the FSI-face watch (phase 2), gauges (phase 2's
  /// following gauges from the idle MPM), dt.
  void step_solver(const std::string& peer, double dt, double t, GaugeSamplers samplers) {
    cosim::Message& request = peer == "fdm" ? fdm_request_ : mpm_request_;
    clear_for_reuse(fdm_request_);
    clear_for_reuse(mpm_request_);
    add_advance(request, dt, t);
    const bool watch = peer == "fdm" && layout_.watch_cells.has_value();
    if (watch) add_export(request, region::kFsiWatch, {"pressure"});
    gauges_.add(true, t + dt, samplers, fdm_request_, mpm_request_);
    add_propose_dt(request);
    const cosim::Message reply = send_and_receive(peer, request);
    if (watch) {
      const auto p = cosim::view_array<double>(reply, region::kFsiWatch, "pressure");
      observation_.watch_pressure.assign(p.values().begin(), p.values().end());
    }
    if (peer == "fdm") {
      // Gauges that follow the material are read from the idle MPM's particles.
      const bool following = exchange_of(mpm_request_).operations_size() > 0;
      gauges_.read(reply, following ? send_and_receive("mpm", mpm_request_) : cosim::Message{});
    } else {
      gauges_.read(cosim::Message{}, reply);
    }
    dt_ = proposed_dt(reply, peer);
  }

  BurnObservation burn_observation(const cosim::Message& reply, const char* region_name) const {
    const auto burn = cosim::view_array<double>(reply, region_name, "burn_fraction");
    const auto material = cosim::view_array<std::uint32_t>(reply, region_name, "material");
    materials_.assign(material.values().begin(), material.values().end());  // keeps its memory
    BurnObservation seen;
    for (const int m : materials_)
      if (std::find(explosive_.begin(), explosive_.end(), m) != explosive_.end())
        ++seen.explosive_particles;
    seen.complete = handoff::detonation_complete(burn.values(), materials_, explosive_);
    return seen;
  }

  cosim::Message send_and_receive(const std::string& peer, cosim::Message& request) {
    hub_.send_keeping_header(peer, request);
    cosim::Message reply = hub_.receive_from(peer);
    contact_[peer] = Clock::now();
    return reply;
  }

  /// A transition due now: hand over, retire the solver without a further role.
  void handle(const std::optional<Transition>& transition, double t, std::int64_t n) {
    if (!transition) return;
    transitions_.push_back(transition->summary());
    phases_.push_back({{"phase", phase_name(transition->from)},
                       {"start", phase_time_},
                       {"end", t},
                       {"steps", phase_steps_},
                       {"wall_s", seconds_since(phase_start_)}});
    phase_time_ = t;
    phase_steps_ = 0;
    phase_start_ = Clock::now();
    const Logger logger("coupler");
    logger.info("AFDMP: ", phase_name(transition->from), " -> ", phase_name(transition->to),
                " at t = ", t, " s (step ", n, ", ", trigger_name(transition->trigger), ")");
    // A handoff can outlast an idle solver's patience (an embedded solver waits 60 s):
    // restart every clock before it begins.
    ping_idle(std::chrono::milliseconds(0));
    const bool handing_over =
        transition->to == AfdmpPhase::fdm_blast || transition->to == AfdmpPhase::mpm_fsi;
    // The giver's last totals and outflow ledger (a retired solver answers no more).
    if (handing_over) audit_holder(holder_);
    const Conserved before = sum(audit_.current(), audit_.outflow());
    const auto at_end = audit_.entries();  // the run-long errors as the phase ends
    std::optional<HandoffRecord> record;
    if (transition->to == AfdmpPhase::fdm_blast) {
      if (transition->from == AfdmpPhase::spherical_detonation) {
        record = handoff_spherical_to_fdm(scene_, *stage_, hub_, settings_);
        audit_.clear_stage();
      } else {
        record = handoff_mpm_to_fdm(scene_, layout_, hub_, settings_);
        if (layout_.fsi_cells) {
          discard_mpm_fluid();
          audit_holder("mpm");  // the FSI zone it keeps, frozen through phase 2
        } else {
          retire("mpm", "the FDM carries the blast; no FSI zone");
          audit_.clear_mpm();
        }
      }
      // The FSI zone's cells: the MPM -> FDM handoff fills them with the ambient state;
      // the 1D -> 3D remap gives them its ambient fill, the same while the 1D stage's
      // ball stays outside the zone (else the difference shows as the fsi_face_leak).
      placeholder_ = placeholder_conserved(scene_, layout_);
      holder_ = "fdm";
      contact_["fdm"] = Clock::now();
      audit_holder("fdm");
      audit_.set_placeholder(placeholder_);
      if (transition->from == AfdmpPhase::spherical_detonation)
        audit_.book_remap_momentum(
            difference(sum(audit_.current(), audit_.outflow()), before).momentum);
    } else if (transition->to == AfdmpPhase::mpm_fsi) {
      record = handoff_fdm_to_mpm(scene_, layout_, hub_, settings_, placeholder_);
      retire("fdm", "the MPM carries the FSI phase");
      audit_.clear_fdm();
      audit_.drop("fsi_face_leak", record->fsi_face_leak);
      holder_ = "mpm";
      contact_["mpm"] = Clock::now();
      audit_holder("mpm");
    }
    if (!record) return;
    // The run-long audit across the handoff: held + outflow + dropped, after - before.
    const Conserved jump = difference(sum(audit_.current(), audit_.outflow()), before);
    record->summary["run_long_error_before"] = {{"mass", at_end[0].relative_error(0)},
                                                {"energy", at_end[4].relative_error(0)}};
    record->summary["run_long_jump"] = {{"mass", jump.mass / audit_.initial().mass},
                                        {"momentum", jump.momentum},
                                        {"energy", jump.energy / audit_.initial().energy}};
    record->summary["time"] = t;
    record->summary["step"] = n;
    record->summary["trigger"] = transition->summary();
    record->summary["tolerance"] = record->tolerance;
    handoffs_.push_back(record->summary);
    dt_ = record->stable_dt;
    const double worst = record->worst_error.worst();
    logger.info("AFDMP: ", record->summary["name"].get<std::string>(),
                " handoff: worst relative conservation error ", worst, " in ",
                record->summary["wall_s"].get<double>(), " s");
    if (worst > record->tolerance)
      logger.warn("AFDMP: the ", record->summary["name"].get<std::string>(),
                  " handoff conserves only to ", worst, " (round-off allows ", record->tolerance,
                  "); see summary.json details.afdmp.handoffs");
  }

  /// The MPM keeps its FSI-zone particles; what lies outside them is the FDM's now.
  void discard_mpm_fluid() {
    cosim::Message request;
    add_remove(request, "to_fdm", region::kFsiParticles);
    exchange_of(request).mutable_operations(0)->mutable_remove()->set_discard(true);
    (void)send_and_receive("mpm", request);
  }

  void retire(const std::string& peer, const std::string& reason) {
    cosim::Message message;
    message.header.mutable_shutdown()->set_reason(reason);
    hub_.send(peer, std::move(message));
    (void)hub_.receive_from(peer);
    retired_.insert(peer);
  }

  /// Pings every idle solver still needed whose last answer is older than keep_alive.
  void keep_idle_alive() { ping_idle(options_.keep_alive); }

  /// Pings every solver still needed, other than the active one, whose last answer is
  /// older than `age`.
  void ping_idle(std::chrono::milliseconds age) {
    for (const auto& peer : kAfdmpPeers) {
      if (peer == holder_ || retired_.contains(peer)) continue;
      if (Clock::now() - contact_[peer] < age) continue;
      cosim::Message ping;
      ping.header.mutable_ping();
      hub_.send(peer, std::move(ping));
      const auto pong = hub_.receive_from(peer);
      if (!pong.header.has_pong())
        throw Error("solver '" + peer + "' answered Ping with '" +
                    std::string(cosim::body_name(pong.header)) + "'");
      contact_[peer] = Clock::now();
    }
  }

  void observe_stage() {
    observation_.spherical_burn_complete = stage_->burn_complete();
    observation_.front_radius = stage_->front_radius();
    dt_ = stage_->stable_dt();
  }

  void sample_stage_gauges(double t) {
    if (!gauges_.due(t)) return;
    stage_pressure_.resize(scene_.gauges.size());
    stage_->gauge_pressures(stage_pressure_);
    gauges_.record_pressure(t, stage_pressure_);
  }

  /// The run-long audit's reading of `who` ("spherical", "fdm" or "mpm") now.
  void audit_holder(const std::string& who) {
    if (who == "spherical") {
      audit_.set_stage(stage_and_fill(scene_, *stage_));
      return;
    }
    // Chunked as the handoffs' fields: a whole grid in one reply could pass max_message_bytes.
    const bool fdm = who == "fdm";
    const auto names = fdm ? fdm_audit_fields(outflow_.fdm) : mpm_audit_fields(outflow_.mpm);
    const cosim::Message fields = export_fields(hub_, who, "audit", names, options_.max_chunk_bytes,
                                                options_.handoff_timeout);
    contact_[who] = Clock::now();
    if (fdm)
      audit_.set_fdm(fdm_audit_reading(fields, static_cast<std::size_t>(grid_.cell_count()),
                                       grid_.cell_volume(), outflow_.fdm));
    else
      audit_.set_mpm(mpm_audit_reading(fields, outflow_.mpm));
  }

  /// Output of the solver that holds the state now (the last phase's, once done),
  /// and the run-long audit's reading of it.
  void write_output(int index) {
    audit_holder(holder_);
    if (holder_ == "spherical")
      write_stage_profile(index);
    else
      write_solver_output(holder_, index);
  }

  void write_solver_output(const std::string& peer, int index) {
    cosim::Message message;
    message.header.mutable_write_output()->set_basename(peer + "_" + std::to_string(index));
    hub_.send(peer, std::move(message));
    const cosim::Message reply = hub_.receive_from(peer);
    contact_[peer] = Clock::now();
    // Each solver numbers its own snapshots: list the files that hold this output.
    nlohmann::json files = nlohmann::json::array();
    for (const auto& file : reply.header.output_written().files())
      files.push_back(io::path_in_run(file, options_.out_dir));
    outputs_.push_back(
        {{"index", index}, {"solver", peer}, {"time", report_.time}, {"files", files}});
  }

  /// The 1D stage's particles as CSV (radius, density, velocity, specific energy, material).
  void write_stage_profile(int index) {
    std::ostringstream name;
    name << "profile_" << std::setw(4) << std::setfill('0') << index << ".csv";
    const auto dir = options_.out_dir / "spherical";
    std::filesystem::create_directories(dir);
    std::ofstream out(dir / name.str());
    if (!out)
      throw Error("cannot write the 1D stage's profile '" + (dir / name.str()).string() + "'");
    out << "# 1D spherical stage at t = " << stage_->time() << " s\n"
        << "r_inner_m,r_outer_m,density_kg_m3,velocity_m_s,specific_internal_energy_J_kg,"
           "material\n";
    out << std::setprecision(10);
    const auto shells = stage_->shells();
    for (std::size_t k = 0; k < shells.density.size(); ++k)
      out << shells.edges[k] << ',' << shells.edges[k + 1] << ',' << shells.density[k] << ','
          << shells.velocity[k] << ',' << shells.internal_energy[k] << ',' << shells.material[k]
          << '\n';
    if (!out.flush())
      throw Error("writing the 1D stage's profile '" + (dir / name.str()).string() + "' failed");
    outputs_.push_back(
        {{"index", index},
         {"solver", "spherical"},
         {"time", report_.time},
         {"files", {io::path_in_run((dir / name.str()).string(), options_.out_dir)}}});
  }

  const config::Scene& scene_;
  const std::string& scene_text_;
  const AfdmpLayout& layout_;
  AuditOutflow outflow_;
  AfdmpStart start_;
  PhaseMachine machine_;
  std::vector<int> explosive_;
  mutable std::vector<int> materials_;  ///< scratch of burn_observation, kept between steps
  CoupledGauges gauges_;
  cosim::Hub& hub_;
  io::RunSummary& summary_;
  const CoupledRunOptions& options_;
  HandoffSettings settings_;
  grid::UniformGrid grid_;  ///< the scene's
  RunLongAudit audit_;
  std::optional<SphericalStage> stage_;
  std::string holder_ = "mpm";  ///< who holds the state: "mpm", "spherical" or "fdm"
  Observation observation_;
  double dt_ = 0;
  cosim::Message fdm_request_, mpm_request_;
  std::map<std::string, Clock::time_point> contact_;
  std::set<std::string> retired_;
  Conserved placeholder_;
  std::vector<double> stage_pressure_;
  nlohmann::json phases_ = nlohmann::json::array();
  nlohmann::json transitions_ = nlohmann::json::array();
  nlohmann::json handoffs_ = nlohmann::json::array();
  nlohmann::json outputs_ = nlohmann::json::array();
  double phase_time_ = 0;
  std::int64_t phase_steps_ = 0;
  Clock::time_point phase_start_;
  CoupledRunReport report_;
  CheckpointLog checkpoints_{options_.checkpoint_every, options_.checkpoint_keep,
                             options_.restart.has_value()};
};

}  // namespace

CoupledRunReport run_afdmp(const config::Scene& scene, const std::string& scene_text,
                           cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                           const CoupledRunOptions& options) {
  const AfdmpLayout layout = make_afdmp_layout(scene);
  const AfdmpStart start = start_of(scene);
  const auto body = [&](const std::vector<v1::Hello>& hellos, io::RunSummary& summary,
                        std::set<std::string>& retired) {
    const bool mpm_needed = start == AfdmpStart::mpm || layout.fsi_cells.has_value();
    check_capabilities(hellos, mpm_needed, layout.fsi_cells.has_value());
    const AuditOutflow outflow = audit_outflow(hellos, mpm_needed);
    // v1.2 additive (proto/README.md §15 rule 8): without it, today's cell-state start.
    const bool material_import = start == AfdmpStart::mpm && offers(hellos[0], "material_import");
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
