#include "coupler/run/cfdmp_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "coupler/handshake/particle_removal.hpp"
#include "coupler/run/strip_step_limit.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

constexpr const char* kFdm = "fdm";
constexpr const char* kMpm = "mpm";
/// Minimum injected particle mass / m_e of T (4-15). Sod MPM-part error
/// (docs/coupler.md): 1/2 2.31e-2, 1/4 1.79e-2, 1/8 1.61e-2, 1/16 1.49e-2,
/// 1/32 1.52e-2 with the FDM's face crossing (v1.1); 1/8 gave 1.54e-2 under v1.0.
constexpr double kMinParticleShare = 1.0 / 16;
/// Inflow denser than this many times the zone's seeding makes no more particles
/// per volume (particle_injection.hpp). 4 leaves the Sod case as it was (inflow
/// 3.4x the seeding's density).
constexpr double kMaxDensification = 4;

/// The v1.1 outflow_* totals of `region` (one row each).
Totals outflow_totals(const cosim::Message& reply, std::string_view peer, std::string_view region) {
  Totals totals;
  // Copied while the view lives: a view of a misaligned frame holds its own copy.
  const auto read = [&](std::string_view name, std::span<double> into) {
    const auto view = cosim::view_array<double>(reply, region, name);
    check_value_count(reply, peer, region, name, view.values().size(), into.size());
    std::copy_n(view.values().begin(), into.size(), into.begin());
  };
  read("outflow_mass", {&totals.mass, 1});
  read("outflow_energy", {&totals.energy, 1});
  read("outflow_momentum", totals.momentum);
  return totals;
}

}  // namespace

template <int Dim>
CfdmpStep<Dim>::CfdmpStep(const config::Scene& scene, const ZoneLayout& layout,
                          SolverFeatures features)
    : scene_(scene), layout_(layout), features_(features), injected_material_(scene) {
  if (layout.dimension != Dim)
    throw Error("CfdmpStep<" + std::to_string(Dim) + "> built for a " +
                std::to_string(layout.dimension) + "D layout");
  const auto& d = scene.domain;
  double volume = 1;
  for (int a = 0; a < 3; ++a) {
    const double h = (d.upper[a] - d.lower[a]) / d.cells[a];
    volume *= h;
    inactive_centre_[a] = d.lower[a] + 0.5 * h;
  }
  for (int k = 0; k < Dim; ++k) {
    const int a = layout.active[k];
    geometry_.origin(k) = d.lower[a];
    geometry_.spacing(k) = (d.upper[a] - d.lower[a]) / d.cells[a];
  }
  geometry_.cell_volume = volume;
  int face_axis = 0;
  for (int k = 0; k < Dim; ++k)
    if (layout.active[k] == layout.face_axis) face_axis = k;
  strip_layout_ = handshake::make_strip_layout(to_kernel_box<Dim>(layout.strip_cells, layout),
                                               {face_axis, layout.face_side});
  stencil_ = handshake::make_interface_stencil(strip_layout_,
                                               to_kernel_box<Dim>(layout.interface_nodes, layout));
  outer_nodes_ = mpm_reaches_outer_nodes(scene);
  if (outer_nodes_)
    outer_stencil_ = handshake::make_outer_node_stencil(
        strip_layout_, to_kernel_box<Dim>(layout.outer_nodes, layout));
  ghost_cells_ = to_kernel_box<Dim>(layout.ghost_cells, layout);
  ghost_nodes_ = to_kernel_box<Dim>(layout.ghost_nodes, layout);
  face_cells_ = to_kernel_box<Dim>(layout.face_cells, layout);
  deposit_box_ = to_kernel_box<Dim>(layout.deposit_cells, layout);
  corners_ = handshake::corner_nodes(ghost_cells_, ghost_nodes_);
  handshake::Index<Dim> domain_cells{};
  for (int k = 0; k < Dim; ++k) domain_cells[k] = d.cells[layout.active[k]];
  corner_support_ = handshake::corner_support<Dim>(ghost_cells_, domain_cells);
  const std::size_t faces = strip_layout_.face_cells();
  outer_in_deposit_.resize(faces);
  for (std::size_t t = 0; t < faces; ++t) {
    auto outer = strip_layout_.inner_cell[t];
    outer[face_axis] -= layout.face_side;
    outer_in_deposit_[t] = deposit_box_.flat(outer);
  }
  const auto face_box = to_kernel_box<Dim>(layout.coupling_face, layout);
  face_in_export_.resize(faces);
  for (std::size_t t = 0; t < faces; ++t) {
    auto cell = strip_layout_.inner_cell[t];  // the cell above the face
    if (layout.face_side < 0) cell[face_axis] += 1;
    face_in_export_[t] = face_box.flat(cell);
  }
  crossed_mass_.assign(faces, 0);
  face_mass_.assign(faces, 0);
  face_solid_volume_.assign(faces, 0);
  push_volume_.assign(faces, 0);
  solid_ = material_strength_flags(scene);
  any_solid_ = config::has_structure(scene);
  crossed_energy_.assign(faces, 0);
  crossed_momentum_.assign(faces, Vec::Zero());
  parcels_ = handshake::Parcels<Dim>(faces);
  returned_mass_.assign(faces, 0);
  returned_energy_.assign(faces, 0);
  returned_momentum_.assign(faces, Vec::Zero());
}

template <int Dim>
Totals CfdmpStep<Dim>::parcel_totals() const {
  Totals totals;
  for (std::size_t t = 0; t < parcels_.size(); ++t) {
    totals.mass += parcels_.mass[t];
    totals.energy += parcels_.energy[t];
    for (int k = 0; k < Dim; ++k) totals.momentum[layout_.active[k]] += parcels_.momentum[t](k);
  }
  return totals;
}

template <int Dim>
void CfdmpStep<Dim>::build(const StepPlan& plan, cosim::Message& fdm, cosim::Message& mpm) {
  fdm_ops_.clear();
  mpm_ops_.clear();
  traffic_ = {};
  std::fill(returned_mass_.begin(), returned_mass_.end(), 0.0);
  std::fill(returned_energy_.begin(), returned_energy_.end(), 0.0);
  std::fill(returned_momentum_.begin(), returned_momentum_.end(), Vec::Zero());
  const handshake::Amounts<Dim> returned{returned_mass_, returned_momentum_, returned_energy_};
  if (flux_due_) named_drain([&] { add_face_fluxes(returned); });
  add_deposit(fdm);
  if (plan.advance) {
    if (plan.mpm) add_ghost_cells(fdm, plan);
    add_advance(fdm, plan.dt, plan.time);
    fdm_ops_.push_back(Op::advance);
  }
  if (plan.advance && plan.mpm) {
    add_injection(mpm);
    add_interface_nodes(mpm);
    add_advance(mpm, plan.dt, plan.time);
    mpm_ops_.push_back(Op::advance);
  }
  add_export(fdm, "strip_cells", {"rho", "momentum", "E", "pressure"});
  fdm_ops_.push_back(Op::export_strip);
  if (outer_nodes_) {
    add_export(fdm, "beyond_cells", {"rho", "momentum", "E", "pressure"});
    fdm_ops_.push_back(Op::export_beyond);
  }
  if (plan.advance && features_.fdm_face_crossing) {
    add_export(fdm, "coupling_face", {"crossed_mass", "crossed_momentum", "crossed_energy"});
    fdm_ops_.push_back(Op::export_face);
  }
  if (plan.audit) {
    add_audit_export(fdm, "fdm_owned");
    fdm_ops_.push_back(Op::export_owned);
  }
  if (!plan.mpm && plan.audit) {
    add_audit_export(fdm, "dormant_zone");
    fdm_ops_.push_back(Op::export_dormant);
  }
  add_propose_dt(fdm);
  fdm_ops_.push_back(Op::propose);
  if (!plan.mpm) return;

  if (!have_ghost_source_) {
    // Step 0: the MPM filled the scene's bodies over the whole domain; what lies
    // outside its zone is the FDM's material, so it is dropped, not deposited.
    add_remove(mpm, "outside", "mpm_zone");
    mpm_ops_.push_back(Op::discard);
  }
  // Before the removal: the particles it takes lie outside cell k-w+1 anyway, and its
  // uint32 arrays would leave these frames misaligned (a copy, so an allocation, per read);
  // in a scene with a solid this export's own material array does so (docs/coupler.md).
  // The quantities setups() declares (coupled_run.cpp); a recorded run replays these names.
  if (any_solid_)
    add_export(mpm, "face_particles", {"mass", "position", "volume", "material"});
  else
    add_export(mpm, "face_particles", {"mass", "position"});
  mpm_ops_.push_back(Op::export_face_particles);
  if (plan.advance) {
    add_remove(mpm, "crossed", "mpm_zone");
    mpm_ops_.push_back(Op::remove);
  }
  // After the removal: the MPM maps the next step for this export (map_next_step),
  // and a removal after it would drop that map. The removed particles go to the FDM
  // cells (4-19)...(4-21), so the ghost nodes are not to hold them. For w >= 2 (any w
  // with linear shapes) they lie beyond every ghost node's stencil anyway; at w = 1 a
  // uGIMP particle just past the face would have reached one.
  if (plan.advance || !have_ghost_source_) {
    add_export(mpm, "ghost_nodes", {"mass", "momentum", "internal_energy"});
    mpm_ops_.push_back(Op::export_ghost);
  }
  if (plan.audit) {
    if (features_.mpm_outflow)
      add_export(mpm, "mpm_zone",
                 {"mass", "velocity", "internal_energy", "outflow_mass", "outflow_momentum",
                  "outflow_energy"});
    else
      add_export(mpm, "mpm_zone", {"mass", "velocity", "internal_energy"});
    mpm_ops_.push_back(Op::export_particles);
  }
  add_propose_dt(mpm);
  mpm_ops_.push_back(Op::propose);
}

template <int Dim>
void CfdmpStep<Dim>::add_face_fluxes(const handshake::Amounts<Dim>& returned) {
  // Step 14 of the last step, from the strip_cells of its start: with the FDM's
  // own crossing (v1.1) the parcels gain exactly what the FDM lost; else T (4-10) ... (4-14).
  const handshake::CellStates<Dim> strip{strip_prev_.rho, strip_prev_.momentum, strip_prev_.energy};
  if (features_.fdm_face_crossing)
    handshake::accumulate_crossed_amounts<Dim>({crossed_mass_, crossed_momentum_, crossed_energy_},
                                               strip, strip_prev_.pressure, strip_layout_,
                                               geometry_, dt_last_, parcels_, returned);
  else
    handshake::accumulate_face_fluxes<Dim>(strip, strip_layout_, geometry_, dt_last_, parcels_,
                                           returned);
  flux_due_ = false;
}

template <int Dim>
void CfdmpStep<Dim>::add_audit_export(cosim::Message& fdm, const char* region) const {
  // The contents, and what left through the region's domain faces (v1.1) when offered.
  if (features_.fdm_outflow)
    add_export(fdm, region,
               {"rho", "momentum", "E", "outflow_mass", "outflow_momentum", "outflow_energy"});
  else
    add_export(fdm, region, {"rho", "momentum", "E"});
}

template <int Dim>
void CfdmpStep<Dim>::read_crossed(const cosim::Message& reply) {
  // v1.1 `coupling_face`: amounts toward +face_axis in box C order -> per face cell, into the zone.
  const std::size_t n = face_in_export_.size();
  auto& mass = scratch_.mass;
  auto& energy = scratch_.energy;
  auto& momentum = scratch_.momentum;
  read_doubles(reply, kFdm, "coupling_face", "crossed_mass", n, mass);
  read_doubles(reply, kFdm, "coupling_face", "crossed_energy", n, energy);
  read_wire_vectors<Dim>(reply, kFdm, "coupling_face", "crossed_momentum", n, layout_, momentum);
  for (std::size_t i = 0; i < n; ++i) {  // a peer's NaN would pass every m > 0 test below
    const bool finite = std::isfinite(mass[i]) && std::isfinite(energy[i]) &&
                        std::isfinite(momentum[i].squaredNorm());
    if (!finite)
      throw Error("solver 'fdm' exported a non-finite crossed amount at coupling_face entry " +
                  std::to_string(i) + ": mass " + shortest_text(mass[i]) + " kg, energy " +
                  shortest_text(energy[i]) + " J");
  }
  const double side = layout_.face_side;
  for (std::size_t t = 0; t < n; ++t) {
    const std::size_t e = face_in_export_[t];
    crossed_mass_[t] = side * mass[e];
    crossed_momentum_[t] = side * momentum[e];
    crossed_energy_[t] = side * energy[e];
  }
}

template <int Dim>
void CfdmpStep<Dim>::add_deposit(cosim::Message& fdm) {
  // T (4-19) ... (4-21): the particles removed in the last step and the returned parcels.
  const std::size_t n = deposit_box_.count();
  auto& rho = scratch_.rho;
  auto& energy = scratch_.energy;
  auto& momentum = scratch_.momentum;
  rho.assign(n, 0.0);
  energy.assign(n, 0.0);
  momentum.assign(n, Vec::Zero());
  const handshake::CellOutputs<Dim> add{rho, momentum, energy};
  const std::size_t removed = removed_mass_.size();
  if (removed > 0) {
    auto& cell = scratch_.index;
    auto& p = scratch_.velocity;  // the particles' momenta
    auto& e = scratch_.mass;      // and total energies
    cell.resize(removed);
    handshake::locate_deposit_cells<Dim>(removed_position_, deposit_box_, geometry_, cell);
    p.resize(removed);
    e.resize(removed);
    handshake::particle_amounts<Dim>(removed_mass_, removed_velocity_, removed_energy_, p, e);
    handshake::deposit<Dim>(removed_mass_, p, e, cell, geometry_.cell_volume, add);
    for (const double m : removed_mass_) traffic_.deposited_mass += m;
  }
  handshake::deposit<Dim>(returned_mass_, returned_momentum_, returned_energy_, outer_in_deposit_,
                          geometry_.cell_volume, add);
  for (const double m : returned_mass_) traffic_.deposited_mass += m;
  drain_.start_deposit();
  if (!strip_now_.rho.empty())  // the cells k-w as the FDM exported them after its last advance
    for (std::size_t t = 0; t < outer_in_deposit_.size(); ++t)
      drain_.observe(t, strip_now_.rho[strip_layout_.outer[t]], rho[outer_in_deposit_[t]],
                     returned_mass_[t], geometry_.cell_volume);
  removed_mass_.clear();
  removed_energy_.clear();
  removed_position_.clear();
  removed_velocity_.clear();
  if (traffic_.deposited_mass == 0.0) return;
  add_cell_apply(fdm, "deposit_cells", v1::ApplyRegion::MODE_ADD);
}

template <int Dim>
void CfdmpStep<Dim>::add_cell_apply(cosim::Message& fdm, const char* region,
                                    v1::ApplyRegion::Mode mode) {
  // The conserved densities in scratch_ (rho, momentum, energy), one entry per region cell.
  const std::size_t n = scratch_.rho.size();
  cosim::add_array(fdm, {region, "rho", {}, "kg/m^3"}, std::span<const double>(scratch_.rho));
  cosim::add_array(fdm, {region, "momentum", {n, 3}, "kg/(m^2*s)"},
                   to_wire_vectors<Dim>(scratch_.momentum, layout_, {0, 0, 0}, scratch_.wire));
  cosim::add_array(fdm, {region, "E", {}, "J/m^3"}, std::span<const double>(scratch_.energy));
  add_apply(fdm, region, mode);
  fdm_ops_.push_back(Op::apply);
}

template <int Dim>
void CfdmpStep<Dim>::add_ghost_cells(cosim::Message& fdm, const StepPlan& plan) {
  // T (4-1) ... (4-6) from the ghost_nodes of t^n.
  const std::size_t n = ghost_cells_.count();
  auto& rho = scratch_.rho;
  auto& energy = scratch_.energy;
  auto& momentum = scratch_.momentum;
  rho.resize(n);
  energy.resize(n);
  momentum.resize(n);
  const auto empty = handshake::fill_ghost_cells<Dim>(
      {ghost_node_mass_, ghost_node_momentum_, ghost_cell_energy_}, corners_, corner_support_,
      geometry_.cell_volume, {rho, momentum, energy});
  if (empty) throw Error(empty_ghost_cell_text(*empty, plan));
  add_cell_apply(fdm, "ghost_cells", v1::ApplyRegion::MODE_SET);
}

template <int Dim>
std::string CfdmpStep<Dim>::cell_text(const handshake::Index<Dim>& cell) const {
  std::array<std::int64_t, 3> index{};
  std::array<double, 3> centre = inactive_centre_;
  for (int k = 0; k < Dim; ++k) {
    const int a = layout_.active[k];
    index[a] = cell[k];
    centre[a] = geometry_.origin(k) + (static_cast<double>(cell[k]) + 0.5) * geometry_.spacing(k);
  }
  // Appended, not "(" + ...: GCC 12 warns (-Wrestrict, its bug 105329) on that once inlined.
  std::string text("(");
  for (int a = 0; a < 3; ++a) text.append(std::to_string(index[a])).append(a < 2 ? ", " : ") at (");
  for (int a = 0; a < 3; ++a) text.append(number_text(centre[a], 6)).append(a < 2 ? ", " : ") m");
  return text;
}

template <int Dim>
std::string CfdmpStep<Dim>::empty_ghost_cell_text(std::size_t c, const StepPlan& plan) const {
  char time[32];
  std::snprintf(time, sizeof time, "%g", plan.time);
  return "ghost cells: at t = " + std::string(time) + " s (step " + std::to_string(plan.step) +
         ") the FDM ghost cell " + cell_text(ghost_cells_.at(c)) +
         " gets no MPM nodal mass (T (4-1): its corner nodes hold none): the MPM zone has "
         "emptied next to the zone face, so there is no material to give the FDM there. An MPM "
         "zone must not empty: give its outer faces wall or symmetry boundaries, or move the zone "
         "face (zones.mpm) to where inflow keeps the zone filled";
}

template <int Dim>
std::string CfdmpStep<Dim>::face_drain_text() const {
  auto cell = strip_layout_.inner_cell[drain_.worst().face_cell];  // k-w+1; k-w is outside
  cell[strip_layout_.face.axis] -= strip_layout_.face.side;
  return drain_.cause_text(cell_text(cell));
}

template <int Dim>
void CfdmpStep<Dim>::add_injection(cosim::Message& mpm) {
  // T (4-15) ... (4-18): parcels heavy enough become particles in cell k-w+1.
  auto& count = scratch_.index;
  count.resize(parcels_.size());
  const std::size_t n = handshake::count_new_particles<Dim>(parcels_, rule_, count);
  if (n == 0) return;
  auto& position = scratch_.position;
  auto& velocity = scratch_.velocity;
  auto& mass = scratch_.mass;
  auto& volume = scratch_.volume;
  auto& energy = scratch_.energy;
  auto& face = scratch_.face;
  auto& ids = scratch_.ids;
  auto& material = scratch_.material;
  position.resize(n);
  velocity.resize(n);
  mass.resize(n);
  volume.resize(n);
  energy.resize(n);
  face.resize(n);
  handshake::create_particles<Dim>(parcels_, count, strip_layout_, geometry_,
                                   {position, velocity, mass, volume, energy, face});
  ids.resize(n);
  for (auto& id : ids) id = next_id_++;
  material.resize(n);
  for (std::size_t p = 0; p < n; ++p)
    material[p] = injected_material_.choose(mass[p] / volume[p], energy[p] / mass[p],
                                            strip_now_.pressure[strip_layout_.inner[face[p]]]);
  cosim::add_array(mpm, {"injected", "id", {}, "1"}, std::span<const std::uint64_t>(ids));
  cosim::add_array(mpm, {"injected", "position", {n, 3}, "m"},
                   to_wire_vectors<Dim>(position, layout_, inactive_centre_, scratch_.wire));
  cosim::add_array(mpm, {"injected", "velocity", {n, 3}, "m/s"},
                   to_wire_vectors<Dim>(velocity, layout_, {0, 0, 0}, scratch_.wire));
  cosim::add_array(mpm, {"injected", "mass", {}, "kg"}, std::span<const double>(mass));
  cosim::add_array(mpm, {"injected", "volume", {}, "m^3"}, std::span<const double>(volume));
  cosim::add_array(mpm, {"injected", "internal_energy", {}, "J"}, std::span<const double>(energy));
  cosim::add_array(mpm, {"injected", "material", {}, "1"},
                   std::span<const std::uint32_t>(material));
  add_inject(mpm, "injected");
  mpm_ops_.push_back(Op::inject);
  traffic_.injected = n;
  for (const double m : mass) traffic_.injected_mass += m;
}

template <int Dim>
void CfdmpStep<Dim>::add_interface_nodes(cosim::Message& mpm) {
  // Second terms of T (4-7) ... (4-9) from the strip_cells of t^n.
  const std::size_t n = stencil_.cells.size();
  auto& mass = scratch_.mass;
  auto& momentum = scratch_.momentum;
  auto& force = scratch_.force;
  mass.resize(n);
  momentum.resize(n);
  force.resize(n);
  std::span<const double> push_volume;  // T's V_c until the MPM has told its face mass
  if (have_face_mass_) {
    named_drain([&] {
      handshake::face_push_volume<Dim>(face_mass_, face_solid_volume_, strip_now_.rho,
                                       strip_layout_, geometry_.cell_volume, push_volume_);
    });
    push_volume = push_volume_;
  }
  handshake::interface_node_terms<Dim>({strip_now_.rho, strip_now_.momentum, strip_now_.energy},
                                       strip_now_.pressure, scene_.solver.mpm.reference_pressure,
                                       strip_layout_, stencil_, geometry_, {mass, momentum, force},
                                       push_volume);
  cosim::add_array(mpm, {"interface_nodes", "mass", {}, "kg"}, std::span<const double>(mass));
  cosim::add_array(mpm, {"interface_nodes", "momentum", {n, 3}, "kg*m/s"},
                   to_wire_vectors<Dim>(momentum, layout_, {0, 0, 0}, scratch_.wire));
  cosim::add_array(mpm, {"interface_nodes", "internal_force", {n, 3}, "N"},
                   to_wire_vectors<Dim>(force, layout_, {0, 0, 0}, scratch_.wire));
  add_apply(mpm, "interface_nodes", v1::ApplyRegion::MODE_ADD);
  mpm_ops_.push_back(Op::apply);
  if (!outer_nodes_) return;
  // uGIMP: the node layer outside the face, which the particles near the face reach.
  const std::size_t m = outer_stencil_.cells.size();
  mass.resize(m);
  momentum.resize(m);
  force.resize(m);
  handshake::outer_node_terms<Dim>(
      {strip_now_.rho, strip_now_.momentum, strip_now_.energy}, strip_now_.pressure,
      {beyond_.rho, beyond_.momentum, beyond_.energy}, beyond_.pressure,
      scene_.solver.mpm.reference_pressure, strip_layout_, outer_stencil_, geometry_,
      {mass, momentum, force});
  cosim::add_array(mpm, {"outer_nodes", "mass", {}, "kg"}, std::span<const double>(mass));
  cosim::add_array(mpm, {"outer_nodes", "momentum", {m, 3}, "kg*m/s"},
                   to_wire_vectors<Dim>(momentum, layout_, {0, 0, 0}, scratch_.wire));
  cosim::add_array(mpm, {"outer_nodes", "internal_force", {m, 3}, "N"},
                   to_wire_vectors<Dim>(force, layout_, {0, 0, 0}, scratch_.wire));
  add_apply(mpm, "outer_nodes", v1::ApplyRegion::MODE_ADD);
  mpm_ops_.push_back(Op::apply);
}

template <int Dim>
Totals CfdmpStep<Dim>::cell_totals(const cosim::Message& reply, const char* region,
                                   std::size_t count) const {
  const auto rho_view = cosim::view_array<double>(reply, region, "rho");
  const auto momentum_view = cosim::view_array<double>(reply, region, "momentum");
  const auto energy_view = cosim::view_array<double>(reply, region, "E");
  const auto rho = rho_view.values(), momentum = momentum_view.values(),
             energy = energy_view.values();
  check_value_count(reply, kFdm, region, "rho", rho.size(), count);
  check_value_count(reply, kFdm, region, "momentum", momentum.size(), 3 * count);
  check_value_count(reply, kFdm, region, "E", energy.size(), count);
  Totals totals;
  const double v = geometry_.cell_volume;
  for (std::size_t i = 0; i < count; ++i) {
    totals.mass += rho[i] * v;
    totals.energy += energy[i] * v;
    for (int a = 0; a < 3; ++a) totals.momentum[a] += momentum[3 * i + a] * v;
  }
  return totals;
}

template <int Dim>
void CfdmpStep<Dim>::read_fdm(const StepPlan& plan, const cosim::Message& reply) {
  for (std::size_t i = 0; i < fdm_ops_.size(); ++i) {
    const auto& result = result_of(reply, kFdm, static_cast<int>(i));
    if (fdm_ops_[i] == Op::export_strip) {
      if (plan.advance) {
        std::swap(strip_prev_, strip_now_);
        // No face flux while the zone sleeps: the face is an inner face of the FDM then.
        flux_due_ = plan.mpm;
        dt_last_ = plan.dt;
      }
      const std::size_t n = strip_layout_.box.count();
      read_doubles(reply, kFdm, "strip_cells", "rho", n, strip_now_.rho);
      read_doubles(reply, kFdm, "strip_cells", "E", n, strip_now_.energy);
      read_doubles(reply, kFdm, "strip_cells", "pressure", n, strip_now_.pressure);
      read_wire_vectors<Dim>(reply, kFdm, "strip_cells", "momentum", n, layout_,
                             strip_now_.momentum);
      // Not while the zone sleeps: the FDM owns its cells then and steps at its own CFL.
      strip_dt_ = std::numeric_limits<double>::infinity();
      if (plan.mpm)
        strip_dt_ = strip_step_limit<Dim>(strip_now_.rho, strip_now_.momentum, strip_now_.energy,
                                          strip_now_.pressure, injected_material_, scene_,
                                          scene_.time.mpm_cfl(), geometry_.spacing.minCoeff());
      if (rule_.reference_mass == 0.0) {
        // m_e of T (4-15): the mass of a zone particle at the densest inner strip cell.
        double rho_max = 0;
        for (const std::size_t c : strip_layout_.inner)
          rho_max = std::max(rho_max, strip_now_.rho[c]);
        int per_axis = 2;  // the default of bodies[].particles_per_axis
        for (const auto& body : scene_.bodies)
          per_axis = std::max(per_axis, body.particles_per_axis);
        const double per_cell = std::pow(static_cast<double>(per_axis), Dim);
        rule_.reference_mass = rho_max * geometry_.cell_volume / per_cell;
        rule_.min_particle_mass = kMinParticleShare * rule_.reference_mass;
        rule_.min_particle_volume = geometry_.cell_volume / (kMaxDensification * per_cell);
        rule_.check();
      }
    } else if (fdm_ops_[i] == Op::export_beyond) {
      const std::size_t n = strip_layout_.face_cells();
      read_doubles(reply, kFdm, "beyond_cells", "rho", n, beyond_.rho);
      read_doubles(reply, kFdm, "beyond_cells", "E", n, beyond_.energy);
      read_doubles(reply, kFdm, "beyond_cells", "pressure", n, beyond_.pressure);
      read_wire_vectors<Dim>(reply, kFdm, "beyond_cells", "momentum", n, layout_, beyond_.momentum);
    } else if (fdm_ops_[i] == Op::export_face) {
      read_crossed(reply);
    } else if (fdm_ops_[i] == Op::export_owned) {
      fdm_totals_ =
          cell_totals(reply, "fdm_owned", static_cast<std::size_t>(layout_.fdm_owned.count()));
      if (features_.fdm_outflow) fdm_outflow_ = outflow_totals(reply, kFdm, "fdm_owned");
    } else if (fdm_ops_[i] == Op::export_dormant) {
      mpm_totals_ =
          cell_totals(reply, "dormant_zone", static_cast<std::size_t>(layout_.mpm_zone.count()));
      // The zone's faces on the domain boundary are the FDM's while it sleeps; the last value
      // stays in the audit after the activation (the MPM's ledger starts then).
      if (features_.fdm_outflow) dormant_outflow_ = outflow_totals(reply, kFdm, "dormant_zone");
    } else if (fdm_ops_[i] == Op::propose) {
      fdm_dt_ = result.proposed().stable_dt();
    }
  }
}

template <int Dim>
void CfdmpStep<Dim>::read_mpm(const cosim::Message& reply) {
  for (std::size_t i = 0; i < mpm_ops_.size(); ++i) {
    const auto& result = result_of(reply, kMpm, static_cast<int>(i));
    switch (mpm_ops_[i]) {
      case Op::export_ghost: {
        const std::size_t nodes = ghost_nodes_.count();
        read_doubles(reply, kMpm, "ghost_nodes", "mass", nodes, ghost_node_mass_);
        read_wire_vectors<Dim>(reply, kMpm, "ghost_nodes", "momentum", nodes, layout_,
                               ghost_node_momentum_);
        read_doubles(reply, kMpm, "ghost_nodes", "internal_energy", ghost_cells_.count(),
                     ghost_cell_energy_);
        have_ghost_source_ = true;
        break;
      }
      case Op::export_face_particles:
        read_face_particles(static_cast<std::size_t>(result.exported().count()), reply);
        break;
      case Op::discard:
        traffic_.discarded = static_cast<std::size_t>(result.removed().removed());
        break;
      case Op::remove: {
        const auto n = static_cast<std::size_t>(result.removed().removed());
        traffic_.removed = n;
        if (n == 0) break;
        read_doubles(reply, kMpm, "crossed", "mass", n, removed_mass_);
        read_doubles(reply, kMpm, "crossed", "internal_energy", n, removed_energy_);
        read_wire_vectors<Dim>(reply, kMpm, "crossed", "position", n, layout_, removed_position_);
        read_wire_vectors<Dim>(reply, kMpm, "crossed", "velocity", n, layout_, removed_velocity_);
        break;
      }
      case Op::export_particles: {
        const auto n = static_cast<std::size_t>(result.exported().count());
        const auto mass_view = cosim::view_array<double>(reply, "mpm_zone", "mass");
        const auto velocity_view = cosim::view_array<double>(reply, "mpm_zone", "velocity");
        const auto energy_view = cosim::view_array<double>(reply, "mpm_zone", "internal_energy");
        const auto mass = mass_view.values(), velocity = velocity_view.values(),
                   energy = energy_view.values();
        check_value_count(reply, kMpm, "mpm_zone", "mass", mass.size(), n);
        check_value_count(reply, kMpm, "mpm_zone", "velocity", velocity.size(), 3 * n);
        check_value_count(reply, kMpm, "mpm_zone", "internal_energy", energy.size(), n);
        mpm_totals_ = {};
        for (std::size_t p = 0; p < n; ++p) {
          double v2 = 0;
          for (int a = 0; a < 3; ++a) {
            mpm_totals_.momentum[a] += mass[p] * velocity[3 * p + a];
            v2 += velocity[3 * p + a] * velocity[3 * p + a];
          }
          mpm_totals_.mass += mass[p];
          mpm_totals_.energy += energy[p] + 0.5 * mass[p] * v2;
        }
        if (features_.mpm_outflow) mpm_outflow_ = outflow_totals(reply, kMpm, "mpm_zone");
        break;
      }
      case Op::propose:
        mpm_dt_ = result.proposed().stable_dt();
        break;
      default:
        break;
    }
  }
}

template <int Dim>
std::size_t CfdmpStep<Dim>::face_cell_of(std::span<const double> position, std::size_t p) const {
  handshake::Index<Dim> cell{};
  for (int k = 0; k < Dim; ++k) {  // clamped: a particle on the box's edge is the box's
    const double x = position[3 * p + static_cast<std::size_t>(layout_.active[k])];
    const auto i =
        static_cast<std::int64_t>(std::floor((x - geometry_.origin(k)) / geometry_.spacing(k)));
    cell[k] = std::clamp(i, face_cells_.lo[k], face_cells_.hi[k] - 1);
  }
  return face_cells_.flat(cell);
}

template <int Dim>
void CfdmpStep<Dim>::read_face_particles(std::size_t n, const cosim::Message& reply) {
  // Per cell k-w+1, the zone's particles that resist the FDM's push (face_push_volume):
  // the fluids' Σ m_p and, in a scene with solids, the solids' Σ V_p.
  // Summed from the views: the count changes every injection, so no copy is kept.
  const auto mass_view = cosim::view_array<double>(reply, "face_particles", "mass");
  const auto position_view = cosim::view_array<double>(reply, "face_particles", "position");
  const auto mass = mass_view.values(), position = position_view.values();
  check_value_count(reply, kMpm, "face_particles", "mass", mass.size(), n);
  check_value_count(reply, kMpm, "face_particles", "position", position.size(), 3 * n);
  std::fill(face_mass_.begin(), face_mass_.end(), 0.0);
  std::fill(face_solid_volume_.begin(), face_solid_volume_.end(), 0.0);
  have_face_mass_ = true;
  if (!any_solid_) {
    for (std::size_t p = 0; p < n; ++p) face_mass_[face_cell_of(position, p)] += mass[p];
    return;
  }
  const auto volume_view = cosim::view_array<double>(reply, "face_particles", "volume");
  const auto material_view = cosim::view_array<std::uint32_t>(reply, "face_particles", "material");
  const auto volume = volume_view.values();
  const auto material = material_view.values();
  check_value_count(reply, kMpm, "face_particles", "volume", volume.size(), n);
  check_value_count(reply, kMpm, "face_particles", "material", material.size(), n);
  for (std::size_t p = 0; p < n; ++p) {
    if (material[p] >= solid_.size())
      throw Error("solver 'mpm' exported face_particles material " + std::to_string(material[p]) +
                  " for particle " + std::to_string(p) + "; the scene has " +
                  std::to_string(solid_.size()) + " materials");
    const std::size_t t = face_cell_of(position, p);
    if (solid_[material[p]])
      face_solid_volume_[t] += volume[p];
    else
      face_mass_[t] += mass[p];
  }
}

template <int Dim>
void CfdmpStep<Dim>::read(const StepPlan& plan, const cosim::Message& fdm,
                          const cosim::Message& mpm) {
  read_fdm(plan, fdm);
  if (plan.mpm)
    read_mpm(mpm);
  else  // a dormant zone proposes nothing: the FDM advances with its own dt
    mpm_dt_ = std::numeric_limits<double>::infinity();
  if (!(stable_dt() > 0.0) || !std::isfinite(stable_dt()))
    throw Error("step at t = " + std::to_string(plan.time) + " s: stable dt proposals fdm " +
                std::to_string(fdm_dt_) + " s, mpm " + std::to_string(mpm_dt_) +
                " s; expected both > 0 and finite");
}

template class CfdmpStep<1>;
template class CfdmpStep<2>;
template class CfdmpStep<3>;

}  // namespace mpfd::coupler
