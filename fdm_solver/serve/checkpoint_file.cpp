#include "fdm_solver/serve/checkpoint_file.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "common/io/hdf5_file.hpp"
#include "cosim/serving/checkpoint_reader.hpp"
#include "fdm_solver/mixture_eos.hpp"
#include "fdm_solver/serve/tracker_checkpoint.hpp"

namespace mpfd::fdm {
namespace {

/// The conserved arrays, in Variable order (euler_state.hpp).
constexpr std::array<const char*, kVariables> kConserved = {
    "/state/rho", "/state/momentum_x", "/state/momentum_y", "/state/momentum_z", "/state/E"};
constexpr std::array<const char*, kVariables> kConservedUnits = {
    "kg/m^3", "kg/(m^2 s)", "kg/(m^2 s)", "kg/(m^2 s)", "J/m^3"};

/// The dataset of one face's outflow per boundary cell.
std::string face_outflow_name(std::size_t face) {
  return std::string("/audit/face_outflow/") + config::kFaceNames[face];
}

std::string cells_text(const std::array<double, 3>& n) {
  std::string text = "[";
  for (std::size_t a = 0; a < 3; ++a)
    text += (a ? ", " : "") + std::to_string(static_cast<long long>(n[a]));
  return text + "]";
}

/// The scene's material names in index order, comma separated.
std::string material_names(const config::Scene& scene) {
  std::string names;
  for (const auto& m : scene.materials) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

std::vector<std::size_t> cell_shape(const grid::UniformGrid& grid) {
  const auto& n = grid.cells();
  return {static_cast<std::size_t>(n[2]), static_cast<std::size_t>(n[1]),
          static_cast<std::size_t>(n[0])};
}

void check_header(const cosim::CheckpointReader& in, const ServedZone& zone) {
  const io::Hdf5File& h5 = in.file();
  const std::string format = h5.read_string_attribute("/", "format");
  if (format != kCheckpointFormat)
    in.mismatch("has format '" + format + "', not an FDM checkpoint ('" + kCheckpointFormat + "')");
  const double version = h5.read_attribute("/", "format_version");
  if (version != static_cast<double>(kCheckpointVersion))
    in.mismatch("has format_version " + std::to_string(static_cast<long long>(version)) +
                "; this solver reads version " + std::to_string(kCheckpointVersion));

  const auto file_cells = h5.read_dataset("/grid/cells").values;
  const auto& n = zone.solver.state().grid.cells();
  const std::array<double, 3> running = {double(n[0]), double(n[1]), double(n[2])};
  if (file_cells.size() != 3 || !std::equal(running.begin(), running.end(), file_cells.begin()))
    in.mismatch("holds a grid of " +
                (file_cells.size() == 3 ? cells_text({file_cells[0], file_cells[1], file_cells[2]})
                                        : std::to_string(file_cells.size()) + " axes") +
                " cells; the running scene '" + zone.scene.name + "' has " + cells_text(running));

  const double materials = h5.read_attribute("/", "material_count");
  const std::string names = h5.read_string_attribute("/", "material_names");
  if (materials != static_cast<double>(zone.scene.materials.size()) ||
      names != material_names(zone.scene))
    in.mismatch("holds material count " + std::to_string(static_cast<long long>(materials)) + " (" +
                names + "); the running scene '" + zone.scene.name + "' has " +
                std::to_string(zone.scene.materials.size()) + " (" + material_names(zone.scene) +
                ")");
}

}  // namespace

void write_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone) {
  const EulerSolver& solver = zone.solver;
  const EulerState& state = solver.state();
  const auto shape = cell_shape(state.grid);
  io::Hdf5File h5(file, io::Hdf5File::Mode::create);
  h5.write_attribute("/", "format", std::string(kCheckpointFormat));
  h5.write_attribute("/", "format_version", kCheckpointVersion);
  cosim::write_checkpoint_clock(
      h5, {solver.steps(), solver.time(), zone.start_time, zone.setup_start_time});
  h5.write_attribute("/", "scene", zone.scene_text);
  h5.write_text("/snapshots", zone.output.history());  // grows with the outputs: a dataset
  h5.write_attribute("/", "material_count", static_cast<std::int64_t>(zone.scene.materials.size()));
  h5.write_attribute("/", "material_names", material_names(zone.scene));
  h5.create_group("/grid");
  const auto& n = state.grid.cells();
  const std::array<std::int64_t, 3> cells = {n[0], n[1], n[2]};
  h5.write_dataset("/grid/cells", cells, {3});
  h5.create_group("/state");
  for (std::size_t v = 0; v < kVariables; ++v)
    h5.write_dataset(kConserved[v], state.u[v], shape, kConservedUnits[v]);
  const std::vector<std::int64_t> material(state.material.begin(), state.material.end());
  h5.write_dataset("/state/material", material, shape);
  if (!state.mix_gamma.empty()) {
    h5.write_dataset("/state/mix_gamma", state.mix_gamma, shape, "1");
    h5.write_dataset("/state/mix_pinf", state.mix_pinf, shape, "Pa");
  }
  if (const MultiMaterialTracker* tracker = solver.tracker())
    write_tracker_state(h5, *tracker, state.grid);
  h5.create_group("/audit");
  h5.write_dataset("/audit/outflow", solver.outflow(), {kVariables},
                   "kg, kg m/s, kg m/s, kg m/s, J");
  h5.create_group("/audit/face_outflow");
  for (std::size_t f = 0; f < solver.face_outflow().size(); ++f) {
    const std::vector<double>& per_cell = solver.face_outflow()[f];
    if (per_cell.empty()) continue;  // the faces of an inactive axis
    h5.write_dataset(face_outflow_name(f), per_cell, {per_cell.size() / kVariables, kVariables},
                     "kg, kg m/s, kg m/s, kg m/s, J");
  }
}

CheckpointContents read_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone,
                                        std::uint64_t step) {
  const cosim::CheckpointReader in(file);
  const io::Hdf5File& h5 = in.file();
  check_header(in, zone);

  const grid::UniformGrid& grid = zone.solver.state().grid;
  const std::size_t count = grid.cell_count();
  const int materials = static_cast<int>(zone.scene.materials.size());
  CheckpointContents back{.state = EulerState(grid)};
  for (std::size_t v = 0; v < kVariables; ++v)
    back.state.u[v] = in.values(kConserved[v], count, "one per cell");
  // A zone that started with one material holds tracers once an import gave
  // it some: the restore makes the running zone multi-material too. Only such
  // a zone has mixed cells (and their EOS fit).
  const bool multi_material = zone.solver.tracker() != nullptr || h5.exists("/tracers");
  const std::string indices = "a material index in [0, " + std::to_string(materials) + ")";
  const auto material =
      multi_material
          ? in.indices("/state/material", count, "one per cell", materials, kMixedMaterial,
                       indices + " or " + std::to_string(kMixedMaterial) + " (mixed)")
          : in.indices("/state/material", count, "one per cell", materials, std::nullopt,
                       indices + " (no tracers, so no mixed cell)");
  std::copy(material.begin(), material.end(), back.state.material.begin());
  if (multi_material) {
    back.state.mix_gamma = in.values("/state/mix_gamma", count, "one per cell");
    back.state.mix_pinf = in.values("/state/mix_pinf", count, "one per cell");
    back.tracker = read_tracker_state(in, grid, materials);
  }
  const auto outflow = in.values("/audit/outflow", kVariables, "mass, momentum x/y/z, energy");
  std::copy(outflow.begin(), outflow.end(), back.outflow.begin());
  for (std::size_t f = 0; f < back.face_outflow.size(); ++f)
    if (const std::size_t values = zone.solver.face_outflow()[f].size(); values > 0)
      back.face_outflow[f] =
          in.values(face_outflow_name(f), values, "mass, momentum x/y/z, energy per boundary cell");

  back.clock = cosim::read_checkpoint_clock(in, step, zone.setup_start_time);
  back.scene_text = h5.read_string_attribute("/", "scene");
  back.snapshot_history = h5.read_text("/snapshots");
  return back;
}

}  // namespace mpfd::fdm
