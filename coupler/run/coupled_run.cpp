#include "coupler/run/coupled_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string_view>
#include <variant>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/core/progress.hpp"
#include "common/io/run_summary.hpp"
#include "coupler/run/activation.hpp"
#include "coupler/run/cfdmp_step.hpp"
#include "coupler/run/gauges.hpp"
#include "coupler/run/restart_file.hpp"
#include "coupler/run/session.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

using Clock = std::chrono::steady_clock;
const std::vector<std::string> kPeers = {"fdm", "mpm"};
const std::vector<std::string> kFdmOnly = {"fdm"};
const std::vector<std::string> kMpmOnly = {"mpm"};

/// The Setup of each solver (proto §5, regions of §6).
std::vector<cosim::Message> setups(const config::Scene& scene, const std::string& text,
                                   const ZoneLayout& layout, const SolverFeatures& features,
                                   const std::filesystem::path& out) {
  std::vector<cosim::Message> messages(2);
  auto& fdm = *messages[0].header.mutable_setup();
  fdm.mutable_zone()->set_name("fdm");
  fdm.mutable_zone()->set_kind(v1::ZONE_KIND_EULER);
  *fdm.mutable_zone()->mutable_grid() = wire_grid(scene);
  fdm.mutable_zone()->set_ghost_layers(static_cast<std::uint32_t>(config::kFdmGhostLayers));
  fdm.set_scene_fragment(text);
  const auto cells = v1::REGION_KIND_CELLS;
  *fdm.add_regions() =
      make_region("ghost_cells", cells, layout.ghost_cells, {"rho", "momentum", "E"});
  *fdm.add_regions() =
      make_region("strip_cells", cells, layout.strip_cells, {"rho", "momentum", "E", "pressure"});
  *fdm.add_regions() =
      make_region("deposit_cells", cells, layout.deposit_cells, {"rho", "momentum", "E"});
  const bool outer_nodes = mpm_reaches_outer_nodes(scene);
  if (outer_nodes)
    *fdm.add_regions() = make_region("beyond_cells", cells, layout.beyond_cells,
                                     {"rho", "momentum", "E", "pressure"});
  // Audit regions: contents, and what left through their domain faces (v1.1) when offered.
  const auto audit_region = [&](std::string_view name, const WireBox& box) {
    auto region = make_region(name, cells, box, {"rho", "momentum", "E"});
    if (features.fdm_outflow)
      for (const char* q : {"outflow_mass", "outflow_momentum", "outflow_energy"})
        region.add_quantities(q);
    return region;
  };
  *fdm.add_regions() = audit_region("fdm_owned", layout.fdm_owned);
  if (features.fdm_face_crossing) {  // v1.1 (proto §14)
    auto& face = *fdm.add_regions();
    face = make_region("coupling_face", v1::REGION_KIND_FACES, layout.coupling_face,
                       {"crossed_mass", "crossed_momentum", "crossed_energy"});
    face.set_face_axis(static_cast<std::uint32_t>(layout.face_axis));
  }
  const bool dormant = scene.zones->mpm->activation_pressure.has_value();
  if (dormant)  // the audit's stand-in for the sleeping MPM zone (activation.hpp)
    *fdm.add_regions() = audit_region("dormant_zone", layout.mpm_zone);
  fdm.set_output_dir((out / "fdm").string());

  auto& mpm = *messages[1].header.mutable_setup();
  mpm.mutable_zone()->set_name("mpm");
  mpm.mutable_zone()->set_kind(v1::ZONE_KIND_MPM);
  mpm.mutable_zone()->set_dormant(dormant);
  *mpm.mutable_zone()->mutable_grid() = wire_grid(scene);
  mpm.set_scene_fragment(text);
  *mpm.add_regions() = make_region("ghost_nodes", v1::REGION_KIND_NODES, layout.ghost_nodes,
                                   {"mass", "momentum", "internal_energy"});
  *mpm.add_regions() = make_region("interface_nodes", v1::REGION_KIND_NODES, layout.interface_nodes,
                                   {"mass", "momentum", "internal_force"});
  if (outer_nodes)
    *mpm.add_regions() = make_region("outer_nodes", v1::REGION_KIND_NODES, layout.outer_nodes,
                                     {"mass", "momentum", "internal_force"});
  // CfdmpStep::build exports the same names each step (any_solid_ = has_structure).
  if (config::has_structure(scene))
    *mpm.add_regions() = make_region("face_particles", v1::REGION_KIND_PARTICLES, layout.face_cells,
                                     {"mass", "position", "volume", "material"});
  else
    *mpm.add_regions() = make_region("face_particles", v1::REGION_KIND_PARTICLES, layout.face_cells,
                                     {"mass", "position"});
  *mpm.add_regions() = features.mpm_outflow
                           ? make_region("mpm_zone", v1::REGION_KIND_PARTICLES, layout.mpm_zone,
                                         {"mass", "velocity", "internal_energy", "outflow_mass",
                                          "outflow_momentum", "outflow_energy"})
                           : make_region("mpm_zone", v1::REGION_KIND_PARTICLES, layout.mpm_zone,
                                         {"mass", "velocity", "internal_energy"});
  mpm.set_output_dir((out / "mpm").string());
  return messages;
}

Totals sum(std::initializer_list<Totals> parts) {
  Totals t;
  for (const Totals& part : parts) {
    t.mass += part.mass;
    t.energy += part.energy;
    for (int k = 0; k < 3; ++k) t.momentum[k] += part.momentum[k];
  }
  return t;
}

std::vector<io::ConservationEntry> audit(const Totals& initial, const Totals& now,
                                         const Totals& outflow) {
  std::vector<io::ConservationEntry> entries;
  entries.push_back({"mass", "kg", initial.mass, now.mass, outflow.mass});
  const char* names[3] = {"momentum_x", "momentum_y", "momentum_z"};
  for (int k = 0; k < 3; ++k)
    entries.push_back(
        {names[k], "kg m/s", initial.momentum[k], now.momentum[k], outflow.momentum[k]});
  entries.push_back({"energy", "J", initial.energy, now.energy, outflow.energy});
  return entries;
}

nlohmann::json totals_json(const Totals& t) {
  return {{"mass", t.mass}, {"momentum", t.momentum}, {"energy", t.energy}};
}

template <int Dim>
class Loop {
 public:
  Loop(const config::Scene& scene, const std::string& scene_text, const ZoneLayout& layout,
       const SolverFeatures& features, cosim::Hub& hub, io::RunSummary& summary,
       const CoupledRunOptions& options)
      : scene_(scene),
        scene_text_(scene_text),
        step_(scene, layout, features),
        watch_(scene.zones->mpm->activation_pressure),
        gauges_(scene, options.out_dir,
                options.restart ? io::GaugeStart::restart : io::GaugeStart::fresh),
        hub_(hub),
        summary_(summary),
        options_(options) {}

  CoupledRunReport run() {
    const auto start = Clock::now();
    const RunPosition at = options_.restart ? resume(*options_.restart) : begin();
    ProgressLine progress(std::cerr, scene_.time.end, "coupler", options_.progress);
    const double interval = scene_.output.interval > 0 ? scene_.output.interval : scene_.time.end;
    int outputs = at.outputs;
    double t = at.time;
    std::int64_t n = at.step;
    const auto wall = [&] { return checkpoints_.earlier_wall_seconds() + seconds_since(start); };
    while (t < scene_.time.end * (1 - 1e-12)) {
      if (n >= scene_.time.max_steps)
        throw Error("scene '" + scene_.name +
                    "': time.max_steps = " + std::to_string(scene_.time.max_steps) +
                    " reached at t = " + std::to_string(t) + " s");
      if (watch_.due()) activate(t, n);
      const double next_output = std::min(scene_.time.end, outputs * interval);
      const auto [dt, output_now] = step_to_output(t, step_.stable_dt(), next_output);
      count_limit(step_.limited_by());
      ++n;
      hub_.set_clock(static_cast<std::uint64_t>(n), t);
      const auto step_start = Clock::now();
      const auto [fdm_s, mpm_s] = exchange({.advance = true, .dt = dt, .time = t, .step = n});
      report_.fdm_advance_seconds += fdm_s;
      report_.mpm_advance_seconds += mpm_s;
      report_.max_advance_seconds += std::max(fdm_s, mpm_s);
      step_seconds_ += seconds_since(step_start);
      t = output_now ? next_output : t + dt;
      report_.steps = n;
      report_.time = t;
      if (output_now) {
        hub_.set_clock(static_cast<std::uint64_t>(n), t);
        exchange({.advance = false, .time = t, .audit = true});
        write_output(outputs++);
        // Before the summary, which then names it (one rewrite of summary.json and gauges.h5).
        if (checkpoints_.due(outputs, t < scene_.time.end * (1 - 1e-12)))
          checkpoint({.time = t, .step = n, .outputs = outputs}, wall());
        record_summary("running", wall());
      }
      progress.update(n, t);
    }
    progress.finish(n, t);
    report_.wall_seconds = wall();
    record_summary("completed", report_.wall_seconds);
    return report_;
  }

  [[nodiscard]] std::string face_drain_text() const { return step_.face_drain_text(); }
  /// False while a restart has not yet restored the run: its summary would hold nothing
  /// yet and must not replace the stopped run's files (gauges.h5 among them).
  [[nodiscard]] bool summary_ready() const { return checkpoints_.summary_ready(); }

  void record_summary(const std::string& status, double wall) {
    const Totals now = current();
    // What left through open faces (0 from a solver that does not report it, v1.0).
    const auto entries = audit(
        initial_, now, sum({step_.fdm_outflow(), step_.mpm_outflow(), step_.dormant_outflow()}));
    gauges_.flush();
    summary_.set_detail("gauges", gauges_.listing());
    summary_.set_status(status);
    summary_.set_progress(report_.steps, report_.time, scene_.time.end, wall);
    summary_.set_conservation(entries);
    report_.mass_error = entries[0].relative_error(0);
    report_.energy_error = entries[4].relative_error(0);
    summary_.set_detail("zones", {{"fdm_owned", totals_json(step_.fdm_totals())},
                                  {"mpm", totals_json(step_.mpm_totals())},
                                  {"parcels", totals_json(step_.parcel_totals())},
                                  {"fdm_outflow", totals_json(step_.fdm_outflow())},
                                  {"mpm_outflow", totals_json(step_.mpm_outflow())},
                                  {"dormant_zone_outflow", totals_json(step_.dormant_outflow())}});
    const auto& features = step_.features();
    summary_.set_detail("protocol", {{"fdm_face_crossing", features.fdm_face_crossing},
                                     {"fdm_outflow", features.fdm_outflow},
                                     {"mpm_outflow", features.mpm_outflow}});
    nlohmann::json activation = watch_.summary();
    if (!audit_switch_.is_null()) activation["audit_switch"] = audit_switch_;
    summary_.set_detail("activation", activation);
    summary_.set_detail("crossing", {{"injected_particles", injected_},
                                     {"removed_particles", removed_},
                                     {"injected_mass_kg", injected_mass_},
                                     {"deposited_mass_kg", deposited_mass_},
                                     {"max_face_cell_drain", step_.max_face_drain_share()},
                                     {"discarded_at_start", discarded_}});
    const double overhead =
        step_seconds_ > 0 ? 1.0 - report_.max_advance_seconds / step_seconds_ : 0.0;
    summary_.set_detail("timing", {{"step_seconds", step_seconds_},
                                   {"fdm_advance_seconds", report_.fdm_advance_seconds},
                                   {"mpm_advance_seconds", report_.mpm_advance_seconds},
                                   {"slower_advance_seconds", report_.max_advance_seconds},
                                   {"coupling_overhead_share", overhead}});
    summary_.set_detail("checkpoints", checkpoints_.summary());
    summary_.set_detail("steps_limited_by", {{"fdm", report_.steps_limited_by_fdm},
                                             {"mpm", report_.steps_limited_by_mpm},
                                             {"strip", report_.steps_limited_by_strip}});
    summary_.write(options_.out_dir / "summary.json");
  }

 private:
  /// A new run: the step-0 exchange (audit), the zone's activation if due, output 0.
  RunPosition begin() {
    exchange({.advance = false, .audit = true});
    initial_ = current();
    if (watch_.due()) activate(0, 0);
    write_output(0);
    return {.time = 0, .step = 0, .outputs = 1};
  }

  /// A restarted run: the coupler's state from `from`, checked, then each solver's
  /// Restore, gauges.csv as the checkpoint had it, and the output's exchange again, which
  /// brings back the strip cells, face mass, proposals and audit totals of t^n without
  /// changing either solver. Nothing in the folder changes before the checks pass.
  RunPosition resume(const CouplerCheckpoint& from) {
    from.read_state([&](const RestartReader& in) {
      restore(in);
      if (!from.fdm)
        in.refuse(
            "names no FDM checkpoint (attribute fdm_path): a CFDMP run's FDM zone holds state "
            "throughout");
      if (from.mpm.has_value() == watch_.dormant())
        in.refuse(std::string(watch_.dormant() ? "names an MPM checkpoint for a sleeping zone"
                                               : "names no MPM checkpoint for an awake zone") +
                  " (attribute mpm_path, group /activation)");
    });
    restore_solvers(hub_, from, options_.handoff_timeout);
    gauges_.resume_files();
    report_.steps = from.step;
    report_.time = from.time;
    hub_.set_clock(static_cast<std::uint64_t>(from.step), from.time);
    exchange({.advance = false, .time = from.time, .audit = true});
    checkpoints_.restarted(from);
    Logger("coupler").info("restarted from ", from.file.string(), ": step ", from.step,
                           ", t = ", from.time, " s, ", from.outputs, " outputs written");
    return from.position();
  }

  /// Each awake solver's Checkpoint, then the coupler's file (take_checkpoint).
  void checkpoint(const RunPosition& at, double wall) {
    if (watch_.dormant()) keep_mpm_alive();  // it takes no Checkpoint, so no message meanwhile
    checkpoints_.taken(take_checkpoint(
        hub_, at, wall, options_.out_dir, peers(), options_.handoff_timeout, scene_text_,
        grid_dimension(scene_), [&](RestartWriter& out) { save(out); }));
  }

  void save(RestartWriter& out) const {
    save_totals(out, "loop", "initial", initial_);
    save_totals(out, "loop", "switch", switch_);
    out.text("loop", "audit_switch", audit_switch_.dump());
    const std::pair<const char*, double> numbers[] = {
        {"injected_particles", static_cast<double>(injected_)},
        {"removed_particles", static_cast<double>(removed_)},
        {"discarded_particles", static_cast<double>(discarded_)},
        {"injected_mass", injected_mass_},
        {"deposited_mass", deposited_mass_},
        {"steps_limited_by_fdm", static_cast<double>(report_.steps_limited_by_fdm)},
        {"steps_limited_by_mpm", static_cast<double>(report_.steps_limited_by_mpm)},
        {"steps_limited_by_strip", static_cast<double>(report_.steps_limited_by_strip)},
        {"step_seconds", step_seconds_},
        {"fdm_advance_seconds", report_.fdm_advance_seconds},
        {"mpm_advance_seconds", report_.mpm_advance_seconds},
        {"slower_advance_seconds", report_.max_advance_seconds},
        {"mpm_slower", mpm_slower_ ? 1.0 : 0.0}};
    for (const auto& [name, value] : numbers) out.number("loop", name, value);
    step_.save(out);
    watch_.save(out);
    gauges_.save(out);
  }

  void restore(const RestartReader& in) {
    const auto count = [&](const char* name) {
      return static_cast<std::uint64_t>(in.number("loop", name));
    };
    initial_ = restored_totals(in, "loop", "initial");
    switch_ = restored_totals(in, "loop", "switch");
    audit_switch_ = in.json("loop", "audit_switch");
    injected_ = count("injected_particles");
    removed_ = count("removed_particles");
    discarded_ = count("discarded_particles");
    injected_mass_ = in.number("loop", "injected_mass");
    deposited_mass_ = in.number("loop", "deposited_mass");
    report_.steps_limited_by_fdm = static_cast<std::int64_t>(count("steps_limited_by_fdm"));
    report_.steps_limited_by_mpm = static_cast<std::int64_t>(count("steps_limited_by_mpm"));
    report_.steps_limited_by_strip = static_cast<std::int64_t>(count("steps_limited_by_strip"));
    step_seconds_ = in.number("loop", "step_seconds");
    report_.fdm_advance_seconds = in.number("loop", "fdm_advance_seconds");
    report_.mpm_advance_seconds = in.number("loop", "mpm_advance_seconds");
    report_.max_advance_seconds = in.number("loop", "slower_advance_seconds");
    mpm_slower_ = in.number("loop", "mpm_slower") != 0;
    step_.restore(in);
    watch_.restore(in);
    gauges_.restore(in);
  }

  void count_limit(std::string_view by) {
    auto& count = by == "strip" ? report_.steps_limited_by_strip
                  : by == "mpm" ? report_.steps_limited_by_mpm
                                : report_.steps_limited_by_fdm;
    ++count;
  }

  [[nodiscard]] Totals current() const {
    Totals now = sum({step_.fdm_totals(), step_.mpm_totals(), step_.parcel_totals()});
    now.mass -= switch_.mass;
    now.energy -= switch_.energy;
    for (int a = 0; a < 3; ++a) now.momentum[a] -= switch_.momentum[a];
    return now;
  }

  /// The solvers that get messages: the FDM alone while the MPM zone sleeps.
  [[nodiscard]] const std::vector<std::string>& peers() const {
    return watch_.dormant() ? kFdmOnly : kPeers;
  }

  /// One Exchange per awake solver, sent together; returns the two advance wall times.
  std::pair<double, double> exchange(StepPlan plan) {
    plan.mpm = !watch_.dormant();
    clear_for_reuse(fdm_request_);
    clear_for_reuse(mpm_request_);
    step_.build(plan, fdm_request_, mpm_request_);
    gauges_.add(plan.advance, plan.advance ? plan.time + plan.dt : plan.time,
                plan.mpm ? GaugeSamplers::owners : GaugeSamplers::fdm_only_mpm_asleep, fdm_request_,
                mpm_request_);
    // The solver that was slower last step gets its request first: over ipc/tcp the one
    // woken second can wait ~2 ms for a core behind the first (docs/coupler.md, overhead).
    const bool mpm_first = plan.mpm && mpm_slower_;
    if (mpm_first) hub_.send_keeping_header("mpm", mpm_request_);
    hub_.send_keeping_header("fdm", fdm_request_);
    if (plan.mpm && !mpm_first) hub_.send_keeping_header("mpm", mpm_request_);
    auto replies = hub_.gather(peers());
    if (!plan.mpm) replies.emplace_back();
    step_.read(plan, replies[0], replies[1]);
    gauges_.read(replies[0], replies[1]);
    if (!plan.mpm) {
      watch_.observe(step_.strip_pressure(), plan.advance ? plan.time + plan.dt : plan.time);
      keep_mpm_alive();
    }
    const auto& traffic = step_.traffic();
    injected_ += traffic.injected;
    removed_ += traffic.removed;
    injected_mass_ += traffic.injected_mass;
    deposited_mass_ += traffic.deposited_mass;
    discarded_ += traffic.discarded;
    const double fdm_seconds = advance_seconds(replies[0]);
    const double mpm_seconds = advance_seconds(replies[1]);
    if (plan.advance) mpm_slower_ = mpm_seconds > fdm_seconds;
    return {fdm_seconds, mpm_seconds};
  }

  /// A sleeping MPM gets no request; a Ping every options_.keep_alive restarts its
  /// idle wait (proto §1), so that a long quiet phase does not end it.
  void keep_mpm_alive() {
    if (Clock::now() - mpm_contact_ < options_.keep_alive) return;
    cosim::Message ping;
    ping.header.mutable_ping();
    hub_.send("mpm", std::move(ping));
    const auto pong = hub_.receive_from("mpm");
    if (!pong.header.has_pong())
      throw Error("solver 'mpm' answered Ping with '" + std::string(cosim::body_name(pong.header)) +
                  "'");
    mpm_contact_ = Clock::now();
  }

  /// Wakes the MPM zone at t (activation.hpp): an audit export of the FDM alone,
  /// Activate, then the step-0 exchange (discard outside the zone, export, propose
  /// dt) with both solvers.
  void activate(double t, std::int64_t n) {
    hub_.set_clock(static_cast<std::uint64_t>(n), t);
    exchange({.advance = false, .time = t, .audit = true});  // the FDM's zone cells at t
    const Totals cells = step_.mpm_totals();
    cosim::Message message;
    message.header.mutable_activate()->set_reason(
        "strip pressure passed zones.mpm.activation_pressure");
    hub_.send("mpm", std::move(message));
    hub_.gather(kMpmOnly);
    watch_.activated(t, n);
    exchange({.advance = false, .time = t, .audit = true});
    const Totals& particles = step_.mpm_totals();
    // The zone's content changes hands: the FDM's cells there give way to the MPM's
    // particles (the scene's initial state). The difference is what the FDM carried
    // across the face while the zone slept; it is reported here and kept out of the
    // audit's error, which stays continuous across the switch (activation.hpp).
    switch_.mass = particles.mass - cells.mass;
    switch_.energy = particles.energy - cells.energy;
    for (int a = 0; a < 3; ++a) switch_.momentum[a] = particles.momentum[a] - cells.momentum[a];
    audit_switch_ = {{"fdm_cells", totals_json(cells)},
                     {"particles", totals_json(particles)},
                     {"relative_mass_change", switch_.mass / initial_.mass},
                     {"relative_energy_change", switch_.energy / initial_.energy}};
    Logger("coupler").info(watch_.activation_text(), "; MPM zone mass ", particles.mass,
                           " kg replaces the FDM's ", cells.mass, " kg there (",
                           switch_.mass / initial_.mass, " of the total)");
  }

  void write_output(int index) {
    for (const auto& peer : peers()) {
      cosim::Message message;
      auto& body = *message.header.mutable_write_output();
      body.set_basename(peer + "_" + std::to_string(index));
      hub_.send(peer, std::move(message));
    }
    hub_.gather(peers());
  }

  const config::Scene& scene_;
  const std::string& scene_text_;
  CfdmpStep<Dim> step_;
  cosim::Message fdm_request_, mpm_request_;  ///< kept: a step reuses their memory
  ActivationWatch watch_;
  nlohmann::json audit_switch_;  ///< the zone's totals either side of the activation
  Totals switch_;                ///< particles - FDM cells of the zone at the activation
  Clock::time_point mpm_contact_ = Clock::now();  ///< the last reply of a sleeping MPM
  CoupledGauges gauges_;
  cosim::Hub& hub_;
  io::RunSummary& summary_;
  const CoupledRunOptions& options_;
  Totals initial_;
  CoupledRunReport report_;
  double step_seconds_ = 0;
  CheckpointLog checkpoints_{options_.checkpoint_every, options_.checkpoint_keep,
                             options_.restart.has_value()};
  bool mpm_slower_ = false;  ///< the MPM's last Advance took longer than the FDM's
  std::uint64_t injected_ = 0, removed_ = 0, discarded_ = 0;
  double injected_mass_ = 0, deposited_mass_ = 0;
};

template <int Dim>
CoupledRunReport run_loop(const config::Scene& scene, const std::string& scene_text,
                          const ZoneLayout& layout, const SolverFeatures& features, cosim::Hub& hub,
                          io::RunSummary& summary, const CoupledRunOptions& options) {
  Loop<Dim> loop(scene, scene_text, layout, features, hub, summary, options);
  const auto record_failure = [&loop] {
    if (!loop.summary_ready()) return;
    try {
      loop.record_summary("failed", 0);
    } catch (const std::exception&) {
      // The run's own error is the one to report; run_session writes the summary's status.
    }
  };
  try {
    return loop.run();
  } catch (const Error& error) {
    record_failure();
    // An FDM cell beside the face that the deposits were emptying is the cause behind
    // the FDM's stop (the coupler's own strip checks add it where they throw).
    const std::string cause = loop.face_drain_text();
    if (cause.empty() || !hub.reported_fatal_error("fdm")) throw;
    throw Error(with_cause(error.what(), cause));
  } catch (...) {
    record_failure();
    throw;
  }
}

}  // namespace

CoupledRunReport run_cfdmp(const config::Scene& scene, const std::string& scene_text,
                           cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                           const CoupledRunOptions& options) {
  const Logger logger("coupler");
  const ZoneLayout layout = make_zone_layout(scene);
  const auto body = [&](const std::vector<v1::Hello>& hellos, io::RunSummary& summary,
                        std::set<std::string>&) {
    const SolverFeatures features{.fdm_face_crossing = offers(hellos[0], "face_crossing"),
                                  .fdm_outflow = offers(hellos[0], "boundary_outflow"),
                                  .mpm_outflow = offers(hellos[1], "boundary_outflow")};
    auto messages = setups(scene, scene_text, layout, features, options.out_dir);
    hub.send("fdm", std::move(messages[0]));
    hub.send("mpm", std::move(messages[1]));
    hub.gather(kPeers);
    logger.info("zones set up: face normal to axis ", layout.face_axis, " side ", layout.face_side,
                ", strip ", box_text(layout.strip_cells), ", ghost cells ",
                box_text(layout.ghost_cells));
    switch (layout.dimension) {
      case 1:
        return run_loop<1>(scene, scene_text, layout, features, hub, summary, options);
      case 2:
        return run_loop<2>(scene, scene_text, layout, features, hub, summary, options);
      default:
        return run_loop<3>(scene, scene_text, layout, features, hub, summary, options);
    }
  };
  const CoupledRunReport report = run_session(scene, hub, solvers, options, body);
  logger.info("done: ", report.steps, " steps to t = ", report.time, " s in ", report.wall_seconds,
              " s; mass error ", report.mass_error, ", energy error ", report.energy_error);
  return report;
}

}  // namespace mpfd::coupler
