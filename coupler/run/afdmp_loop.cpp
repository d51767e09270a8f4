#include "coupler/run/afdmp_loop.hpp"

#include <algorithm>
#include <iostream>
#include <string>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/core/progress.hpp"
#include "cosim/arrays.hpp"
#include "coupler/handoff/detonation_trigger.hpp"
#include "coupler/run/field_transfer.hpp"
#include "coupler/run/session.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

namespace region = afdmp_region;

double proposed_dt(const cosim::Message& reply, const std::string& peer) {
  for (const auto& result : reply.header.exchange_result().results())
    if (result.has_proposed()) return result.proposed().stable_dt();
  throw Error("solver '" + peer + "' answered without a ProposeDt result");
}

}  // namespace

AfdmpStart afdmp_start(const config::Scene& scene) {
  return scene.solver.afdmp.start == config::AfdmpStart::spherical ? AfdmpStart::spherical
                                                                   : AfdmpStart::mpm;
}

AfdmpLoop::AfdmpLoop(const config::Scene& scene, const std::string& scene_text,
                     const AfdmpLayout& layout, AuditOutflow outflow, bool material_import,
                     cosim::Hub& hub, io::RunSummary& summary, const CoupledRunOptions& options)
    : scene_(scene),
      scene_text_(scene_text),
      layout_(layout),
      outflow_(outflow),
      start_(afdmp_start(scene)),
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

CoupledRunReport AfdmpLoop::run() {
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
    const auto [dt, output_now] = step_to_output(t, dt_, next_output);
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

/// A new run: phase 1 (or the 1D stage) set up, the audit's start, output 0.
RunPosition AfdmpLoop::begin() {
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

/// One step of the current phase from t to t_next.
void AfdmpLoop::step(double t, double t_next, std::int64_t n) {
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
void AfdmpLoop::step_mpm_detonation(bool advance, double dt, double t) {
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
void AfdmpLoop::step_solver(const std::string& peer, double dt, double t, GaugeSamplers samplers) {
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

BurnObservation AfdmpLoop::burn_observation(const cosim::Message& reply,
                                            const char* region_name) const {
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

cosim::Message AfdmpLoop::send_and_receive(const std::string& peer, cosim::Message& request) {
  hub_.send_keeping_header(peer, request);
  cosim::Message reply = hub_.receive_from(peer);
  contact_[peer] = Clock::now();
  return reply;
}

/// A transition due now: hand over, retire the solver without a further role.
void AfdmpLoop::handle(const std::optional<Transition>& transition, double t, std::int64_t n) {
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
void AfdmpLoop::discard_mpm_fluid() {
  cosim::Message request;
  add_remove(request, "to_fdm", region::kFsiParticles);
  exchange_of(request).mutable_operations(0)->mutable_remove()->set_discard(true);
  (void)send_and_receive("mpm", request);
}

void AfdmpLoop::retire(const std::string& peer, const std::string& reason) {
  cosim::Message message;
  message.header.mutable_shutdown()->set_reason(reason);
  hub_.send(peer, std::move(message));
  (void)hub_.receive_from(peer);
  retired_.insert(peer);
}

/// Pings every solver still needed, other than the active one, whose last answer is
/// older than `age`.
void AfdmpLoop::ping_idle(std::chrono::milliseconds age) {
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

void AfdmpLoop::observe_stage() {
  observation_.spherical_burn_complete = stage_->burn_complete();
  observation_.front_radius = stage_->front_radius();
  dt_ = stage_->stable_dt();
}

void AfdmpLoop::sample_stage_gauges(double t) {
  if (!gauges_.due(t)) return;
  stage_pressure_.resize(scene_.gauges.size());
  stage_->gauge_pressures(stage_pressure_);
  gauges_.record_pressure(t, stage_pressure_);
}

/// The run-long audit's reading of `who` ("spherical", "fdm" or "mpm") now.
void AfdmpLoop::audit_holder(const std::string& who) {
  if (who == "spherical") {
    audit_.set_stage(stage_and_fill(scene_, *stage_));
    return;
  }
  // Chunked as the handoffs' fields: a whole grid in one reply could pass max_message_bytes.
  const bool fdm = who == "fdm";
  const auto names = fdm ? fdm_audit_fields(outflow_.fdm) : mpm_audit_fields(outflow_.mpm);
  const cosim::Message fields =
      export_fields(hub_, who, "audit", names, options_.max_chunk_bytes, options_.handoff_timeout);
  contact_[who] = Clock::now();
  if (fdm)
    audit_.set_fdm(fdm_audit_reading(fields, static_cast<std::size_t>(grid_.cell_count()),
                                     grid_.cell_volume(), outflow_.fdm));
  else
    audit_.set_mpm(mpm_audit_reading(fields, outflow_.mpm));
}

}  // namespace mpfd::coupler
