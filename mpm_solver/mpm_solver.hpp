#pragma once
// Explicit MPM on a sparse background grid, T §2.1.2, one step = (2-9)-(2-21):
//
//   1. rebuild_grid()         blocks where particles are; particles binned by block;
//                             with contact, the nodes two bodies' stencils reach are marked
//   2. particles_to_grid()    m_I (2-12), p_I (2-9), f_I = f_int (2-10); at marked nodes
//                             also per body m^b, p^b, f^b and the mass gradient (2-23)
//   3. integrate_nodes()      f_I += gravity, the shear-mode damping (2-33)-(2-48) and
//                             the non-reflecting tractions (W §2.4); p_I^{n+1} = p_I + f_I dt
//                             (2-13), at shared nodes per body with the contact force
//                             (2-25)-(2-32); then faces and fixed particle sets
//   4. update_and_remap_velocities()
//                             v_p += sum f_I / m_I N_Ip dt (2-15) (f^b + f^{b,c} of the
//                             particle's body at shared nodes), and in the same particle
//                             pass (MUSL) the remap sum m_p N_Ip v_p^{n+1} (2-17), per body
//                             at shared nodes;
//   5.                        then / m_I and the face conditions
//   6. update_particles()     x_p += sum p_I^{n+1} / m_I N_Ip dt (2-16); strain and spin
//                             increments (2-18), (2-19) from the step-5 (MUSL) or
//                             step-3 (USL) nodal velocities (its body's at shared nodes);
//                             density (2-20); bulk viscosity; Jaumann rotation and the
//                             constitutive model (2-21) with the program burn (3-1), (3-2)
//   7. remove_outflow()       particles that left through an outflow or non-reflecting face
//
// A coupler's ghost-node export may run steps 1 and 2 early, at the end of the
// previous step (map_next_step); the advance then starts from step 3.
//
// In a coupled run (mpm_solver serve) a coupler's nodal contributions
// (queue_node_load, T (4-7)...(4-9), T §4.3 steps 3 and 5) act between steps 2
// and 3: after (2-9)-(2-12) have mapped the particles, before (2-13). Without
// them a step is the standalone step, bit for bit.
//
// USAVG (Nairn 2003; Wallstedt & Guilkey 2008): step 2 sums only m_I and p_I;
// the coupler's mass and momentum loads are added; then strain_first_half():
// half the strain increment from v_I^n = p_I / m_I, dt / 2, and in the same
// particle pass the forces f_I of the half-updated stress (the coupler's force
// loads follow; with cpGIMP, whose weights follow the strain, step 2 is redone
// whole instead); step 6 then strains with the other half, from the step-5
// velocities. The pressure work is then sigma^{n+1/2} : (v^n + v^{n+1}) / 2,
// what the kinetic energy gained.
//
// USL skips steps 4 and 5 and does (2-15) in step 6. All weights are N^n (the
// particles' positions at the start of the step). Nothing is allocated inside a
// step once the grid's arrays have reached their largest size.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "common/config/scene.hpp"
#include "mpm_solver/bulk_viscosity.hpp"
#include "mpm_solver/contact_fields.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/particle_batch.hpp"
#include "mpm_solver/particle_generation.hpp"
#include "mpm_solver/particle_stencil.hpp"
#include "mpm_solver/sparse_grid.hpp"

namespace mpfd::mpm {

struct MpmSettings {
  double cfl = config::kMpmDefaultCfl;  ///< dt = cfl h_min / max_p (c_p + |v_p|)
  config::ShapeFunction shape_function = config::ShapeFunction::linear;
  /// MUSL when built by hand; a scene's default is usavg (config::MpmOptions, from_scene).
  config::MpmUpdate update = config::MpmUpdate::musl;
  double bulk_viscosity_quadratic = 1.5;  ///< c0
  double bulk_viscosity_linear = 0.06;    ///< c1
  double shear_damping = 0.0;             ///< Q_s of T (2-48); 0: off
  double reference_pressure = 0.0;        ///< p_ref off the stress in the internal force [Pa]

  /// The settings a scene asks for.
  static MpmSettings from_scene(const config::Scene& scene);
};

/// The scene-file name of a shape function: "linear", "gimp", "cpgimp".
[[nodiscard]] inline const char* shape_function_name(config::ShapeFunction f) {
  switch (f) {
    case config::ShapeFunction::gimp:
      return "gimp";
    case config::ShapeFunction::cpgimp:
      return "cpgimp";
    case config::ShapeFunction::linear:
      break;
  }
  return "linear";
}

/// The scene-file name of an update scheme: "musl", "usl", "usavg".
[[nodiscard]] inline const char* update_name(config::MpmUpdate u) {
  switch (u) {
    case config::MpmUpdate::usl:
      return "usl";
    case config::MpmUpdate::usavg:
      return "usavg";
    case config::MpmUpdate::musl:
      break;
  }
  return "musl";
}

/// What the domain holds: mass, momentum, kinetic and internal energy.
struct MpmTotals {
  double mass = 0.0;                 ///< [kg]
  std::array<double, 3> momentum{};  ///< [kg m/s]
  double kinetic_energy = 0.0;       ///< [J]
  double internal_energy = 0.0;      ///< sum m_p e_p [J]
};

/// What crossed the domain's faces since the start (positive: out of the domain).
struct BoundaryLedger {
  double mass = 0.0;  ///< carried out by removed particles [kg]
  /// carried out, minus the impulse walls, non-reflecting faces and fixed particle
  /// sets gave [kg m/s] (gravity's impulse is not booked)
  std::array<double, 3> momentum{};
  double energy = 0.0;  ///< kinetic + internal energy carried out [J]
  std::int64_t particles_removed = 0;
};

/// Mass and momentum a node holds after the particles are mapped to the grid.
struct NodeState {
  double mass = 0.0;                 ///< m_I (2-12) [kg]
  std::array<double, 3> momentum{};  ///< p_I (2-9) [kg m/s]
};

/// Node mass and momentum of a box of grid nodes (MpmSolver::map_particles_to_node_box,
/// MpmSolver::read_next_step_box).
/// Kept by the caller between calls: after the first, filling it allocates nothing.
struct NodeBoxMap {
  std::vector<double> mass;      ///< m_I (2-12) per node [kg]
  std::vector<double> momentum;  ///< p_I (2-9), 3 per node [kg m/s]
  /// e_I = sum_p N_Ip m_p e_p, the particles' internal energy mapped as (2-12) [J]
  std::vector<double> internal_energy;
  /// The particles whose stencil reaches the box, in index order.
  std::vector<std::int32_t> reaching;
  std::vector<std::int32_t> by_colour;  ///< scratch: `reaching` in summation order

  /// Sizes the node arrays to the box [lo, hi) and zeroes them; empties `reaching`.
  void reset(const grid::Index3& lo, const grid::Index3& hi) {
    const std::size_t nodes = static_cast<std::size_t>(hi[0] - lo[0]) *
                              static_cast<std::size_t>(hi[1] - lo[1]) *
                              static_cast<std::size_t>(hi[2] - lo[2]);
    mass.assign(nodes, 0.0);
    momentum.assign(3 * nodes, 0.0);
    internal_energy.assign(nodes, 0.0);
    reaching.clear();
  }
};

class MpmSolver {
 public:
  /// Particles from the scene's bodies and charges (particle_generation.hpp),
  /// with a constitutive model per material used. Throws mpfd::Error for a
  /// scene this solver cannot run.
  MpmSolver(const config::Scene& scene, MpmSettings settings);
  ~MpmSolver();
  MpmSolver(const MpmSolver&) = delete;
  MpmSolver& operator=(const MpmSolver&) = delete;

  /// cfl * h_min / max_p (c_p + |v_p|) [s] at the current state.
  [[nodiscard]] double stable_dt() const { return stable_dt_; }
  /// The step to take toward `target` [s]: stable_dt, or the time left, or
  /// half of it when one more full step would leave a sliver.
  [[nodiscard]] double step_toward(double target) const;
  /// One step of size dt [s]. Throws mpfd::Error if a particle's volume collapses.
  void advance(double dt);
  void advance_to(double end);

  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] std::int64_t steps() const { return steps_; }
  /// Sum over steps of the particles updated [-].
  [[nodiscard]] double particle_updates() const { return particle_updates_; }
  [[nodiscard]] const ParticleSet& particles() const { return particles_; }
  [[nodiscard]] const std::vector<BodyInfo>& bodies() const { return bodies_; }
  [[nodiscard]] const grid::UniformGrid& grid() const { return grid_.grid(); }
  [[nodiscard]] const SparseGrid& sparse_grid() const { return grid_; }
  [[nodiscard]] const MpmSettings& settings() const { return settings_; }
  [[nodiscard]] MpmTotals totals() const;
  [[nodiscard]] const BoundaryLedger& boundary_ledger() const { return ledger_; }
  /// Burn fraction F (T (3-2)) of particle p now.
  [[nodiscard]] double burn_fraction(std::size_t p) const;

  // --- Coupling (mpm_solver serve, proto/README.md §6). A standalone run calls none of these.

  /// Appends particles (T (4-15)...(4-18)): density m/V, e = E/m, pressure and
  /// sound speed from their material's model; with a stress, p = -tr(sigma)/3
  /// and the deviator from it instead. They join the inert body "injected
  /// <material>" (GIMP half-width of two particles per cell). Throws
  /// mpfd::Error naming the first bad particle (non-positive mass or volume,
  /// unknown material, position off the grid) before anything is added.
  void inject_particles(const ParticleBatch& batch);
  /// Removes the particles whose flag is not 0 and returns their state (not
  /// booked as outflow: the coupler takes them over).
  [[nodiscard]] ParticleBatch remove_particles(std::span<const std::uint8_t> flags);
  /// Maps the particles to the grid as step 2 does, so that node_state reads
  /// the current state; the next advance maps again.
  void map_particles_to_nodes();
  /// A grid node's mass and momentum after map_particles_to_nodes (zero
  /// where no particle's stencil reaches). `node`: grid node indices.
  [[nodiscard]] NodeState node_state(const grid::Index3& node) const;
  /// map_particles_to_nodes then node_state over the grid-node box [lo, hi),
  /// bit for bit, mapping only the particles whose stencil reaches the box, in
  /// the scatter's summation order (home-block colour, then particle index).
  /// Fills `out` (C order over the box, k fastest) and leaves the grid as it was.
  void map_particles_to_node_box(const grid::Index3& lo, const grid::Index3& hi,
                                 NodeBoxMap& out) const;
  /// Maps the particles to the grid as the next advance's step 2 would
  /// (rebuild, (2-12), (2-9), and with MUSL/USL (2-10)), so that the advance
  /// starts from this map instead of mapping again, and sums over the grid-node
  /// box [lo, hi) e_I = sum_p N_Ip m_p e_p as (2-12). A coupler exports its
  /// ghost nodes from it (read_next_step_box): the step's own scatter, not a
  /// second one. Particles injected before the advance are added to the map
  /// after the others, so its sums differ from a fresh map in the last bits;
  /// a removal, a restore, map_particles_to_nodes, an injection that reaches a
  /// block the map lacks, or a load on a node of such a block makes the
  /// advance map afresh.
  void map_next_step(const grid::Index3& lo, const grid::Index3& hi);
  /// Whether the next advance starts from a map of map_next_step's.
  [[nodiscard]] bool has_next_step_map() const { return next_map_.valid; }
  /// For a checkpoint: the grid-node box [lo, hi) of that map, which a restored
  /// run maps again (and then adds later injections in the same order). A map
  /// that already holds injected particles cannot be remade so: it is dropped
  /// (this run then maps afresh too) and nothing is returned.
  [[nodiscard]] std::optional<std::array<grid::Index3, 2>> next_step_map_for_checkpoint();
  /// Whether the next advance starts from map_next_step's map of the box [lo, hi).
  [[nodiscard]] bool next_step_mapped(const grid::Index3& lo, const grid::Index3& hi) const;
  /// The box's node mass, momentum and e_I from map_next_step's map, as
  /// map_particles_to_node_box fills them, bit for bit (C order over the box,
  /// k fastest; `reaching` is left empty). Requires next_step_mapped(lo, hi).
  void read_next_step_box(const grid::Index3& lo, const grid::Index3& hi, NodeBoxMap& out) const;
  /// Whether the last advance started from map_next_step's map.
  [[nodiscard]] bool last_advance_was_premapped() const { return last_advance_premapped_; }
  /// Queues a contribution for the next advance, applied in queue order
  /// after (2-12) and before (2-13) (see the step order above).
  void queue_node_load(const NodeLoad& load);
  [[nodiscard]] std::size_t queued_node_loads() const { return node_loads_.size(); }
  /// Bodies from the scene; later ones were made by inject_particles.
  [[nodiscard]] std::size_t scene_body_count() const { return scene_bodies_; }
  /// Replaces the state with a checkpoint's: particles, the materials of the
  /// injected bodies (in body order), clock, ledger. Throws mpfd::Error,
  /// leaving the state as it was, if they do not fit this scene (a body,
  /// material or history width it lacks) or a particle lies off the grid or at
  /// a non-finite position.
  void restore(ParticleSet particles, std::span<const std::size_t> injected_body_materials,
               double time, std::int64_t steps, const BoundaryLedger& ledger,
               double particle_updates);

 private:
  void rebuild_grid();
  /// Storage coordinates of the first and last node of particle p's stencil (rebuild_grid's
  /// blocks).
  void stencil_box(std::size_t p, grid::Index3& lo, grid::Index3& hi) const;
  /// GIMP half-widths of particle p per axis [grid units]: its body's, times F_aa for cpGIMP.
  void particle_half_width(std::size_t p, double half_width[3]) const;
  void mark_shared_nodes();
  /// What particles_to_grid sums: everything, or (USAVG's first scatter) only
  /// what the stress does not change: m_I, p_I, the contact fields' mass,
  /// momentum and mass gradient, the fixed particle sets' mass.
  enum class Scatter { all, mass_and_momentum };
  /// What step 2 scatters first: USAVG only m_I and p_I, the others everything.
  [[nodiscard]] Scatter first_scatter() const {
    return settings_.update == config::MpmUpdate::usavg ? Scatter::mass_and_momentum : Scatter::all;
  }
  /// Zeroes the per-node sums of the scenes that need them and scatters every particle.
  void particles_to_grid(Scatter what = Scatter::all);
  /// Which particles scatter_particles takes: all, block by block in colour
  /// order, or those appended to a map (from its `first` on, in index order).
  enum class ScatterOrder { by_colour, appended };
  /// The scatter of particles_to_grid. With next_map_.valid it also sums e_I over its box.
  void scatter_particles(Scatter what, ScatterOrder order, std::size_t first = 0);
  /// Adds the particles from `first` on to map_next_step's map, or drops the
  /// map when one reaches a block it lacks.
  void add_to_next_step_map(std::size_t first);
  /// Whether every queued load lies on a node of the grid's blocks.
  [[nodiscard]] bool loads_on_mapped_blocks() const;
  /// Zeroes the stress-dependent per-node sums of the scenes that need them
  /// (shear-mode damping's cells, non-reflecting faces').
  void zero_stress_sums();
  /// Particle p's stress sigma + p_ref I of the internal force (2-10); returns its volume.
  double internal_stress(std::size_t p, double (&sigma)[3][3]) const;
  /// Particle p's share of the stress-dependent sums zero_stress_sums zeroes.
  template <class S>
  void scatter_stress_sums(std::size_t p, const double (&x)[3], const S& s);
  void integrate_nodes(double dt);
  /// Adds the shear-mode damping forces, T (2-47), over the cells holding particles.
  void add_shear_damping(double dt);
  /// The non-reflecting faces' tractions on p^{n+1} of their nodes, W (2-59), (2-60).
  void add_boundary_tractions(double dt);
  /// At shared nodes: hands the external forces to the bodies by mass and
  /// replaces (2-13) by the contact update, T (2-25)-(2-32).
  void advance_shared_nodes(double dt);
  /// Zeroes the constrained components at nodes on fixed and symmetry faces and
  /// at nodes of fixed particle sets; resets the force so that (2-15) agrees with (2-13).
  void apply_node_constraints(double dt);
  void apply_face_conditions_to_remap();
  void update_and_remap_velocities(double dt);
  /// USAVG's first half: strain, density and stress with dt / 2 from v_I^n
  /// (with the coupler's mass and momentum), and with `scatter_forces` the
  /// internal forces of the half-updated stress in the same particle pass.
  void strain_first_half(double dt, bool scatter_forces);
  void update_particles(double dt);
  /// Strain increment (2-18), spin (2-19), density (2-20), bulk viscosity and the
  /// constitutive model (2-21) of particle p over `dt` from its velocity gradient
  /// `l`, the burn at `t1`. False (nothing changed) if the particle collapses.
  bool strain_particle(std::size_t p, const Tensor3& l, double dt, double t1);
  /// Throws mpfd::Error naming the first particle leaving_ marks as collapsed.
  [[noreturn]] void throw_collapsed(std::size_t count, double t1) const;
  void remove_outflow();
  /// The CFL step from the fastest particle (c + |v|); with first > 0 only the
  /// particles from `first` on are visited and the others' speed is the one last
  /// computed (particles appended since). Throws (throw_unphysical) if a visited
  /// particle is unphysical.
  void compute_stable_dt(std::size_t first = 0);
  /// Reserves the per-particle scratch's capacity for the present particle
  /// count, doubling it: injection adds a few particles every step, and
  /// reserving the exact count reallocated (and page-faulted) it each time.
  void reserve_particle_scratch();
  /// c + |v| of particle p [m/s].
  [[nodiscard]] double signal_speed(std::size_t p) const;
  /// Particle p's state is finite, its density positive and, in an ideal gas, its pressure not
  /// negative.
  [[nodiscard]] bool physical(std::size_t p) const;
  /// Throws mpfd::Error naming the first of the `count` unphysical particles and its state.
  [[noreturn]] void throw_unphysical(std::size_t count) const;
  /// The model of `material`, made (and the history stride widened) on first use.
  ConstitutiveModel& model_for(std::size_t material);
  /// The body injected particles of `material` join, made on first use.
  std::uint16_t injected_body(std::size_t material);
  /// Throws mpfd::Error naming `what` when the zone has contact (which does not
  /// support a coupler's loads yet).
  void refuse_unsupported_coupling(const char* what) const;
  /// Which queued loads apply_node_loads applies: USAVG takes the mass and
  /// momentum loads before its first half-strain and the force loads after
  /// its force scatter; MUSL and USL take all at once.
  enum class NodeLoadPass { all, mass_and_momentum, force };
  /// Adds the queued loads of `pass` to (or sets) the nodal sums.
  void apply_node_loads(NodeLoadPass pass);
  /// Keeps the mass and momentum the queued loads add, for the remap: once a step.
  void record_added_node_state();
  template <class Fn>
  void for_each_face_node(const Fn& fn) const;

  MpmSettings settings_;
  std::array<config::BoundaryKind, 6> faces_{};
  SparseGrid grid_;
  StencilGeometry geometry_;
  int axis_mask_ = 0;
  double min_spacing_ = 0.0;
  BulkViscosity viscosity_;
  ParticleSet particles_;
  std::vector<BodyInfo> bodies_;
  std::vector<std::unique_ptr<ConstitutiveModel>> models_;  // by material index; null if unused
  std::vector<config::Material> materials_;                 // the scene's, for models made later
  std::vector<std::uint8_t> gas_;  // per material: 1 for an ideal gas (no tension)
  std::size_t scene_bodies_ = 0;
  std::vector<NodeLoad> node_loads_;  // for the next advance
  /// Mass and momentum a coupler added to nodes this step (node slot, dm, dp): a
  /// virtual particle (the FDM cells of T (4-7), (4-8)) that the MUSL remap must see too.
  struct AddedNodeState {
    std::size_t node;
    double mass;
    std::array<double, 3> momentum;
  };
  std::vector<AddedNodeState> added_node_state_;
  std::vector<std::int32_t> added_slot_;  // per node: its entry in added_node_state_, or -1
  /// map_next_step's map: valid until the advance that uses it or a change it
  /// cannot follow; e_I summed over the storage-coordinate node box [lo, hi).
  struct NextStepMap {
    bool valid = false;
    grid::Index3 lo{}, hi{};
    std::size_t appended = 0;  ///< particles injected onto it
  };
  NextStepMap next_map_;
  std::vector<double> next_map_energy_;  // per node: e_I over next_map_'s box [J]
  bool last_advance_premapped_ = false;
  std::vector<std::int32_t> home_slot_;  // scratch, per particle
  std::vector<std::uint8_t> leaving_;    // scratch, per particle
  double stable_dt_ = 0.0;
  double fastest_speed_ = 0.0;  ///< max over particles of c + |v| when stable_dt_ was set
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  double particle_updates_ = 0.0;
  BoundaryLedger ledger_;

  // Physics the scene switches on; each costs nothing when off.
  std::array<double, 3> gravity_{};
  bool contact_ = false;
  double friction_ = 0.0;
  std::vector<int> normal_rank_;  ///< per body: smaller gives the contact normal first
  ContactFields contact_fields_;
  std::vector<std::uint8_t> body_fixed_;  ///< per body
  bool has_fixed_ = false;
  std::vector<double> fixed_mass_;  ///< per node: sum N m_p of fixed particles
  std::vector<double> cell_mass_;   ///< per node: sum m_p of the cell it is the lower corner of
  std::vector<double> cell_sound_speed_;  ///< per node: the largest c_p in that cell
  bool non_reflecting_ = false;
  double far_field_pressure_ = 0.0;               ///< p of `initial` [Pa]
  std::vector<double> body_shear_modulus_;        ///< per body [Pa], for c_s
  std::array<std::vector<double>, 3> face_sums_;  ///< per node: sum N V_p, N m_p c_p, N m_p c_s
};

}  // namespace mpfd::mpm
