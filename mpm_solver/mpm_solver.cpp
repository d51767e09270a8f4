#include "mpm_solver/mpm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/initial/initial_cells.hpp"
#include "mpm_solver/contact/multi_velocity_contact.hpp"
#include "mpm_solver/damping/shear_mode_damping.hpp"
#include "mpm_solver/material/shear_modulus.hpp"
#include "mpm_solver/program_burn.hpp"

namespace mpfd::mpm {
namespace {

using config::BoundaryKind;

/// Runs fn(p) for every particle, block by block in colour order: blocks of one
/// colour share no node, so their scatters run in parallel without races.
template <class Fn>
void for_each_particle_by_colour(const SparseGrid& grid, std::size_t particles, const Fn& fn) {
  const bool parallel = static_cast<std::ptrdiff_t>(particles) >= kMinParallelCount;
#pragma omp parallel if (parallel)
  for (int c = 0; c < SparseGrid::kColours; ++c) {
    const auto slots = grid.colour(c);
    const auto count = static_cast<std::ptrdiff_t>(slots.size());
#pragma omp for schedule(dynamic, 4)
    for (std::ptrdiff_t b = 0; b < count; ++b)
      for (const std::int32_t p : grid.bucket(slots[static_cast<std::size_t>(b)]))
        fn(static_cast<std::size_t>(p));
  }
}

/// Runs fn(n) for every node of the grid.
template <class Fn>
void for_each_node(std::size_t nodes, const Fn& fn) {
  parallel_for(nodes, fn);
}

/// Calls fn(width, mask, contact) with compile-time constants, so that the
/// particle passes of a scene without contact carry no per-node test.
template <class Fn>
void dispatch_kernel(bool gimp, int mask, bool contact, Fn&& fn) {
  dispatch_stencil(gimp, mask, [&](auto width, auto m) {
    if (contact)
      fn(width, m, std::true_type{});
    else
      fn(width, m, std::false_type{});
  });
}

/// A fixed body's mass in the contact kernel: it takes any impulse without moving.
constexpr double kFixedMassFactor = 1e12;

}  // namespace

MpmSettings MpmSettings::from_scene(const config::Scene& scene) {
  return {.cfl = scene.time.mpm_cfl(),
          .shape_function = scene.solver.mpm.shape_function,
          .update = scene.solver.mpm.update,
          .bulk_viscosity_quadratic = scene.solver.mpm.bulk_viscosity_quadratic,
          .bulk_viscosity_linear = scene.solver.mpm.bulk_viscosity_linear,
          .shear_damping = scene.solver.mpm.shear_damping,
          .reference_pressure = scene.solver.mpm.reference_pressure};
}

MpmSolver::MpmSolver(const config::Scene& scene, MpmSettings settings)
    : settings_(settings), faces_(scene.boundaries.faces), grid_(initial::scene_grid(scene)) {
  const auto& g = grid_.grid();
  min_spacing_ = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    geometry_.origin[a] = g.origin()[a];
    geometry_.inverse_spacing[a] = 1.0 / g.spacing()[a];
    geometry_.offset[a] = grid_.offset()[a];
    if (g.is_active(a)) {
      axis_mask_ |= 1 << a;
      min_spacing_ = std::min(min_spacing_, g.spacing()[a]);
    }
  }
  if (axis_mask_ == 0)
    throw Error("scene '" + scene.name +
                "': mpm needs at least one axis with more than one cell, got cells 1 x 1 x 1");
  viscosity_ = {settings.bulk_viscosity_quadratic, settings.bulk_viscosity_linear, min_spacing_};

  GeneratedParticles generated = generate_particles(scene, g);
  particles_ = std::move(generated.particles);
  bodies_ = std::move(generated.bodies);
  scene_bodies_ = bodies_.size();
  materials_ = scene.materials;
  for (const auto& m : materials_)
    gas_.push_back(std::holds_alternative<eos::IdealGas>(m.eos) ? 1 : 0);
  for (std::size_t p = 0; p < particles_.size(); ++p) particles_.id[p] = kSceneParticleIdBase + p;

  models_.resize(scene.materials.size());
  for (const auto& body : bodies_)
    if (!models_[body.material])
      models_[body.material] = make_constitutive_model(scene.materials[body.material]);
  std::size_t stride = 0;
  for (const auto& m : models_)
    if (m) stride = std::max(stride, static_cast<std::size_t>(m->history_count()));
  particles_.history_stride = stride;
  particles_.history.assign(particles_.size() * stride, 0.0);

  for (std::size_t p = 0; p < particles_.size(); ++p) {
    Tensor3 s = Tensor3::Zero();
    MaterialPoint point = particles_.material_point(p, s);
    models_[particles_.material[p]]->initialise(particles_.density[p], point);
    particles_.pressure[p] *= burn_fraction(p);  // T (3-1)
    particles_.set_deviator(p, s);
  }
  reserve_particle_scratch();

  const auto& mpm = scene.solver.mpm;
  gravity_ = mpm.gravity;
  body_fixed_.assign(bodies_.size(), 0);
  for (std::size_t b = 0; b < scene.bodies.size() && b < bodies_.size(); ++b)
    body_fixed_[b] = scene.bodies[b].fixed ? 1 : 0;
  has_fixed_ = std::find(body_fixed_.begin(), body_fixed_.end(), 1) != body_fixed_.end();
  body_shear_modulus_.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    body_shear_modulus_[b] = shear_modulus(scene.materials[bodies_[b].material].strength);
  for (const BoundaryKind kind : faces_) non_reflecting_ |= kind == BoundaryKind::non_reflecting;
  if (non_reflecting_) {
    const auto& s = scene.initial;
    const auto* material = config::find_material(scene, s.material);
    far_field_pressure_ = s.pressure ? *s.pressure
                          : material
                              ? eos::pressure(material->eos, s.density, *s.specific_internal_energy)
                              : 0.0;
  }
  if (mpm.contact && settings_.update == config::MpmUpdate::usavg)
    throw Error("scene '" + scene.name +
                "': solver.mpm.update usavg is not supported with solver.mpm.contact yet; "
                "expected musl or usl");
  if (mpm.contact) {
    contact_ = true;
    friction_ = mpm.contact->friction;
    if (bodies_.size() > static_cast<std::size_t>(ContactFields::kMaxBodies))
      throw Error("scene '" + scene.name + "': solver.mpm.contact handles at most " +
                  std::to_string(ContactFields::kMaxBodies) + " bodies and charges, got " +
                  std::to_string(bodies_.size()));
    contact_fields_.bodies = static_cast<int>(bodies_.size());
    // The body that gives the normal, T (2-24): the named one, else fixed bodies,
    // else the stiffest (largest rho c^2 of its particles at the start), else the first.
    std::vector<double> stiffness(bodies_.size(), 0.0);
    for (std::size_t p = 0; p < particles_.size(); ++p) {
      double& k = stiffness[particles_.body[p]];
      k = std::max(k,
                   particles_.density[p] * particles_.sound_speed[p] * particles_.sound_speed[p]);
    }
    std::vector<std::size_t> order(bodies_.size());
    for (std::size_t b = 0; b < order.size(); ++b) order[b] = b;
    const auto& named = mpm.contact->normal_body;
    const auto key = [&](std::size_t b) {
      const bool is_named = named && bodies_[b].name == *named;
      return std::tuple(!is_named, body_fixed_[b] == 0, -stiffness[b]);
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    normal_rank_.resize(bodies_.size());
    for (std::size_t r = 0; r < order.size(); ++r) normal_rank_[order[r]] = static_cast<int>(r);
  }
  compute_stable_dt();
}

MpmSolver::~MpmSolver() = default;

double MpmSolver::burn_fraction(std::size_t p) const {
  return mpm::burn_fraction(time_, particles_.lighting_time[p],
                            bodies_[particles_.body[p]].burn_rate);
}

double MpmSolver::step_toward(double target) const {
  const double left = target - time_;
  if (left <= stable_dt_) return left;
  return left < 2.0 * stable_dt_ ? 0.5 * left : stable_dt_;
}

void MpmSolver::advance_to(double end) {
  while (time_ < end) advance(step_toward(end));
}

void MpmSolver::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error("mpm: time step must be positive and finite, got " + std::to_string(dt));
  // A coupler's ghost-node export may have mapped this step already (map_next_step).
  last_advance_premapped_ = next_map_.valid && loads_on_mapped_blocks();
  next_map_.valid = false;
  if (!last_advance_premapped_) {
    rebuild_grid();
    if (contact_) mark_shared_nodes();
    // USAVG's forces are those of the half-updated stress: the first scatter
    // sums only what the stress does not change.
    particles_to_grid(first_scatter());
  }
  const bool usavg = settings_.update == config::MpmUpdate::usavg;
  record_added_node_state();
  if (!usavg) {
    apply_node_loads(NodeLoadPass::all);
  } else {
    // v_I^n of the first half includes the FDM cells a coupler adds to the
    // interface nodes, T (4-7), (4-8), as the remap's v^{n+1} does.
    apply_node_loads(NodeLoadPass::mass_and_momentum);
    // cpGIMP's domains follow F_aa, which the first half changes, and with
    // them every weight: m_I and p_I are mapped again, not only f_I.
    const bool weights_change = settings_.shape_function == config::ShapeFunction::cpgimp;
    strain_first_half(dt, !weights_change);
    if (weights_change) {
      grid_.allocate_nodes();  // the particles have not moved: same blocks, zeroed sums
      particles_to_grid(Scatter::all);
      apply_node_loads(NodeLoadPass::all);
    } else {
      apply_node_loads(NodeLoadPass::force);
    }
  }
  node_loads_.clear();
  integrate_nodes(dt);
  if (settings_.update != config::MpmUpdate::usl) update_and_remap_velocities(dt);
  update_particles(dt);
  particle_updates_ += static_cast<double>(particles_.size());
  time_ += dt;
  ++steps_;
  remove_outflow();
  compute_stable_dt();
}

void MpmSolver::reserve_particle_scratch() {
  const std::size_t n = particles_.size();
  if (home_slot_.capacity() < n) home_slot_.reserve(std::max(n, 2 * home_slot_.capacity()));
  if (leaving_.capacity() < n) leaving_.reserve(std::max(n, 2 * leaving_.capacity()));
}

void MpmSolver::rebuild_grid() {
  const std::size_t n = particles_.size();
  home_slot_.resize(n);
  grid_.clear();
  for (std::size_t p = 0; p < n; ++p) {
    grid::Index3 lo{}, hi{};
    stencil_box(p, lo, hi);
    home_slot_[p] = grid_.activate(lo, hi);
  }
  for (const NodeLoad& load : node_loads_) {  // a coupler's node may lie beyond every stencil
    grid::Index3 node{};
    for (int a = 0; a < 3; ++a) node[a] = load.node[a] + grid_.offset()[a];
    grid_.activate(node, node);
  }
  grid_.allocate_nodes();
  grid_.bin_particles(home_slot_);
}

void MpmSolver::stencil_box(std::size_t p, grid::Index3& lo, grid::Index3& hi) const {
  const auto& g = grid_.grid();
  const bool gimp = settings_.shape_function != config::ShapeFunction::linear;
  for (int a = 0; a < 3; ++a) {
    const double x = particles_.position[a][p];
    const bool active = g.is_active(a);
    lo[a] = gimp ? first_node<3>(x, a, active, geometry_) : first_node<2>(x, a, active, geometry_);
    hi[a] = active ? lo[a] + (gimp ? 2 : 1) : lo[a];
  }
}

void MpmSolver::particle_half_width(std::size_t p, double half_width[3]) const {
  const BodyInfo& body = bodies_[particles_.body[p]];
  for (int a = 0; a < 3; ++a) {
    half_width[a] = body.half_width[a];
    // cpGIMP (W §2.3): the domain follows F_aa; at most half a cell, so that
    // three nodes per axis still hold the stencil, and not degenerate.
    if (settings_.shape_function == config::ShapeFunction::cpgimp && grid_.grid().is_active(a))
      half_width[a] = std::clamp(half_width[a] * particles_.stretch[a][p], 1e-3, 0.5);
  }
}

template <class Fn>
void MpmSolver::for_each_face_node(const Fn& fn) const {
  const auto& g = grid_.grid();
  const std::size_t per_block = grid_.block_nodes();
  for (std::size_t slot = 0; slot < grid_.block_count(); ++slot) {
    const grid::Index3 corner = grid_.node_coordinates(slot * per_block);
    bool touches = false;
    for (int a = 0; a < 3 && !touches; ++a) {
      if (!g.is_active(a)) continue;
      const int reach = 1 << SparseGrid::kBlockShift;
      touches = corner[a] <= 1 || corner[a] + reach - 1 >= g.cells()[a] + 1;
    }
    if (!touches) continue;
    for (std::size_t n = slot * per_block; n < (slot + 1) * per_block; ++n) {
      const grid::Index3 at = grid_.node_coordinates(n);
      for (int a = 0; a < 3; ++a) {
        if (!g.is_active(a)) continue;
        // Storage coordinate <= 1: the node on the lower face or the ghost beyond it.
        const int side = at[a] <= 1 ? 0 : at[a] >= g.cells()[a] + 1 ? 1 : -1;
        if (side < 0) continue;
        fn(n, a, side, faces_[static_cast<std::size_t>(2 * a + side)]);
      }
    }
  }
}

void MpmSolver::mark_shared_nodes() {
  const auto& ps = particles_;
  auto& fields = contact_fields_;
  fields.begin_marking(grid_.node_count());
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        using S = Stencil<decltype(width)::value, decltype(mask)::value>;
        for_each_particle_by_colour(grid_, ps.size(), [&](std::size_t p) {
          const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
          S s;
          double half_width[3];
          particle_half_width(p, half_width);
          compute_stencil(x, half_width, geometry_, grid_, s);
          const int body = ps.body[p];
          for (int c = 0; c < S::kCount; ++c)
            if (s.weight[c] > 0.0) fields.mark(s.node[c], body);
        });
      });
  fields.compact();
}

double MpmSolver::internal_stress(std::size_t p, double (&sigma)[3][3]) const {
  const auto& ps = particles_;
  // sigma + p_ref I = s - (p + q - p_ref) I, tension positive. The particle
  // sum of V_p grad N_I(x_p) vanishes only on the particles' initial lattice;
  // off it a uniform p pushes the nodes (a negative stiffness ~ p / h^2 that
  // makes still 2D air grow, docs/mpm.md), which p_ref, the ambient
  // pressure, takes away.
  const double pq = ps.pressure[p] + ps.bulk_viscosity[p] - settings_.reference_pressure;
  const auto& d = ps.deviatoric_stress;
  const double rows[3][3] = {{d[kXX][p] - pq, d[kXY][p], d[kZX][p]},
                             {d[kXY][p], d[kYY][p] - pq, d[kYZ][p]},
                             {d[kZX][p], d[kYZ][p], d[kZZ][p] - pq}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sigma[i][j] = rows[i][j];
  return ps.mass[p] / ps.density[p];
}

void MpmSolver::zero_stress_sums() {
  const std::size_t nodes = grid_.node_count();
  if (settings_.shear_damping > 0.0) {
    cell_mass_.assign(nodes, 0.0);
    cell_sound_speed_.assign(nodes, 0.0);
  }
  if (non_reflecting_)
    for (auto& a : face_sums_) a.assign(nodes, 0.0);
}

template <class S>
void MpmSolver::scatter_stress_sums(std::size_t p, const double (&x)[3], const S& s) {
  const auto& ps = particles_;
  const double m = ps.mass[p];
  if (settings_.shear_damping > 0.0) {
    // The lower corner of the particle's cell, as a stencil slot.
    int corner = 0;
    const int extent[3] = {S::kNx, S::kNy, S::kNz};
    for (int a = 2; a >= 0; --a) {
      int i = 0;
      if (extent[a] > 1)
        i = static_cast<int>(
                std::floor((x[a] - geometry_.origin[a]) * geometry_.inverse_spacing[a])) +
            geometry_.offset[a] - s.first[a];
      corner = corner * extent[a] + std::clamp(i, 0, extent[a] - 1);
    }
    const std::size_t node = s.node[corner];
    cell_mass_[node] += m;
    cell_sound_speed_[node] = std::max(cell_sound_speed_[node], ps.sound_speed[p]);
  }
  if (non_reflecting_) {
    const auto& g = grid_.grid();
    bool near = false;
    const int extent[3] = {S::kNx, S::kNy, S::kNz};
    for (int a = 0; a < 3; ++a) {
      if (!g.is_active(a)) continue;
      near |= faces_[static_cast<std::size_t>(2 * a)] == BoundaryKind::non_reflecting &&
              s.first[a] <= 1;
      near |= faces_[static_cast<std::size_t>(2 * a + 1)] == BoundaryKind::non_reflecting &&
              s.first[a] + extent[a] - 1 >= g.cells()[a] + 1;
    }
    if (!near) return;
    const double volume = m / ps.density[p];
    const double c_s = std::sqrt(body_shear_modulus_[ps.body[p]] / ps.density[p]);
    for (int c = 0; c < S::kCount; ++c) {
      const double w = s.weight[c];
      face_sums_[0][s.node[c]] += w * volume;
      face_sums_[1][s.node[c]] += w * m * ps.sound_speed[p];
      face_sums_[2][s.node[c]] += w * m * c_s;
    }
  }
}

void MpmSolver::particles_to_grid(Scatter what) {
  // Per-node sums only some scenes need, zeroed here (grow-only: no allocation).
  if (has_fixed_) fixed_mass_.assign(grid_.node_count(), 0.0);
  if (what == Scatter::all) zero_stress_sums();
  scatter_particles(what, ScatterOrder::by_colour);
}

void MpmSolver::scatter_particles(Scatter what, ScatterOrder order, std::size_t first) {
  const auto& ps = particles_;
  double* node_mass = grid_.mass.data();
  double* node_momentum[3] = {grid_.momentum[0].data(), grid_.momentum[1].data(),
                              grid_.momentum[2].data()};
  double* node_force[3] = {grid_.force[0].data(), grid_.force[1].data(), grid_.force[2].data()};
  auto& cf = contact_fields_;
  double* box_energy = next_map_.valid ? next_map_energy_.data() : nullptr;
  const auto for_each = [&](const auto& fn) {
    if (order == ScatterOrder::by_colour)
      for_each_particle_by_colour(grid_, ps.size(), fn);
    else
      for (std::size_t p = first; p < ps.size(); ++p) fn(p);
  };
  const auto scatter = [&](auto with_stress) {
    constexpr bool kStress = decltype(with_stress)::value;
    dispatch_kernel(
        settings_.shape_function != config::ShapeFunction::linear, axis_mask_, contact_,
        [&](auto width, auto mask, auto with_contact) {
          using S = Stencil<decltype(width)::value, decltype(mask)::value>;
          constexpr bool kContact = decltype(with_contact)::value;
          for_each([&](std::size_t p) {
            const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
            S s;
            double half_width[3];
            particle_half_width(p, half_width);
            compute_stencil(x, half_width, geometry_, grid_, s);
            const double m = ps.mass[p];
            if (box_energy != nullptr) {  // e_I of (2-12) where a coupler reads it
              const int extent[3] = {S::kNx, S::kNy, S::kNz};
              bool reaches = true;
              for (int a = 0; a < 3; ++a)
                reaches = reaches && s.first[a] + extent[a] > next_map_.lo[a] &&
                          s.first[a] < next_map_.hi[a];
              if (reaches) {
                const double e = ps.specific_internal_energy[p];
                for (int c = 0; c < S::kCount; ++c) box_energy[s.node[c]] += s.weight[c] * m * e;
              }
            }
            const double v[3] = {ps.velocity[0][p], ps.velocity[1][p], ps.velocity[2][p]};
            const int body = ps.body[p];
            double sigma[3][3] = {};
            double volume = 0.0;
            if constexpr (kStress) volume = internal_stress(p, sigma);
            for (int c = 0; c < S::kCount; ++c) {
              const std::size_t node = s.node[c];
              const double wm = s.weight[c] * m;
              node_mass[node] += wm;  // (2-12)
              const double* gr = s.gradient[c];
              double f[3] = {0.0, 0.0, 0.0};
              for (int i = 0; i < 3; ++i) {
                node_momentum[i][node] += wm * v[i];  // (2-9)
                if constexpr (kStress) {
                  f[i] =
                      -volume * (sigma[i][0] * gr[0] + sigma[i][1] * gr[1] + sigma[i][2] * gr[2]);
                  node_force[i][node] += f[i];  // (2-10)
                }
              }
              if constexpr (kContact) {
                const std::int32_t k = cf.shared[node];
                if (k >= 0) {
                  const std::size_t at = cf.at(k, body);
                  cf.mass[at] += wm;
                  for (int i = 0; i < 3; ++i) {
                    cf.momentum[i][at] += wm * v[i];
                    cf.gradient[i][at] += m * gr[i];  // numerator of (2-23)
                    if constexpr (kStress) cf.force[i][at] += f[i];
                  }
                }
              }
            }
            if (has_fixed_ && body_fixed_[body] != 0)
              for (int c = 0; c < S::kCount; ++c) fixed_mass_[s.node[c]] += s.weight[c] * m;
            if constexpr (kStress) scatter_stress_sums(p, x, s);
          });
        });
  };
  if (what == Scatter::all)
    scatter(std::true_type{});
  else
    scatter(std::false_type{});
}

void MpmSolver::integrate_nodes(double dt) {
  const std::size_t nodes = grid_.node_count();
  auto& momentum = grid_.momentum;
  auto& force = grid_.force;
  if (gravity_[0] != 0.0 || gravity_[1] != 0.0 || gravity_[2] != 0.0) {
    for_each_node(nodes, [&](std::size_t n) {
      for (int a = 0; a < 3; ++a) force[a][n] += grid_.mass[n] * gravity_[a];
    });
  }
  if (settings_.shear_damping > 0.0) add_shear_damping(dt);
  for_each_node(nodes, [&](std::size_t n) {
    for (int a = 0; a < 3; ++a) momentum[a][n] += force[a][n] * dt;  // (2-13)
  });
  if (contact_) advance_shared_nodes(dt);
  if (non_reflecting_) add_boundary_tractions(dt);
  apply_node_constraints(dt);
  // From here on the arrays hold velocities and accelerations, p / m and f / m,
  // so the particle passes only multiply. Only massless nodes are skipped: a
  // light node's f / m is large but its weight N_Ip is as small, so N f / m
  // stays bounded, and a relative cut-off (tried: 1e-10 of the lightest
  // particle) broke the momentum balance by 1e-10 with GIMP.
  for_each_node(nodes, [&](std::size_t n) {
    const double m = grid_.mass[n];
    const double inverse = m > 0.0 ? 1.0 / m : 0.0;
    for (int a = 0; a < 3; ++a) {
      momentum[a][n] *= inverse;
      force[a][n] *= inverse;
    }
  });
  if (contact_) {
    auto& cf = contact_fields_;
    parallel_for(cf.mass.size(), [&](std::size_t at) {
      const double inverse = cf.mass[at] > 0.0 ? 1.0 / cf.mass[at] : 0.0;
      for (int a = 0; a < 3; ++a) {
        cf.momentum[a][at] *= inverse;
        cf.force[a][at] *= inverse;
      }
    });
  }
}

namespace {

/// The shear-mode damping of every cell that holds particles and whose lower corner is a
/// node of the block at `slot`, for Dim active axes `axes`.
template <int Dim>
void damp_block_cells(SparseGrid& grid, std::size_t slot, const int (&axes)[3],
                      const std::vector<double>& cell_mass,
                      const std::vector<double>& cell_sound_speed, double cell_size, double q_s,
                      double dt) {
  constexpr int kNodes = damping::kCellNodes<Dim>;
  const std::size_t per_block = grid.block_nodes();
  for (std::size_t n = slot * per_block; n < (slot + 1) * per_block; ++n) {
    if (!(cell_mass[n] > 0.0)) continue;
    const grid::Index3 at = grid.node_coordinates(n);
    std::size_t corner[kNodes];
    damping::CellVectors<Dim> velocity;
    double lightest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < kNodes; ++c) {
      grid::Index3 q = at;
      for (int k = 0; k < Dim; ++k) q[axes[k]] += (c >> k) & 1;
      corner[c] = grid.node(q[0], q[1], q[2]);
      const double m = grid.mass[corner[c]];
      lightest = std::min(lightest, m);
      for (int k = 0; k < Dim; ++k)
        velocity[c](k) = m > 0.0 ? grid.momentum[axes[k]][corner[c]] / m : 0.0;
    }
    // T (2-48); clamped so that dt sum_cells 2^Dim alpha <= 2 m_I at every corner
    // (a node has at most 2^Dim cells): the damping then only removes energy.
    const double alpha = std::min(
        damping::shear_damping_coefficient<Dim>(cell_mass[n], cell_sound_speed[n], cell_size, q_s),
        2.0 * lightest / (dt * kNodes * kNodes));
    if (!(alpha > 0.0)) continue;
    const auto f = damping::shear_damping_forces<Dim>(velocity, alpha);  // T (2-47)
    for (int c = 0; c < kNodes; ++c)
      for (int k = 0; k < Dim; ++k) grid.force[axes[k]][corner[c]] += f[c](k);
  }
}

}  // namespace

void MpmSolver::add_shear_damping(double dt) {
  int axes[3] = {0, 0, 0};
  int dim = 0;
  for (int a = 0; a < 3; ++a)
    if (grid_.grid().is_active(a)) axes[dim++] = a;
  if (dim < 2) return;  // a 1D cell has no shear mode
  // Cells of blocks with equal parities touch no common node: one colour at a time.
  const std::size_t blocks = grid_.block_count();
  for (int colour = 0; colour < SparseGrid::kColours; ++colour) {
    parallel_for(blocks, [&](std::size_t slot) {
      const grid::Index3 at = grid_.node_coordinates(slot * grid_.block_nodes());
      int parity = 0;
      for (int a = 0; a < 3; ++a) parity |= ((at[a] >> SparseGrid::kBlockShift) & 1) << a;
      if (parity != colour) return;
      if (dim == 2)
        damp_block_cells<2>(grid_, slot, axes, cell_mass_, cell_sound_speed_, min_spacing_,
                            settings_.shear_damping, dt);
      else
        damp_block_cells<3>(grid_, slot, axes, cell_mass_, cell_sound_speed_, min_spacing_,
                            settings_.shear_damping, dt);
    });
  }
}

void MpmSolver::add_boundary_tractions(double dt) {
  const auto& g = grid_.grid();
  auto& cf = contact_fields_;
  for_each_face_node([&](std::size_t n, int axis, int side, BoundaryKind kind) {
    if (kind != BoundaryKind::non_reflecting) return;
    const double m = grid_.mass[n];
    if (!(m > 0.0)) return;
    // W (2-59), (2-60) as nodal forces: traction times the node's face area
    // A_I = 2 V_I / h (V_I = sum N V_p: half a cell of particles behind the
    // face), so rho A_I c = 2 (sum N m_p c) / h = k. The dashpot acts on the
    // end-of-step velocity, p^{n+1} = p* / (1 + k dt / m): stable for any step
    // (explicitly, k dt / m = 2 CFL would stop the node every step at CFL 0.5).
    // The far field pushes with the pressure of `initial`, less p_ref.
    const double scale = 2.0 / g.spacing()[axis];
    const double outward = side == 0 ? -1.0 : 1.0;
    for (int c = 0; c < 3; ++c) {
      const double pressure_force =
          c == axis ? -scale * (far_field_pressure_ - settings_.reference_pressure) *
                          face_sums_[0][n] * outward
                    : 0.0;
      const double k = scale * (c == axis ? face_sums_[1][n] : face_sums_[2][n]);
      const double keep = 1.0 / (1.0 + k * dt / m);
      const double before = grid_.momentum[c][n];
      const double after = (before + pressure_force * dt) * keep;
      grid_.momentum[c][n] = after;
      grid_.force[c][n] += (after - before) / dt;  // so that (2-15) agrees
      ledger_.momentum[c] -= after - before;       // the face's impulse
      if (contact_ && cf.shared[n] >= 0) {
        for (int b = 0; b < cf.bodies; ++b) {
          const std::size_t at = cf.at(cf.shared[n], b);
          const double share = cf.mass[at] / m;
          const double body_before = cf.momentum[c][at];
          const double body_after = (body_before + share * pressure_force * dt) * keep;
          cf.momentum[c][at] = body_after;
          cf.force[c][at] += (body_after - body_before) / dt;
        }
      }
    }
  });
}

void MpmSolver::advance_shared_nodes(double dt) {
  using contact::Vec;
  auto& cf = contact_fields_;
  const int bodies = cf.bodies;
  auto& momentum = grid_.momentum;
  auto& force = grid_.force;
  parallel_for(cf.count(), [&](std::size_t index) {
    const auto k = static_cast<std::int32_t>(index);
    const std::size_t n = cf.node_of[index];
    // The forces added at the node (gravity, damping, tractions) go to the bodies
    // in proportion to their mass there.
    double extra[3] = {force[0][n], force[1][n], force[2][n]};
    for (int b = 0; b < bodies; ++b)
      for (int a = 0; a < 3; ++a) extra[a] -= cf.force[a][cf.at(k, b)];
    const double total_mass = grid_.mass[n];
    std::array<double, ContactFields::kMaxBodies> mass{};
    std::array<Vec<3>, ContactFields::kMaxBodies> p{}, grad{}, f{}, p_new{}, f_contact{};
    std::array<int, ContactFields::kMaxBodies> which{};
    int present = 0, normal = 0;
    for (int b = 0; b < bodies; ++b) {
      const std::size_t at = cf.at(k, b);
      if (!(cf.mass[at] > 0.0)) continue;
      for (int a = 0; a < 3; ++a) cf.force[a][at] += cf.mass[at] / total_mass * extra[a];
      const bool fixed = body_fixed_[static_cast<std::size_t>(b)] != 0;
      mass[present] = cf.mass[at] * (fixed ? kFixedMassFactor : 1.0);
      for (int a = 0; a < 3; ++a) {
        p[present](a) = cf.momentum[a][at];
        grad[present](a) = cf.gradient[a][at];
        f[present](a) = cf.force[a][at];
      }
      if (present == 0 || normal_rank_[static_cast<std::size_t>(b)] <
                              normal_rank_[static_cast<std::size_t>(which[normal])])
        normal = present;
      which[present++] = b;
    }
    const auto count = static_cast<std::size_t>(present);
    const contact::NodeBodies<3> node{std::span<const double>(mass.data(), count),
                                      std::span<const Vec<3>>(p.data(), count),
                                      std::span<const Vec<3>>(grad.data(), count)};
    // T (2-25)-(2-32); with one body present it is (2-13) alone.
    contact::advance_momentum_with_contact<3>(
        node, std::span<const Vec<3>>(f.data(), count), dt,
        {.friction = friction_, .normal_body = static_cast<std::size_t>(normal)},
        std::span<Vec<3>>(p_new.data(), count), std::span<Vec<3>>(f_contact.data(), count));
    double sum_p[3] = {0.0, 0.0, 0.0}, sum_f[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < present; ++i) {
      const std::size_t at = cf.at(k, which[i]);
      for (int a = 0; a < 3; ++a) {
        cf.momentum[a][at] = p_new[i](a);
        cf.force[a][at] += f_contact[i](a);
        sum_p[a] += cf.momentum[a][at];
        sum_f[a] += cf.force[a][at];
      }
    }
    for (int a = 0; a < 3; ++a) {
      momentum[a][n] = sum_p[a];
      force[a][n] = sum_f[a];
    }
  });
}

namespace {

/// Components a face holds at its nodes: wall all, symmetry the normal one.
int constrained_components(BoundaryKind kind, int axis) {
  if (kind == BoundaryKind::wall) return 7;
  if (kind == BoundaryKind::symmetry) return 1 << axis;
  return 0;
}

/// Zeroes the components in `mask` of p^{n+1} at `at` and sets the force to
/// -p^n / dt, so that (2-15) agrees with (2-13). Returns nothing; the caller books.
void hold(std::array<std::vector<double>, 3>& momentum, std::array<std::vector<double>, 3>& force,
          std::size_t at, int mask, double dt) {
  for (int c = 0; c < 3; ++c) {
    if (((mask >> c) & 1) == 0) continue;
    const double before = momentum[c][at] - force[c][at] * dt;  // p^n
    momentum[c][at] = 0.0;
    force[c][at] = -before / dt;
  }
}

}  // namespace

void MpmSolver::apply_node_constraints(double dt) {
  auto& cf = contact_fields_;
  const auto fully_held = [&](std::size_t n) {
    return has_fixed_ && fixed_mass_[n] > 0.0 && (!contact_ || cf.shared[n] < 0);
  };
  // Books what the constraint gives the free particles (those that apply
  // (2-15)): they receive (m_free / m) of the held node's -p^n, and the internal
  // forces f dt that the node no longer passes on. Walls: p^{n+1}, as before.
  const auto hold_node = [&](std::size_t n, int mask) {
    const double m = grid_.mass[n];
    const double free_share = has_fixed_ && m > 0.0 ? (m - fixed_mass_[n]) / m : 1.0;
    for (int c = 0; c < 3; ++c)
      if ((mask >> c) & 1) {
        const double f_dt = grid_.force[c][n] * dt;
        ledger_.momentum[c] += f_dt + free_share * (grid_.momentum[c][n] - f_dt);
      }
    hold(grid_.momentum, grid_.force, n, mask, dt);
    if (contact_ && cf.shared[n] >= 0)
      for (int b = 0; b < cf.bodies; ++b)
        hold(cf.momentum, cf.force, cf.at(cf.shared[n], b), mask, dt);
  };
  if (has_fixed_) {
    for (std::size_t n = 0; n < grid_.node_count(); ++n) {
      if (!(fixed_mass_[n] > 0.0)) continue;
      if (fully_held(n)) {
        hold_node(n, 7);
        continue;
      }
      // With contact only the fixed bodies' own fields are held; the others meet
      // them there. The free bodies lose what the fixed fields would have passed on.
      const std::int32_t k = cf.shared[n];
      for (int b = 0; b < cf.bodies; ++b) {
        if (body_fixed_[static_cast<std::size_t>(b)] == 0) continue;
        const std::size_t at = cf.at(k, b);
        for (int c = 0; c < 3; ++c) {
          ledger_.momentum[c] += cf.force[c][at] * dt;
          grid_.momentum[c][n] -= cf.momentum[c][at];
          const double before = cf.momentum[c][at] - cf.force[c][at] * dt;
          grid_.force[c][n] += -before / dt - cf.force[c][at];
        }
        hold(cf.momentum, cf.force, at, 7, dt);
      }
    }
  }
  for_each_face_node([&](std::size_t n, int axis, int, BoundaryKind kind) {
    if (fully_held(n)) return;
    if (const int mask = constrained_components(kind, axis); mask != 0) hold_node(n, mask);
  });
}

void MpmSolver::apply_face_conditions_to_remap() {
  auto& cf = contact_fields_;
  for_each_face_node([&](std::size_t n, int axis, int, BoundaryKind kind) {
    const int mask = constrained_components(kind, axis);
    for (int c = 0; c < 3; ++c) {
      if (((mask >> c) & 1) == 0) continue;
      grid_.remapped[c][n] = 0.0;
      if (contact_ && cf.shared[n] >= 0)
        for (int b = 0; b < cf.bodies; ++b) cf.remapped[c][cf.at(cf.shared[n], b)] = 0.0;
    }
  });
  if (!has_fixed_) return;
  for (std::size_t n = 0; n < grid_.node_count(); ++n) {
    if (!(fixed_mass_[n] > 0.0)) continue;
    const bool shared = contact_ && cf.shared[n] >= 0;
    for (int c = 0; c < 3; ++c) {
      if (!shared) {
        grid_.remapped[c][n] = 0.0;
        continue;
      }
      for (int b = 0; b < cf.bodies; ++b)
        if (body_fixed_[static_cast<std::size_t>(b)] != 0)
          cf.remapped[c][cf.at(cf.shared[n], b)] = 0.0;
    }
  }
}

void MpmSolver::update_and_remap_velocities(double dt) {
  auto& ps = particles_;
  const auto& accel = grid_.force;
  double* remapped[3] = {grid_.remapped[0].data(), grid_.remapped[1].data(),
                         grid_.remapped[2].data()};
  auto& cf = contact_fields_;
  // One pass: a particle's v^{n+1} needs only the nodal accelerations (read)
  // and its remap writes only the remapped momenta, so the two share a stencil.
  dispatch_kernel(settings_.shape_function != config::ShapeFunction::linear, axis_mask_, contact_,
                  [&](auto width, auto mask, auto with_contact) {
                    using S = Stencil<decltype(width)::value, decltype(mask)::value>;
                    constexpr bool kContact = decltype(with_contact)::value;
                    for_each_particle_by_colour(grid_, ps.size(), [&](std::size_t p) {
                      const int body = ps.body[p];
                      if (has_fixed_ && body_fixed_[static_cast<std::size_t>(body)] != 0) return;
                      const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
                      S s;
                      double half_width[3];
                      particle_half_width(p, half_width);
                      compute_stencil(x, half_width, geometry_, grid_, s);
                      double v[3] = {0.0, 0.0, 0.0};
                      for (int c = 0; c < S::kCount; ++c) {
                        const std::size_t node = s.node[c];
                        if constexpr (kContact) {
                          if (const std::int32_t k = cf.shared[node]; k >= 0) {
                            const std::size_t at = cf.at(k, body);
                            for (int i = 0; i < 3; ++i) v[i] += s.weight[c] * cf.force[i][at];
                            continue;
                          }
                        }
                        for (int i = 0; i < 3; ++i) v[i] += s.weight[c] * accel[i][node];
                      }
                      for (int i = 0; i < 3; ++i) {
                        v[i] = ps.velocity[i][p] + v[i] * dt;  // (2-15)
                        ps.velocity[i][p] = v[i];
                      }
                      const double m = ps.mass[p];
                      for (int c = 0; c < S::kCount; ++c) {
                        const std::size_t node = s.node[c];
                        const double wm = s.weight[c] * m;
                        for (int i = 0; i < 3; ++i) remapped[i][node] += wm * v[i];  // (2-17)
                        if constexpr (kContact) {
                          if (const std::int32_t k = cf.shared[node]; k >= 0) {
                            const std::size_t at = cf.at(k, body);
                            for (int i = 0; i < 3; ++i) cf.remapped[i][at] += wm * v[i];
                          }
                        }
                      }
                    });
                  });
  // The mass and momentum a coupler added (T (4-7), (4-8): the FDM cells next
  // to the zone as particles) move with the node's acceleration like any
  // particle; without them the remapped velocity of such a node is the
  // particles' momentum over particles + FDM mass, about half the flow speed
  // at the CFDMP face, and the particles next to it expand spuriously.
  for (const auto& added : added_node_state_)
    for (int a = 0; a < 3; ++a)
      remapped[a][added.node] += added.momentum[a] + added.mass * accel[a][added.node] * dt;
  // Per-body remapped velocities, not corrected by contact a second time (as
  // Nairn does): the thesis corrects at the momentum update only, and the second
  // correction, which changes the strain rates but not the particle velocities,
  // created energy (two elastic disks: +16 % at 20 cells, +9 % at 80; without it
  // the error falls with h: 6.5, 4.2, 2.2 %).
  if (contact_)
    parallel_for(cf.mass.size(), [&](std::size_t at) {
      const double inverse = cf.mass[at] > 0.0 ? 1.0 / cf.mass[at] : 0.0;
      for (int a = 0; a < 3; ++a) cf.remapped[a][at] *= inverse;
    });
  for_each_node(grid_.node_count(), [&](std::size_t n) {
    const double m = grid_.mass[n];
    const double inverse = m > 0.0 ? 1.0 / m : 0.0;
    for (int a = 0; a < 3; ++a) remapped[a][n] *= inverse;
  });
  apply_face_conditions_to_remap();
}

void MpmSolver::strain_first_half(double dt, bool scatter_forces) {
  auto& ps = particles_;
  auto& velocity = grid_.remapped;  // scratch until the remap: v_I^n = p_I / m_I
  for_each_node(grid_.node_count(), [&](std::size_t n) {
    const double m = grid_.mass[n];
    const double inverse = m > 0.0 ? 1.0 / m : 0.0;
    for (int a = 0; a < 3; ++a) velocity[a][n] = grid_.momentum[a][n] * inverse;
  });
  apply_face_conditions_to_remap();
  const double half = 0.5 * dt;
  const double t_half = time_ + half;
  leaving_.assign(ps.size(), 0);
  if (scatter_forces) zero_stress_sums();
  double* force[3] = {grid_.force[0].data(), grid_.force[1].data(), grid_.force[2].data()};
  // One pass in the scatter's order: a particle's strain reads only v_I^n, and
  // its force, of the stress it has just reached, is summed in the same order
  // as a second full scatter would (same values, bit for bit); m_I and p_I
  // have not changed and are not summed again.
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        using S = Stencil<decltype(width)::value, decltype(mask)::value>;
        for_each_particle_by_colour(grid_, ps.size(), [&](std::size_t p) {
          const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
          S s;
          double half_width[3];
          particle_half_width(p, half_width);
          compute_stencil(x, half_width, geometry_, grid_, s);
          if (!has_fixed_ || body_fixed_[ps.body[p]] == 0) {
            Tensor3 l = Tensor3::Zero();
            for (int c = 0; c < S::kCount; ++c)
              for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) l(i, j) += velocity[i][s.node[c]] * s.gradient[c][j];
            if (!strain_particle(p, l, half, t_half)) leaving_[p] = 1;
          }
          if (!scatter_forces) return;
          double sigma[3][3];
          const double volume = internal_stress(p, sigma);
          for (int c = 0; c < S::kCount; ++c) {
            const double* gr = s.gradient[c];
            for (int i = 0; i < 3; ++i) {  // (2-10), as particles_to_grid sums it
              const double f =
                  -volume * (sigma[i][0] * gr[0] + sigma[i][1] * gr[1] + sigma[i][2] * gr[2]);
              force[i][s.node[c]] += f;
            }
          }
          scatter_stress_sums(p, x, s);
        });
      });
  const auto collapsed =
      static_cast<std::size_t>(std::count(leaving_.begin(), leaving_.end(), std::uint8_t{1}));
  if (collapsed > 0) throw_collapsed(collapsed, t_half);
  for_each_node(grid_.node_count(), [&](std::size_t n) {
    for (int a = 0; a < 3; ++a) velocity[a][n] = 0.0;  // the remap sums into it
  });
}

void MpmSolver::update_particles(double dt) {
  auto& ps = particles_;
  const bool usl = settings_.update == config::MpmUpdate::usl;
  const auto& position_velocity = grid_.momentum;  // p^{n+1} / m, (2-16)
  const auto& strain_velocity = usl ? grid_.momentum : grid_.remapped;
  const auto& accel = grid_.force;
  const auto& cf = contact_fields_;
  const auto& body_position_velocity = cf.momentum;
  const auto& body_strain_velocity = usl ? cf.momentum : cf.remapped;
  const auto& body_accel = cf.force;
  const auto& g = grid_.grid();
  const bool active[3] = {g.is_active(0), g.is_active(1), g.is_active(2)};
  const double t1 = time_ + dt;
  // USAVG strained the first half in strain_first_half.
  const double strain_dt = settings_.update == config::MpmUpdate::usavg ? 0.5 * dt : dt;
  std::size_t collapsed = 0;
  leaving_.assign(ps.size(), 0);  // scratch here: marks collapsed particles
  dispatch_kernel(settings_.shape_function != config::ShapeFunction::linear, axis_mask_, contact_,
                  [&](auto width, auto mask, auto with_contact) {
                    using S = Stencil<decltype(width)::value, decltype(mask)::value>;
                    constexpr bool kContact = decltype(with_contact)::value;
                    collapsed = parallel_sum(ps.size(), [&](std::size_t p) -> std::size_t {
                      const int body_index = ps.body[p];
                      // A fixed particle set stays where it is, at rest, unstrained.
                      if (has_fixed_ && body_fixed_[static_cast<std::size_t>(body_index)] != 0)
                        return 0;
                      const double x[3] = {ps.position[0][p], ps.position[1][p], ps.position[2][p]};
                      S s;
                      double half_width[3];
                      particle_half_width(p, half_width);
                      compute_stencil(x, half_width, geometry_, grid_, s);
                      double dx[3] = {0.0, 0.0, 0.0};
                      double dv[3] = {0.0, 0.0, 0.0};
                      Tensor3 l = Tensor3::Zero();  // velocity gradient sum_I v_iI N_I,j
                      for (int c = 0; c < S::kCount; ++c) {
                        const std::vector<double>* vx = position_velocity.data();
                        const std::vector<double>* ve = strain_velocity.data();
                        const std::vector<double>* va = accel.data();
                        std::size_t at = s.node[c];
                        if constexpr (kContact) {
                          if (const std::int32_t k = cf.shared[at]; k >= 0) {
                            vx = body_position_velocity.data();
                            ve = body_strain_velocity.data();
                            va = body_accel.data();
                            at = cf.at(k, body_index);
                          }
                        }
                        for (int i = 0; i < 3; ++i) {
                          dx[i] += s.weight[c] * vx[i][at];
                          if (usl) dv[i] += s.weight[c] * va[i][at];
                          for (int j = 0; j < 3; ++j) l(i, j) += ve[i][at] * s.gradient[c][j];
                        }
                      }
                      for (int i = 0; i < 3; ++i) {
                        if (active[i]) ps.position[i][p] += dx[i] * dt;  // (2-16)
                        if (usl) ps.velocity[i][p] += dv[i] * dt;        // (2-15), USL
                      }
                      if (strain_particle(p, l, strain_dt, t1)) return 0;
                      leaving_[p] = 1;
                      return 1;
                    });
                  });
  if (collapsed > 0) throw_collapsed(collapsed, t1);
}

bool MpmSolver::strain_particle(std::size_t p, const Tensor3& l, double dt, double t1) {
  auto& ps = particles_;
  StrainStep step;
  step.strain_increment = 0.5 * (l + l.transpose()) * dt;  // (2-18)
  const Tensor3 spin = 0.5 * (l - l.transpose()) * dt;     // (2-19)
  const double volumetric = step.strain_increment.trace();
  if (!(1.0 + volumetric > 0.0)) return false;
  for (int i = 0; i < 3; ++i)  // F_ii, the cpGIMP domain stretch
    ps.stretch[i][p] *= 1.0 + step.strain_increment(i, i);
  step.dt = dt;
  step.density_old = ps.density[p];
  step.density_new = ps.density[p] / (1.0 + volumetric);  // (2-20)
  step.bulk_viscosity = viscosity_(volumetric / dt, step.density_new, ps.sound_speed[p]);
  step.burn_fraction = mpm::burn_fraction(t1, ps.lighting_time[p], bodies_[ps.body[p]].burn_rate);
  // (2-21): the Jaumann rotation of the deviator, sigma_ik dW_jk + sigma_jk dW_ik;
  // the isotropic part of sigma is unchanged by it.
  Tensor3 dev = ps.deviator(p);
  dev += dev * spin.transpose() + spin * dev;
  MaterialPoint point = ps.material_point(p, dev);
  models_[ps.material[p]]->update(step, point);
  ps.set_deviator(p, dev);
  ps.density[p] = step.density_new;
  ps.bulk_viscosity[p] = step.bulk_viscosity;
  return true;
}

void MpmSolver::throw_collapsed(std::size_t count, double t1) const {
  const auto& ps = particles_;
  const auto p = static_cast<std::size_t>(
      std::find(leaving_.begin(), leaving_.end(), std::uint8_t{1}) - leaving_.begin());
  char text[512];
  std::snprintf(
      text, sizeof text,
      "mpm: %zu particle(s) collapsed (1 + tr(d eps) <= 0) in the step to t = %.6g s "
      "(step %lld), the first particle %zu (body '%s') at (%.6g, %.6g, %.6g) m, "
      "density %.6g kg/m^3 and pressure %.6g Pa before this strain update; lower time.cfl",
      count, t1, static_cast<long long>(steps_ + 1), p, bodies_[ps.body[p]].name.c_str(),
      ps.position[0][p], ps.position[1][p], ps.position[2][p], ps.density[p], ps.pressure[p]);
  throw Error(text);
}

void MpmSolver::remove_outflow() {
  auto& ps = particles_;
  const auto& g = grid_.grid();
  leaving_.assign(ps.size(), 0);
  const grid::Vec3 upper = g.upper();
  const std::size_t leaving = parallel_sum(ps.size(), [&](std::size_t p) -> std::size_t {
    for (int a = 0; a < 3; ++a) {
      if (!g.is_active(a)) continue;
      double& x = ps.position[a][p];
      const int side = x < g.origin()[a] ? 0 : x >= upper[a] ? 1 : -1;
      if (side < 0) continue;
      if (const BoundaryKind kind = faces_[static_cast<std::size_t>(2 * a + side)];
          kind == BoundaryKind::outflow || kind == BoundaryKind::non_reflecting) {
        leaving_[p] = 1;
        return 1;
      }
      // A closed face: the nodal condition keeps particles in; round-off may not.
      x = side == 0 ? g.origin()[a] : upper[a] - 1e-9 * g.spacing()[a];
    }
    return 0;
  });
  if (leaving == 0) return;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    if (leaving_[p] == 0) continue;
    const double m = ps.mass[p];
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      ledger_.momentum[a] += m * ps.velocity[a][p];
      v2 += ps.velocity[a][p] * ps.velocity[a][p];
    }
    ledger_.mass += m;
    ledger_.energy += m * (0.5 * v2 + ps.specific_internal_energy[p]);
  }
  ledger_.particles_removed += static_cast<std::int64_t>(ps.remove_flagged(leaving_));
}

bool MpmSolver::physical(std::size_t p) const {
  const auto& ps = particles_;
  const double v2 = ps.velocity[0][p] * ps.velocity[0][p] + ps.velocity[1][p] * ps.velocity[1][p] +
                    ps.velocity[2][p] * ps.velocity[2][p];
  const bool finite =
      std::isfinite(v2 + ps.sound_speed[p] + ps.pressure[p] + ps.specific_internal_energy[p] +
                    ps.position[0][p] + ps.position[1][p] + ps.position[2][p]);
  // An ideal gas cannot hold tension: p < 0 means e < 0, T (2-59).
  return finite && ps.density[p] > 0.0 && !(gas_[ps.material[p]] != 0 && ps.pressure[p] < 0.0);
}

double MpmSolver::signal_speed(std::size_t p) const {
  const auto& ps = particles_;
  const double v2 = ps.velocity[0][p] * ps.velocity[0][p] + ps.velocity[1][p] * ps.velocity[1][p] +
                    ps.velocity[2][p] * ps.velocity[2][p];
  return ps.sound_speed[p] + std::sqrt(v2);
}

void MpmSolver::compute_stable_dt(std::size_t first) {
  double fastest = first > 0 ? fastest_speed_ : 0.0;
  std::size_t unphysical = 0;
  const auto begin = static_cast<std::ptrdiff_t>(first);
  const auto count = static_cast<std::ptrdiff_t>(particles_.size());
#pragma omp parallel for schedule(static) reduction(max : fastest) reduction(+ : unphysical) \
    if (count - begin >= kMinParallelCount)
  for (std::ptrdiff_t i = begin; i < count; ++i) {
    const auto p = static_cast<std::size_t>(i);
    fastest = std::max(fastest, signal_speed(p));
    unphysical += physical(p) ? 0 : 1;
  }
  // std::max drops a NaN speed: without this check a broken particle would
  // neither limit the step nor stop the run.
  if (unphysical > 0) throw_unphysical(unphysical);
  fastest_speed_ = fastest;
  stable_dt_ = fastest > 0.0 ? settings_.cfl * min_spacing_ / fastest
                             : std::numeric_limits<double>::infinity();
}

void MpmSolver::throw_unphysical(std::size_t count) const {
  const auto& ps = particles_;
  std::size_t p = 0;
  while (p + 1 < ps.size() && physical(p)) ++p;
  char text[512];
  std::snprintf(text, sizeof text,
                "mpm: unphysical state of particle %zu (id %llu, body '%s', material '%s') at "
                "(%.6g, %.6g, %.6g) m, t = %.6g s (step %lld): density %.6g kg/m^3, pressure "
                "%.6g Pa, specific internal energy %.6g J/kg, velocity (%.6g, %.6g, %.6g) m/s "
                "(%zu particle(s) so); density and energy must stay positive and finite. Reduce "
                "time.cfl or refine the grid.",
                p, static_cast<unsigned long long>(ps.id[p]), bodies_[ps.body[p]].name.c_str(),
                materials_[ps.material[p]].name.c_str(), ps.position[0][p], ps.position[1][p],
                ps.position[2][p], time_, static_cast<long long>(steps_), ps.density[p],
                ps.pressure[p], ps.specific_internal_energy[p], ps.velocity[0][p],
                ps.velocity[1][p], ps.velocity[2][p], count);
  throw Error(text);
}

MpmTotals MpmSolver::totals() const {
  const auto& ps = particles_;
  MpmTotals t;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double m = ps.mass[p];
    t.mass += m;
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      t.momentum[a] += m * ps.velocity[a][p];
      v2 += ps.velocity[a][p] * ps.velocity[a][p];
    }
    t.kinetic_energy += 0.5 * m * v2;
    t.internal_energy += m * ps.specific_internal_energy[p];
  }
  return t;
}

}  // namespace mpfd::mpm
