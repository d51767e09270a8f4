#pragma once
// The three AFDMP handoffs as the coupler runs them over protocol v1.2
// (design §3.5), each audited three ways — what the coupler received, what it
// sent, and the importing solver's own FieldImportDone.totals — and described
// for summary.json:
//   mpm_to_fdm        T (3-3)...(3-8): the MPM's fluid-zone particles become the
//                     FDM's cells and tracers (the FSI zone gets the scene's
//                     initial state as a placeholder);
//   spherical_to_fdm  seed S: the 1D stage's shells remapped onto the grid, the
//                     cells the profile does not cover filled with `initial`;
//   fdm_to_mpm        T (3-14)...(3-20): the FDM's fluid zone becomes particles
//                     added to the MPM, which kept its FSI-zone particles.

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "common/config/scene.hpp"
#include "cosim/hub.hpp"
#include "cosim/serving/field_stream.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/handoff_audit.hpp"
#include "coupler/run/spherical_stage.hpp"

namespace mpfd::coupler {

struct HandoffSettings {
  std::uint64_t max_chunk_bytes = cosim::kDefaultMaxChunkBytes;
  std::chrono::milliseconds timeout{300000};
  /// The FDM offers material_import: mpm_to_fdm (and spherical_to_fdm, if the scene
  /// asks) also send each material's own start in the mixed cells
  /// (coupler/handoff/material_start.hpp).
  bool material_import = false;
};

/// What a handoff did, for summary.json and the tests.
struct HandoffRecord {
  nlohmann::json summary;      ///< name, counts, sums, errors, transfer sizes, wall time
  ConservedError worst_error;  ///< the largest of the three comparisons
  double tolerance = 0;        ///< what round-off allows for its sums (handoff_tolerance)
  double stable_dt = 0;        ///< of the importing solver [s]
  /// fdm_to_mpm: what the FDM moved into the placeholder FSI cells, dropped
  /// (the run-long audit's named term, afdmp_audit.hpp).
  Conserved fsi_face_leak;
};

/// The scene material indices of the charges' explosives.
[[nodiscard]] std::vector<int> explosive_materials(const config::Scene& scene);

/// The relative error round-off allows a sum of `values` doubles (a handoff
/// compares sums of up to 1e6 cells or particles): max(1e-12, 2 n eps).
[[nodiscard]] double handoff_tolerance(std::size_t values);

/// Ids of particles an FDM -> MPM handoff creates (CFDMP's injections start at 2^48).
inline constexpr std::uint64_t kHandoffFirstId = std::uint64_t{1} << 49;

/// The MPM's fluid-zone particles -> FDM cells and tracers, at the hub's clock.
/// Throws mpfd::Error if an explosive particle has not burnt (F < 1).
HandoffRecord handoff_mpm_to_fdm(const config::Scene& scene, const AfdmpLayout& layout,
                                 cosim::Hub& hub, const HandoffSettings& settings);

/// The 1D stage's state -> FDM cells and tracers, at the hub's clock.
HandoffRecord handoff_spherical_to_fdm(const config::Scene& scene, const SphericalStage& stage,
                                       cosim::Hub& hub, const HandoffSettings& settings);

/// The FDM's fluid zone -> MPM particles, at the hub's clock; also reports the
/// FSI-face leak (what the FDM moved into the placeholder FSI cells, discarded).
HandoffRecord handoff_fdm_to_mpm(const config::Scene& scene, const AfdmpLayout& layout,
                                 cosim::Hub& hub, const HandoffSettings& settings,
                                 const Conserved& placeholder);

/// What the FSI-zone placeholder holds at the MPM -> FDM handoff.
[[nodiscard]] Conserved placeholder_conserved(const config::Scene& scene,
                                              const AfdmpLayout& layout);

}  // namespace mpfd::coupler
