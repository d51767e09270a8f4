#pragma once
// One coupled CFDMP step, T §4.3 steps 1-14, as the two Exchange messages of
// proto/README.md §6 and the reading of their replies. The coupler keeps what
// crosses between steps: the strip_cells of t^{n-1} and t^n, the ghost_nodes of
// t^n, the particles removed in the last step and the face parcels.
//   FDM: [apply deposit_cells ADD, apply ghost_cells SET, advance, export strip_cells,
//         (export beyond_cells: uGIMP), (export coupling_face: v1.1), (export fdm_owned),
//         propose_dt]
//   MPM: [inject "injected", apply interface_nodes ADD, (apply outer_nodes ADD: uGIMP),
//         advance, export face_particles, remove "crossed" (left mpm_zone),
//         export ghost_nodes (the MPM maps its next step for it), (export mpm_zone),
//         propose_dt]
// A step without advance (step 0, and the one before each output) keeps only the
// applies of deposits, the exports and the proposals. While the MPM zone is
// dormant (coupler/run/activation.hpp) only the FDM gets a request: advance,
// export strip_cells, (export fdm_owned and dormant_zone), propose_dt; the
// gauges (run/gauges.hpp) append SampleGauges to either request when due.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "cosim/message.hpp"
#include "coupler/handshake/ghost_cells.hpp"
#include "coupler/handshake/injection_flux.hpp"
#include "coupler/handshake/interface_nodes.hpp"
#include "coupler/handshake/particle_injection.hpp"
#include "coupler/handshake/strip_layout.hpp"
#include "coupler/run/face_drain.hpp"
#include "coupler/run/injected_material.hpp"
#include "coupler/run/restart_file.hpp"
#include "coupler/run/zone_layout.hpp"

namespace mpfd::coupler {

/// Mass [kg], momentum [kg m/s] (3 axes) and total energy [J].
struct Totals {
  double mass = 0;
  std::array<double, 3> momentum{};
  double energy = 0;
};

/// A Totals as "/<owner>/<name>" of a coupled checkpoint ([mass, px, py, pz, E]), and back.
void save_totals(RestartWriter& out, const std::string& owner, const std::string& name,
                 const Totals& totals);
[[nodiscard]] Totals restored_totals(const RestartReader& in, const std::string& owner,
                                     const std::string& name);

/// What the solvers' Hello capabilities offer beyond protocol v1.0 (proto §14).
struct SolverFeatures {
  bool fdm_face_crossing = false;  ///< fdm exports `coupling_face` (crossed_*): exact parcels
  bool fdm_outflow = false;        ///< fdm exports outflow_* of `fdm_owned`
  bool mpm_outflow = false;        ///< mpm exports outflow_* of `mpm_zone`
};

struct StepPlan {
  bool advance = false;   ///< false: step 0 or before output (no Advance, no injection)
  double dt = 0;          ///< Δt^n [s]
  double time = 0;        ///< t^n [s]
  std::int64_t step = 0;  ///< n of the step to t^n + Δt^n (messages)
  bool audit = false;     ///< export the zones' contents for the conservation audit
  bool mpm = true;        ///< false: the MPM zone is dormant, only the FDM gets a request
};

/// What one step moved across the face (for the audit and the log).
struct StepTraffic {
  std::size_t injected = 0;   ///< particles sent to the MPM
  std::size_t removed = 0;    ///< particles the MPM gave back
  double injected_mass = 0;   ///< kg
  double deposited_mass = 0;  ///< kg, removed particles and returned parcels
  std::size_t discarded = 0;  ///< step 0: MPM particles outside the MPM zone (the FDM's material)
};

template <int Dim>
class CfdmpStep {
 public:
  CfdmpStep(const config::Scene& scene, const ZoneLayout& layout, SolverFeatures features = {});

  /// Fills the two requests of a step (empty, or emptied by clear_for_reuse, wire.hpp).
  void build(const StepPlan& plan, cosim::Message& fdm, cosim::Message& mpm);
  /// Reads the replies to the requests of the last build().
  void read(const StepPlan& plan, const cosim::Message& fdm, const cosim::Message& mpm);

  /// min of the two solvers' last proposals and the strip cells' cap
  /// (strip_step_limit.hpp) [s].
  [[nodiscard]] double stable_dt() const { return std::min({fdm_dt_, mpm_dt_, strip_dt_}); }
  /// What sets stable_dt(): "fdm", "mpm" or "strip".
  [[nodiscard]] const char* limited_by() const {
    return strip_dt_ < std::min(fdm_dt_, mpm_dt_) ? "strip" : fdm_dt_ <= mpm_dt_ ? "fdm" : "mpm";
  }
  /// The FDM's pressure on strip_cells at the last export [Pa] (the activation watch).
  [[nodiscard]] const std::vector<double>& strip_pressure() const { return strip_now_.pressure; }
  /// The audit exports of the last audited step: FDM zone outside the MPM zone, MPM particles
  /// (while the zone is dormant: the FDM's cells of the MPM zone, see activation.hpp).
  [[nodiscard]] const Totals& fdm_totals() const { return fdm_totals_; }
  [[nodiscard]] const Totals& mpm_totals() const { return mpm_totals_; }
  /// What waits in the face parcels (neither solver holds it).
  [[nodiscard]] Totals parcel_totals() const;
  /// What has left the domain through open faces (momentum: and wall impulse)
  /// since the start, as the solvers report it (zero where they do not).
  [[nodiscard]] const Totals& fdm_outflow() const { return fdm_outflow_; }
  [[nodiscard]] const Totals& mpm_outflow() const { return mpm_outflow_; }
  /// What the FDM put through the MPM zone's domain faces while the zone slept (v1.1).
  [[nodiscard]] const Totals& dormant_outflow() const { return dormant_outflow_; }
  [[nodiscard]] const SolverFeatures& features() const { return features_; }
  [[nodiscard]] const StepTraffic& traffic() const { return traffic_; }
  /// Why an FDM cell beside the coupling face emptied, when one of the last two deposits took
  /// most of one (face_drain.hpp); empty otherwise.
  [[nodiscard]] std::string face_drain_text() const;
  /// The largest share of a face cell's mass any deposit of the run took.
  [[nodiscard]] double max_face_drain_share() const { return drain_.run_max_share(); }

  /// What the coupler carries between steps, in a coupled checkpoint taken after an
  /// output's exchange (restart_file.hpp): the face parcels, the injection rule and ids,
  /// the ghost nodes of t^n, the dormant zone's outflow and the drain watch. The rest
  /// (strip cells, face mass, proposals, audit totals) comes back with the exchange
  /// without advance that a restarted run makes first.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);

 private:
  using Vec = handshake::Vec<Dim>;
  enum class Op {
    apply,
    inject,
    advance,
    export_strip,
    export_beyond,
    export_face,
    export_owned,
    export_ghost,
    export_face_particles,
    discard,
    remove,
    export_particles,
    export_dormant,
    propose
  };

  struct Strip {
    std::vector<double> rho, energy, pressure;
    std::vector<Vec> momentum;
  };

  void add_deposit(cosim::Message& fdm);
  void add_injection(cosim::Message& mpm);
  void add_ghost_cells(cosim::Message& fdm, const StepPlan& plan);
  /// "(i, j, k) at (x, y, z) m" of a cell of the active axes.
  [[nodiscard]] std::string cell_text(const handshake::Index<Dim>& cell) const;
  /// The error for ghost cell `c` (region order) left without MPM mass.
  [[nodiscard]] std::string empty_ghost_cell_text(std::size_t c, const StepPlan& plan) const;
  void add_interface_nodes(cosim::Message& mpm);
  void read_fdm(const StepPlan& plan, const cosim::Message& reply);
  void read_mpm(const cosim::Message& reply);
  [[nodiscard]] Totals cell_totals(const cosim::Message& reply, const char* region,
                                   std::size_t count) const;
  void read_crossed(const cosim::Message& reply);
  void read_face_particles(std::size_t n, const cosim::Message& reply);
  /// The face cell (k-w+1, C order) of particle p of `position` ([n, 3], m).
  [[nodiscard]] std::size_t face_cell_of(std::span<const double> position, std::size_t p) const;
  void add_audit_export(cosim::Message& fdm, const char* region) const;
  void add_cell_apply(cosim::Message& fdm, const char* region, cosim::v1::ApplyRegion::Mode mode);
  void add_face_fluxes(const handshake::Amounts<Dim>& returned);
  /// Runs `kernel` on the strip cells; the Error it throws for a face cell left without
  /// mass gets the cause when the deposits were emptying one (face_drain.hpp).
  template <class Kernel>
  void named_drain(Kernel&& kernel) const {
    try {
      kernel();
    } catch (const Error& error) {
      const std::string cause = face_drain_text();
      if (cause.empty()) throw;
      throw Error(with_cause(error.what(), cause));
    }
  }

  const config::Scene& scene_;
  ZoneLayout layout_;
  SolverFeatures features_;
  handshake::CellGeometry<Dim> geometry_;
  handshake::StripLayout<Dim> strip_layout_;
  handshake::InterfaceStencil<Dim> stencil_;
  bool outer_nodes_ = false;  ///< uGIMP MPM: feed the node layer outside the face too
  handshake::InterfaceStencil<Dim> outer_stencil_;
  handshake::IndexBox<Dim> ghost_cells_;
  handshake::IndexBox<Dim> ghost_nodes_;
  handshake::IndexBox<Dim> face_cells_;  ///< the cells k-w+1, C order = face cells
  handshake::IndexBox<Dim> deposit_box_;
  std::vector<std::size_t> corners_;
  std::vector<double> corner_support_;  // Σ N_Ic s_I per ghost cell (ghost_cells.hpp)
  std::vector<std::size_t>
      outer_in_deposit_;  ///< per face cell: its outer cell's place in deposit_cells
  std::vector<std::size_t> face_in_export_;  ///< per face cell: its place in coupling_face
  std::array<double, 3> inactive_centre_{};  ///< particle coordinates on inactive axes
  handshake::InjectionRule rule_;
  InjectedMaterial injected_material_;
  std::uint64_t next_id_ = std::uint64_t{1} << 48;  ///< injected ids, far above the MPM's own

  Strip strip_now_, strip_prev_;
  Strip beyond_;  ///< cells k-w-1 of t^n, per face cell (outer_nodes_ only)
  double strip_dt_ = std::numeric_limits<double>::infinity();
  bool flux_due_ = false;
  double dt_last_ = 0;
  handshake::Parcels<Dim> parcels_;
  std::vector<double> crossed_mass_, crossed_energy_;  ///< per face cell, into the zone
  std::vector<Vec> crossed_momentum_;
  std::vector<double> returned_mass_, returned_energy_;
  std::vector<Vec> returned_momentum_;
  std::vector<double> ghost_node_mass_, ghost_cell_energy_;
  std::vector<Vec> ghost_node_momentum_;
  bool have_ghost_source_ = false;
  std::vector<double> face_mass_;  ///< per face cell: the MPM's fluid particles' mass in cell k-w+1
  std::vector<double> face_solid_volume_;  ///< per face cell: its solid particles' volume there
  bool have_face_mass_ = false;
  std::vector<char> solid_;          ///< per scene material: it has strength (a solid)
  bool any_solid_ = false;           ///< face_particles then also exports volume and material
  std::vector<double> push_volume_;  ///< per face cell: V of (4-9), face_push_volume
  std::vector<double> removed_mass_, removed_energy_;
  std::vector<Vec> removed_position_, removed_velocity_;

  /// Scratch of build(): sized in the first steps, then reused (no allocation in a step).
  struct Scratch {
    std::vector<double> rho, energy, mass, volume, wire;
    std::vector<Vec> momentum, force, position, velocity;
    std::vector<std::size_t> index, face;
    std::vector<std::uint64_t> ids;
    std::vector<std::uint32_t> material;
  };
  Scratch scratch_;

  std::vector<Op> fdm_ops_, mpm_ops_;
  double fdm_dt_ = 0, mpm_dt_ = 0;
  Totals fdm_totals_, mpm_totals_, fdm_outflow_, mpm_outflow_, dormant_outflow_;
  StepTraffic traffic_;
  FaceDrainWatch drain_;
};

}  // namespace mpfd::coupler
