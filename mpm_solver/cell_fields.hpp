#pragma once
// Particle quantities binned into the grid cells that hold them: the cell
// fields an MPM snapshot writes when the scene's output.fields asks (so an
// MPM run opens in ParaView like an FDM run, cells.xmf beside particles.xmf),
// and the cell values of gauges. A cell's
//   density = sum m_p / V_cell,  velocity = sum m_p v_p / sum m_p,
//   e, c, F = mass-weighted means,  p = particle-volume-weighted mean,
//   volume fraction of material r = sum_{p in r} V_p / sum V_p,
//   material = the material holding most of the cell's mass.
// Binning conserves mass and momentum exactly (each particle lands in one
// cell); it is a post-processing view, not part of the step. Empty cells
// read 0 (density, velocity, pressure, ...) and material -1.

#include <span>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "common/io/field_view.hpp"

namespace mpfd::mpm {

class MpmSolver;
struct ParticleSet;

class CellFields {
 public:
  CellFields(const config::Scene& scene, const grid::UniformGrid& grid);

  [[nodiscard]] bool empty() const { return fields_.empty(); }
  /// The requested fields of the solver's particles now; valid until the next call.
  std::vector<io::FieldView> views(const MpmSolver& solver);

 private:
  void bin(const MpmSolver& solver);

  grid::UniformGrid grid_;
  std::vector<config::Field> fields_;
  std::vector<std::string> material_names_;
  // Per cell; the per-material volumes are material-major.
  std::vector<double> mass_, volume_, density_, pressure_, energy_, sound_speed_, burn_;
  std::vector<double> material_, material_volume_;
  std::array<std::vector<double>, 3> velocity_;
};

/// The cell values of gauges: each gauge reads the binned state of the cell
/// holding it (density, pressure, velocity as in CellFields), beside its
/// nearest particle. One pass over the particles per sample.
class GaugeCells {
 public:
  GaugeCells(const grid::UniformGrid& grid, std::span<const grid::Vec3> positions);
  /// Writes 5 values per gauge (density, pressure, velocity x, y, z) to `out`.
  void sample(const ParticleSet& ps, std::span<double> out);

 private:
  grid::UniformGrid grid_;
  std::vector<std::size_t> cell_;  // per gauge
  std::vector<double> mass_, volume_, pressure_, momentum_;
};

/// Index of the grid cell holding x (clamped to the grid: particles on the
/// upper face belong to the last cell).
[[nodiscard]] std::size_t cell_holding(const grid::UniformGrid& grid, double x, double y, double z);

}  // namespace mpfd::mpm
