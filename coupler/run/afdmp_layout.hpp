#pragma once
// The AFDMP geometry (design §3.2): the FSI zone is the scene's zones.mpm
// (T Fig. 3.1: fluid zone and FSI zone split by a dashed line); like CFDMP's
// MPM zone (zone_layout.hpp) it has exactly one face inside the domain and
// spans the domain across it, so the fluid zone is the complementary box.
// No zones.mpm: no phase 3, the fluid zone is the whole grid. Boxes are wire
// boxes (zone_layout.hpp): cells of the scene's grid, half-open.
// Also the Setup regions both solvers get (design §3.2 table): the fields
// each handoff exports and imports, and the trigger inputs.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/config/scene.hpp"
#include "coupler/handoff/sub_grid.hpp"
#include "coupler/run/wire.hpp"
#include "coupler/run/zone_layout.hpp"

namespace mpfd::coupler {

/// Fluid cell layers next to the FSI face whose pressure triggers phase 3.
inline constexpr std::int64_t kWatchLayers = 2;

/// Who runs phase 1 (scene key solver.afdmp.start).
enum class AfdmpStart {
  mpm,        ///< the 3D MPM detonates the charge (T §3.2.1)
  spherical,  ///< the 1D spherical MPM in the coupler (S; T §4.4.3)
};

struct AfdmpLayout {
  int dimension = 1;                   ///< active axes of the scene's grid
  std::array<int, 3> active{};         ///< the active axes in order (first `dimension` entries)
  WireIndex cells{};                   ///< the scene's cells per axis
  WireBox all_cells;                   ///< the scene's grid
  WireBox fluid_cells;                 ///< all_cells minus the FSI zone
  std::optional<WireBox> fsi_cells;    ///< zones.mpm
  std::optional<WireBox> watch_cells;  ///< kWatchLayers fluid layers next to the FSI face
  WireBox
      charge_cells;   ///< cells the charges' bounding boxes touch, grown by one cell (in the fluid)
  int face_axis = 0;  ///< normal of the FSI face
  int face_side = 1;  ///< +1: the FSI zone lies above the face along face_axis
  std::optional<double> activation_pressure;  ///< zones.mpm.activation_pressure [Pa]
};

/// Computes the layout of an afdmp scene. Throws mpfd::Error naming the rule
/// when the scene is not afdmp, has no charge, when zones.mpm has no or more
/// than one face inside the domain or does not span it across that face,
/// lacks activation_pressure or leaves fewer than kWatchLayers (and 2) fluid
/// cell layers, when a charge reaches into the FSI zone, or when a body with
/// a strength model is not inside the FSI zone (the FDM carries no strength).
[[nodiscard]] AfdmpLayout make_afdmp_layout(const config::Scene& scene);

/// Region names of the Setup both solvers get.
namespace afdmp_region {
inline constexpr const char* kAllCells = "all_cells";
inline constexpr const char* kAllTracers = "all_tracers";
inline constexpr const char* kFluidCells = "fluid_cells";
inline constexpr const char* kFluidTracers = "fluid_tracers";
inline constexpr const char* kFsiWatch = "fsi_watch";
inline constexpr const char* kFsiCells = "fsi_cells";
inline constexpr const char* kFluidParticles = "fluid_particles";
inline constexpr const char* kFsiParticles = "fsi_particles";
inline constexpr const char* kChargeParticles = "charge_particles";
// The run-long audit's (afdmp_audit.hpp): contents and outflow ledgers.
inline constexpr const char* kAuditCells = "audit_cells";
inline constexpr const char* kAuditParticles = "audit_particles";
}  // namespace afdmp_region

/// The Setup regions of each solver (design §3.2 table). FSI-zone regions
/// only with an FSI zone; charge_particles only with start = mpm (the
/// phase-1 trigger); with start = spherical and no FSI zone the MPM has no
/// role and gets none.
struct AfdmpRegions {
  std::vector<v1::Region> fdm;
  std::vector<v1::Region> mpm;
};
/// Which solvers offer boundary_outflow (v1.1, proto/README.md §14): only
/// they get outflow_* in their audit region; a v1.0 solver keeps v1.0.
struct AuditOutflow {
  bool fdm = true;
  bool mpm = true;
};
/// `material_import`: the FDM offers it (proto/README.md §15 rule 8), so
/// all_cells also declares volume_fraction, material_density, material_energy.
[[nodiscard]] AfdmpRegions afdmp_setup_regions(const AfdmpLayout& layout, AfdmpStart start,
                                               AuditOutflow outflow = {},
                                               bool material_import = false);

/// A wire box as the handoff kernels' cell box (same cells, same axes).
[[nodiscard]] handoff::CellBox to_cell_box(const WireBox& box);

}  // namespace mpfd::coupler
