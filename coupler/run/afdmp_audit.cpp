#include "coupler/run/afdmp_audit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/placeholder.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"
#include "coupler/run/afdmp_fields.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

namespace region = afdmp_region;

/// The v1.1 outflow_* of `group` (one row each) that solver `peer` exported.
Conserved outflow_of(const cosim::Message& reply, const char* peer, const char* group) {
  Conserved out;
  // Copied while the view lives: a view of a misaligned frame holds its own copy.
  const auto read = [&](const char* name, std::span<double> into) {
    const auto view = cosim::view_array<double>(reply, group, name);
    check_value_count(reply, peer, group, name, view.values().size(), into.size());
    std::copy_n(view.values().begin(), into.size(), into.begin());
  };
  read("outflow_mass", {&out.mass, 1});
  read("outflow_energy", {&out.energy, 1});
  read("outflow_momentum", out.momentum);
  return out;
}

Conserved scaled(const Conserved& c, double factor) {
  Conserved out = c;
  out.mass *= factor;
  out.energy *= factor;
  for (double& p : out.momentum) p *= factor;
  return out;
}

}  // namespace

std::vector<std::string> fdm_audit_fields(bool outflow) {
  return outflow ? field_names(region::kAuditCells, {"rho", "momentum", "E", "outflow_mass",
                                                     "outflow_momentum", "outflow_energy"})
                 : field_names(region::kAuditCells, {"rho", "momentum", "E"});
}

std::vector<std::string> mpm_audit_fields(bool outflow) {
  return outflow ? field_names(region::kAuditParticles,
                               {"mass", "velocity", "internal_energy", "outflow_mass",
                                "outflow_momentum", "outflow_energy"})
                 : field_names(region::kAuditParticles, {"mass", "velocity", "internal_energy"});
}

AuditReading fdm_audit_reading(const cosim::Message& fields, std::size_t cells, double cell_volume,
                               bool outflow) {
  const auto rho = cosim::view_array<double>(fields, region::kAuditCells, "rho");
  const auto momentum = cosim::view_array<double>(fields, region::kAuditCells, "momentum");
  const auto energy = cosim::view_array<double>(fields, region::kAuditCells, "E");
  check_value_count(fields, "fdm", region::kAuditCells, "rho", rho.values().size(), cells);
  check_value_count(fields, "fdm", region::kAuditCells, "momentum", momentum.values().size(),
                    3 * cells);
  check_value_count(fields, "fdm", region::kAuditCells, "E", energy.values().size(), cells);
  AuditReading reading;
  reading.held = wire_cell_conserved(rho.values(), momentum.values(), energy.values(), cell_volume);
  if (outflow) reading.outflow = outflow_of(fields, "fdm", region::kAuditCells);
  return reading;
}

AuditReading mpm_audit_reading(const cosim::Message& fields, bool outflow) {
  const auto mass = cosim::view_array<double>(fields, region::kAuditParticles, "mass");
  const auto velocity = cosim::view_array<double>(fields, region::kAuditParticles, "velocity");
  const auto energy = cosim::view_array<double>(fields, region::kAuditParticles, "internal_energy");
  const std::size_t n = mass.values().size();
  check_value_count(fields, "mpm", region::kAuditParticles, "velocity", velocity.values().size(),
                    3 * n);
  check_value_count(fields, "mpm", region::kAuditParticles, "internal_energy",
                    energy.values().size(), n);
  AuditReading reading;
  Conserved& c = reading.held;
  for (std::size_t p = 0; p < n; ++p) {
    const double m = mass.values()[p];
    double v2 = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      const double v = velocity.values()[3 * p + a];
      c.momentum[a] += m * v;
      v2 += v * v;
    }
    c.mass += m;
    c.energy += energy.values()[p] + 0.5 * m * v2;
  }
  if (outflow) reading.outflow = outflow_of(fields, "mpm", region::kAuditParticles);
  return reading;
}

Conserved stage_and_fill(const config::Scene& scene, const SphericalStage& stage) {
  const auto grid =
      grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper, scene.domain.cells);
  remap::RadialShells shells = stage.shells();
  const auto inside = remap::totals_inside_grid(grid, stage.centre(), shells.view());
  // The volume the shells cover inside the grid: the same overlaps at density 1.
  std::fill(shells.density.begin(), shells.density.end(), 1.0);
  std::fill(shells.velocity.begin(), shells.velocity.end(), 0.0);
  std::fill(shells.internal_energy.begin(), shells.internal_energy.end(), 0.0);
  const double covered = remap::totals_inside_grid(grid, stage.centre(), shells.view()).mass;
  const double rest =
      std::max(0.0, grid.cell_volume() * static_cast<double>(grid.cell_count()) - covered);
  const auto ambient = handoff::ambient_state(scene);
  double v2 = 0.0;
  for (const double v : ambient.velocity) v2 += v * v;
  Conserved c;
  c.mass = inside.mass + rest * ambient.density;
  c.energy = inside.energy + rest * ambient.density * (ambient.specific_internal_energy + 0.5 * v2);
  for (int a = 0; a < 3; ++a) c.momentum[a] = rest * ambient.density * ambient.velocity[a];
  return c;
}

void save_conserved(RestartWriter& out, const std::string& owner, const std::string& name,
                    const Conserved& amount) {
  out.array(owner, name,
            std::array<double, 6>{amount.mass, amount.momentum[0], amount.momentum[1],
                                  amount.momentum[2], amount.energy, amount.momentum_scale});
}

Conserved restored_conserved(const RestartReader& in, const std::string& owner,
                             const std::string& name) {
  const auto v = in.array(owner, name, 6);
  return {.mass = v[0], .momentum = {v[1], v[2], v[3]}, .energy = v[4], .momentum_scale = v[5]};
}

template <class Audit>
auto RunLongAudit::named_terms(Audit& audit) {
  return std::array{std::pair{"initial", &audit.initial_},
                    std::pair{"fdm", &audit.fdm_},
                    std::pair{"mpm", &audit.mpm_},
                    std::pair{"stage", &audit.stage_},
                    std::pair{"placeholder", &audit.placeholder_},
                    std::pair{"fdm_outflow", &audit.fdm_outflow_},
                    std::pair{"mpm_outflow", &audit.mpm_outflow_}};
}

void RunLongAudit::save(RestartWriter& out) const {
  for (const auto& [name, term] : named_terms(*this)) save_conserved(out, "audit", name, *term);
  nlohmann::json names = nlohmann::json::array();
  for (const auto& [name, amount] : dropped_) {
    names.push_back(name);
    save_conserved(out, "audit", "dropped_" + name, amount);
  }
  out.text("audit", "dropped", names.dump());
}

void RunLongAudit::restore(const RestartReader& in) {
  RunLongAudit back;
  for (const auto& [name, term] : named_terms(back)) *term = restored_conserved(in, "audit", name);
  for (const auto& name : in.json("audit", "dropped"))
    back.dropped_[name] = restored_conserved(in, "audit", "dropped_" + name.get<std::string>());
  *this = std::move(back);
}

void RunLongAudit::start() {
  initial_ = current();
}

void RunLongAudit::set_fdm(const AuditReading& reading) {
  fdm_ = reading.held;
  fdm_outflow_ = reading.outflow;
}

void RunLongAudit::set_mpm(const AuditReading& reading) {
  mpm_ = reading.held;
  mpm_outflow_ = reading.outflow;
}

void RunLongAudit::set_stage(const Conserved& stage_and_fill) {
  stage_ = stage_and_fill;
}

void RunLongAudit::set_placeholder(const Conserved& placeholder) {
  placeholder_ = placeholder;
}

void RunLongAudit::clear_fdm() {
  fdm_ = {};
  placeholder_ = {};
}

void RunLongAudit::clear_mpm() {
  mpm_ = {};
}

void RunLongAudit::clear_stage() {
  stage_ = {};
}

void RunLongAudit::drop(const std::string& name, const Conserved& amount) {
  dropped_[name] = sum(dropped_[name], amount);
}

void RunLongAudit::book_remap_momentum(const std::array<double, 3>& momentum) {
  // Booked like a wall's impulse in the solvers' ledgers: outflow minus impulse given.
  Conserved term;
  for (int a = 0; a < 3; ++a) term.momentum[a] = -momentum[a];
  drop("spherical_remap_momentum", term);
}

Conserved RunLongAudit::current() const {
  return sum(sum(stage_, difference(fdm_, placeholder_)), mpm_);
}

Conserved RunLongAudit::outflow() const {
  Conserved out = sum(fdm_outflow_, mpm_outflow_);
  for (const auto& [name, amount] : dropped_) out = sum(out, amount);
  return out;
}

std::vector<io::ConservationEntry> RunLongAudit::entries() const {
  const Conserved now = current();
  const Conserved out = outflow();
  std::vector<io::ConservationEntry> entries;
  entries.push_back({"mass", "kg", initial_.mass, now.mass, out.mass});
  const char* names[3] = {"momentum_x", "momentum_y", "momentum_z"};
  for (int a = 0; a < 3; ++a)
    entries.push_back({names[a], "kg m/s", initial_.momentum[a], now.momentum[a], out.momentum[a]});
  entries.push_back({"energy", "J", initial_.energy, now.energy, out.energy});
  return entries;
}

nlohmann::json RunLongAudit::summary() const {
  const Conserved now = current();
  const Conserved out = outflow();
  // As the standalone solvers: momentum relative to sqrt(2 M E) (a blast starts at rest).
  const double scale = std::sqrt(2.0 * std::abs(initial_.mass * initial_.energy));
  nlohmann::json momentum_error = nlohmann::json::array();
  for (int a = 0; a < 3; ++a) {
    const double drift = now.momentum[a] + out.momentum[a] - initial_.momentum[a];
    momentum_error.push_back(scale > 0 ? drift / scale : drift);
  }
  nlohmann::json dropped = nlohmann::json::object();
  for (const auto& [name, amount] : dropped_) dropped[name] = amount.summary();
  return {{"initial", initial_.summary()},
          {"held",
           {{"stage_and_fill", stage_.summary()},
            {"fdm_cells", fdm_.summary()},
            {"fdm_placeholder", scaled(placeholder_, -1.0).summary()},
            {"mpm_particles", mpm_.summary()}}},
          {"outflow", {{"fdm", fdm_outflow_.summary()}, {"mpm", mpm_outflow_.summary()}}},
          {"dropped", dropped},
          {"momentum_scale", scale},
          {"momentum_error_relative_to_scale", momentum_error}};
}

}  // namespace mpfd::coupler
