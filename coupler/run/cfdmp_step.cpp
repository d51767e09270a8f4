#include "coupler/run/cfdmp_step.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "coupler/handshake/particle_removal.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

constexpr const char* kFdm = "fdm";
constexpr const char* kMpm = "mpm";

}  // namespace

template <int Dim>
CfdmpStep<Dim>::CfdmpStep(const config::Scene& scene, const ZoneLayout& layout)
    : scene_(scene), layout_(layout), injected_material_(scene) {
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
  ghost_cells_ = to_kernel_box<Dim>(layout.ghost_cells, layout);
  ghost_nodes_ = to_kernel_box<Dim>(layout.ghost_nodes, layout);
  deposit_box_ = to_kernel_box<Dim>(layout.deposit_cells, layout);
  corners_ = handshake::corner_nodes(ghost_cells_, ghost_nodes_);
  const std::size_t faces = strip_layout_.face_cells();
  outer_in_deposit_.resize(faces);
  for (std::size_t t = 0; t < faces; ++t) {
    auto outer = strip_layout_.inner_cell[t];
    outer[face_axis] -= layout.face_side;
    outer_in_deposit_[t] = deposit_box_.flat(outer);
  }
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
  if (flux_due_) {  // step 14 of the last step: T (4-10) ... (4-14) from strip_cells of its start
    handshake::accumulate_face_fluxes<Dim>(
        {strip_prev_.rho, strip_prev_.momentum, strip_prev_.energy}, strip_layout_, geometry_,
        dt_last_, parcels_, returned);
    flux_due_ = false;
  }
  add_deposit(fdm);
  if (plan.advance) {
    add_ghost_cells(fdm);
    add_advance(fdm, plan.dt, plan.time);
    fdm_ops_.push_back(Op::advance);
    add_injection(mpm);
    add_interface_nodes(mpm);
    add_advance(mpm, plan.dt, plan.time);
    mpm_ops_.push_back(Op::advance);
  }
  add_export(fdm, "strip_cells", {"rho", "momentum", "E", "pressure"});
  fdm_ops_.push_back(Op::export_strip);
  if (plan.audit) {
    add_export(fdm, "fdm_owned", {"rho", "momentum", "E"});
    fdm_ops_.push_back(Op::export_owned);
  }
  add_propose_dt(fdm);
  fdm_ops_.push_back(Op::propose);

  if (!have_ghost_source_) {
    // Step 0: the MPM filled the scene's bodies over the whole domain; what lies
    // outside its zone is the FDM's material, so it is dropped, not deposited.
    add_remove(mpm, "outside", "mpm_zone");
    mpm_ops_.push_back(Op::discard);
  }
  if (plan.advance || !have_ghost_source_) {
    add_export(mpm, "ghost_nodes", {"mass", "momentum", "internal_energy"});
    mpm_ops_.push_back(Op::export_ghost);
  }
  if (plan.advance) {
    add_remove(mpm, "crossed", "mpm_zone");
    mpm_ops_.push_back(Op::remove);
  }
  if (plan.audit) {
    add_export(mpm, "mpm_zone", {"mass", "velocity", "internal_energy"});
    mpm_ops_.push_back(Op::export_particles);
  }
  add_propose_dt(mpm);
  mpm_ops_.push_back(Op::propose);
}

template <int Dim>
void CfdmpStep<Dim>::add_deposit(cosim::Message& fdm) {
  // T (4-19) ... (4-21): the particles removed in the last step and the returned parcels.
  const std::size_t n = deposit_box_.count();
  std::vector<double> rho(n, 0.0), energy(n, 0.0);
  std::vector<Vec> momentum(n, Vec::Zero());
  const handshake::CellOutputs<Dim> add{rho, momentum, energy};
  const std::size_t removed = removed_mass_.size();
  if (removed > 0) {
    std::vector<std::size_t> cell(removed);
    handshake::locate_deposit_cells<Dim>(removed_position_, deposit_box_, geometry_, cell);
    std::vector<Vec> p(removed);
    std::vector<double> e(removed);
    handshake::particle_amounts<Dim>(removed_mass_, removed_velocity_, removed_energy_, p, e);
    handshake::deposit<Dim>(removed_mass_, p, e, cell, geometry_.cell_volume, add);
    for (const double m : removed_mass_) traffic_.deposited_mass += m;
  }
  handshake::deposit<Dim>(returned_mass_, returned_momentum_, returned_energy_, outer_in_deposit_,
                          geometry_.cell_volume, add);
  for (const double m : returned_mass_) traffic_.deposited_mass += m;
  removed_mass_.clear();
  removed_energy_.clear();
  removed_position_.clear();
  removed_velocity_.clear();
  if (traffic_.deposited_mass == 0.0) return;
  cosim::add_array(fdm, {"deposit_cells", "rho", {}, "kg/m^3"}, std::span<const double>(rho));
  cosim::add_array(fdm, {"deposit_cells", "momentum", {n, 3}, "kg/(m^2*s)"},
                   std::span<const double>(to_wire_vectors<Dim>(momentum, layout_, {0, 0, 0})));
  cosim::add_array(fdm, {"deposit_cells", "E", {}, "J/m^3"}, std::span<const double>(energy));
  add_apply(fdm, "deposit_cells", v1::ApplyRegion::MODE_ADD);
  fdm_ops_.push_back(Op::apply);
}

template <int Dim>
void CfdmpStep<Dim>::add_ghost_cells(cosim::Message& fdm) {
  // T (4-1) ... (4-6) from the ghost_nodes of t^n.
  const std::size_t n = ghost_cells_.count();
  std::vector<double> rho(n), energy(n);
  std::vector<Vec> momentum(n);
  handshake::fill_ghost_cells<Dim>({ghost_node_mass_, ghost_node_momentum_, ghost_cell_energy_},
                                   corners_, geometry_.cell_volume, {rho, momentum, energy});
  cosim::add_array(fdm, {"ghost_cells", "rho", {}, "kg/m^3"}, std::span<const double>(rho));
  cosim::add_array(fdm, {"ghost_cells", "momentum", {n, 3}, "kg/(m^2*s)"},
                   std::span<const double>(to_wire_vectors<Dim>(momentum, layout_, {0, 0, 0})));
  cosim::add_array(fdm, {"ghost_cells", "E", {}, "J/m^3"}, std::span<const double>(energy));
  add_apply(fdm, "ghost_cells", v1::ApplyRegion::MODE_SET);
  fdm_ops_.push_back(Op::apply);
}

template <int Dim>
void CfdmpStep<Dim>::add_injection(cosim::Message& mpm) {
  // T (4-15) ... (4-18): parcels heavy enough become particles in cell k-w+1.
  std::vector<std::size_t> count(parcels_.size());
  const std::size_t n = handshake::count_new_particles<Dim>(parcels_, rule_, count);
  if (n == 0) return;
  std::vector<Vec> position(n), velocity(n);
  std::vector<double> mass(n), volume(n), energy(n);
  std::vector<std::size_t> face(n);
  handshake::create_particles<Dim>(parcels_, count, strip_layout_, geometry_,
                                   {position, velocity, mass, volume, energy, face});
  std::vector<std::uint64_t> ids(n);
  for (auto& id : ids) id = next_id_++;
  std::vector<std::uint32_t> material(n);
  for (std::size_t p = 0; p < n; ++p)
    material[p] = injected_material_.choose(mass[p] / volume[p], energy[p] / mass[p],
                                            strip_now_.pressure[strip_layout_.inner[face[p]]]);
  cosim::add_array(mpm, {"injected", "id", {}, "1"}, std::span<const std::uint64_t>(ids));
  cosim::add_array(
      mpm, {"injected", "position", {n, 3}, "m"},
      std::span<const double>(to_wire_vectors<Dim>(position, layout_, inactive_centre_)));
  cosim::add_array(mpm, {"injected", "velocity", {n, 3}, "m/s"},
                   std::span<const double>(to_wire_vectors<Dim>(velocity, layout_, {0, 0, 0})));
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
  std::vector<double> mass(n);
  std::vector<Vec> momentum(n), force(n);
  handshake::interface_node_terms<Dim>({strip_now_.rho, strip_now_.momentum, strip_now_.energy},
                                       strip_now_.pressure, strip_layout_, stencil_, geometry_,
                                       {mass, momentum, force});
  cosim::add_array(mpm, {"interface_nodes", "mass", {}, "kg"}, std::span<const double>(mass));
  cosim::add_array(mpm, {"interface_nodes", "momentum", {n, 3}, "kg*m/s"},
                   std::span<const double>(to_wire_vectors<Dim>(momentum, layout_, {0, 0, 0})));
  cosim::add_array(mpm, {"interface_nodes", "internal_force", {n, 3}, "N"},
                   std::span<const double>(to_wire_vectors<Dim>(force, layout_, {0, 0, 0})));
  add_apply(mpm, "interface_nodes", v1::ApplyRegion::MODE_ADD);
  mpm_ops_.push_back(Op::apply);
}

template <int Dim>
Totals CfdmpStep<Dim>::cell_totals(const cosim::Message& reply, std::size_t count) const {
  const auto rho = read_doubles(reply, kFdm, "fdm_owned", "rho", count);
  const auto momentum = read_doubles(reply, kFdm, "fdm_owned", "momentum", 3 * count);
  const auto energy = read_doubles(reply, kFdm, "fdm_owned", "E", count);
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
        flux_due_ = true;
        dt_last_ = plan.dt;
      }
      const std::size_t n = strip_layout_.box.count();
      strip_now_.rho = read_doubles(reply, kFdm, "strip_cells", "rho", n);
      strip_now_.energy = read_doubles(reply, kFdm, "strip_cells", "E", n);
      strip_now_.pressure = read_doubles(reply, kFdm, "strip_cells", "pressure", n);
      from_wire_vectors<Dim>(read_doubles(reply, kFdm, "strip_cells", "momentum", 3 * n), layout_,
                             strip_now_.momentum);
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
        rule_.min_particle_mass = 0.125 * rule_.reference_mass;
        rule_.check();
      }
    } else if (fdm_ops_[i] == Op::export_owned) {
      fdm_totals_ = cell_totals(reply, static_cast<std::size_t>(layout_.fdm_owned.count()));
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
        ghost_node_mass_ = read_doubles(reply, kMpm, "ghost_nodes", "mass", nodes);
        from_wire_vectors<Dim>(read_doubles(reply, kMpm, "ghost_nodes", "momentum", 3 * nodes),
                               layout_, ghost_node_momentum_);
        ghost_cell_energy_ =
            read_doubles(reply, kMpm, "ghost_nodes", "internal_energy", ghost_cells_.count());
        have_ghost_source_ = true;
        break;
      }
      case Op::discard:
        traffic_.discarded = static_cast<std::size_t>(result.removed().removed());
        break;
      case Op::remove: {
        const auto n = static_cast<std::size_t>(result.removed().removed());
        traffic_.removed = n;
        if (n == 0) break;
        removed_mass_ = read_doubles(reply, kMpm, "crossed", "mass", n);
        removed_energy_ = read_doubles(reply, kMpm, "crossed", "internal_energy", n);
        from_wire_vectors<Dim>(read_doubles(reply, kMpm, "crossed", "position", 3 * n), layout_,
                               removed_position_);
        from_wire_vectors<Dim>(read_doubles(reply, kMpm, "crossed", "velocity", 3 * n), layout_,
                               removed_velocity_);
        break;
      }
      case Op::export_particles: {
        const auto n = static_cast<std::size_t>(result.exported().count());
        const auto mass = read_doubles(reply, kMpm, "mpm_zone", "mass", n);
        const auto velocity = read_doubles(reply, kMpm, "mpm_zone", "velocity", 3 * n);
        const auto energy = read_doubles(reply, kMpm, "mpm_zone", "internal_energy", n);
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
void CfdmpStep<Dim>::read(const StepPlan& plan, const cosim::Message& fdm,
                          const cosim::Message& mpm) {
  read_fdm(plan, fdm);
  read_mpm(mpm);
  if (!(stable_dt() > 0.0) || !std::isfinite(stable_dt()))
    throw Error("step at t = " + std::to_string(plan.time) + " s: stable dt proposals fdm " +
                std::to_string(fdm_dt_) + " s, mpm " + std::to_string(mpm_dt_) +
                " s; expected both > 0 and finite");
}

template class CfdmpStep<1>;
template class CfdmpStep<2>;
template class CfdmpStep<3>;

}  // namespace mpfd::coupler
