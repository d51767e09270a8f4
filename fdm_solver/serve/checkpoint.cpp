#include "fdm_solver/serve/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "common/core/log.hpp"
#include "common/io/hdf5_file.hpp"
#include "fdm_solver/mixture_eos.hpp"
#include "fdm_solver/serve/protocol_error.hpp"
#include "fdm_solver/serve/sha256.hpp"

namespace mpfd::fdm {
namespace {

namespace fs = std::filesystem;

/// The conserved arrays, in Variable order (euler_state.hpp).
constexpr std::array<const char*, kVariables> kConserved = {
    "/state/rho", "/state/momentum_x", "/state/momentum_y", "/state/momentum_z", "/state/E"};
constexpr std::array<const char*, kVariables> kConservedUnits = {
    "kg/m^3", "kg/(m^2 s)", "kg/(m^2 s)", "kg/(m^2 s)", "J/m^3"};

[[noreturn]] void refuse(cosim::v1::ErrorCode code, const std::string& text) {
  throw ProtocolError(code, text, false);
}

std::string cells_text(const std::array<double, 3>& n) {
  std::string text = "[";
  for (std::size_t a = 0; a < 3; ++a)
    text += (a ? ", " : "") + std::to_string(static_cast<long long>(n[a]));
  return text + "]";
}

/// The tracers are not part of the state written here, so a multi-material
/// zone could not continue exactly from one.
void require_one_material(const ServedZone& zone, const std::string& operation) {
  if (zone.solver.tracker() != nullptr)
    refuse(cosim::v1::ERROR_CODE_UNEXPECTED,
           operation + ": scene '" + zone.scene.name + "' has " +
               std::to_string(zone.scene.materials.size()) +
               " materials; multi-material (tracer) state is not restorable yet, so "
               "fdm_solver checkpoints one-material zones only (nothing was written or read)");
}

/// `requested` resolved against Setup.output_dir; an empty one is output_dir.
fs::path resolve(const ServedZone& zone, const std::string& requested,
                 const std::string& operation) {
  if (requested.empty()) {
    if (zone.output_dir.empty())
      refuse(cosim::v1::ERROR_CODE_IO, operation + ": no path given and Setup gave no output_dir");
    return zone.output_dir / "checkpoints";
  }
  const fs::path path(requested);
  return path.is_relative() && !zone.output_dir.empty() ? zone.output_dir / path : path;
}

std::vector<std::size_t> cell_shape(const grid::UniformGrid& grid) {
  const auto& n = grid.cells();
  return {static_cast<std::size_t>(n[2]), static_cast<std::size_t>(n[1]),
          static_cast<std::size_t>(n[0])};
}

void write_file(const fs::path& file, const ServedZone& zone) {
  const EulerSolver& solver = zone.solver;
  const EulerState& state = solver.state();
  const auto shape = cell_shape(state.grid);
  io::Hdf5File h5(file, io::Hdf5File::Mode::create);
  h5.write_attribute("/", "format", std::string(kCheckpointFormat));
  h5.write_attribute("/", "format_version", kCheckpointVersion);
  h5.write_attribute("/", "time", zone.time());
  h5.write_attribute("/", "solver_time", solver.time());
  h5.write_attribute("/", "start_time", zone.start_time);
  h5.write_attribute("/", "step", solver.steps());
  h5.write_attribute("/", "scene", zone.scene_text);
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
  h5.create_group("/audit");
  h5.write_dataset("/audit/outflow", solver.outflow(), {kVariables},
                   "kg, kg m/s, kg m/s, kg m/s, J");
}

/// Reads `path` and checks it against the zone; the state to restore.
struct ReadBack {
  EulerState state;
  double solver_time = 0.0;
  std::int64_t steps = 0;
  Totals outflow{};
  std::string scene_text;
};

ReadBack read_file(const fs::path& path, const ServedZone& zone, std::uint64_t step) {
  const std::string where = "Restore: '" + path.string() + "' ";
  auto mismatch = [&](const std::string& what) { refuse(cosim::v1::ERROR_CODE_IO, where + what); };
  const io::Hdf5File h5(path, io::Hdf5File::Mode::read);
  const std::string format = h5.read_string_attribute("/", "format");
  if (format != kCheckpointFormat)
    mismatch("has format '" + format + "', not an FDM checkpoint ('" + kCheckpointFormat + "')");
  const double version = h5.read_attribute("/", "format_version");
  if (version != static_cast<double>(kCheckpointVersion))
    mismatch("has format_version " + std::to_string(static_cast<long long>(version)) +
             "; this solver reads version " + std::to_string(kCheckpointVersion));

  const grid::UniformGrid& grid = zone.solver.state().grid;
  const auto file_cells = h5.read_dataset("/grid/cells").values;
  const auto& n = grid.cells();
  const std::array<double, 3> running = {double(n[0]), double(n[1]), double(n[2])};
  if (file_cells.size() != 3 || !std::equal(running.begin(), running.end(), file_cells.begin()))
    mismatch("holds a grid of " +
             (file_cells.size() == 3 ? cells_text({file_cells[0], file_cells[1], file_cells[2]})
                                     : std::to_string(file_cells.size()) + " axes") +
             " cells; the running scene '" + zone.scene.name + "' has " + cells_text(running));

  const std::size_t count = grid.cell_count();
  auto cell_array = [&](const std::string& name) {
    auto values = h5.read_dataset(name).values;
    if (values.size() != count)
      mismatch("array '" + name + "' has " + std::to_string(values.size()) + " values; the grid " +
               std::to_string(count) + " cells");
    return values;
  };
  ReadBack back{EulerState(grid), 0.0, 0, {}, {}};
  for (std::size_t v = 0; v < kVariables; ++v) back.state.u[v] = cell_array(kConserved[v]);
  const auto material = cell_array("/state/material");
  const std::size_t materials = zone.scene.materials.size();
  for (std::size_t c = 0; c < count; ++c) {
    const double m = material[c];
    if (m != std::floor(m) || m < 0 || (m >= double(materials) && m != kMixedMaterial))
      mismatch("cell " + std::to_string(c) + " has material " + std::to_string(m) +
               "; the scene has " + std::to_string(materials) + " materials");
    back.state.material[c] = static_cast<std::uint8_t>(m);
  }
  const bool mixed = h5.exists("/state/mix_gamma");
  if (mixed != !zone.solver.state().mix_gamma.empty())
    mismatch(mixed ? "holds mixed-cell EOS arrays; the running zone has one material"
                   : "has no mixed-cell EOS arrays; the running zone has several materials");
  if (mixed) {
    back.state.mix_gamma = cell_array("/state/mix_gamma");
    back.state.mix_pinf = cell_array("/state/mix_pinf");
  }
  const auto outflow = h5.read_dataset("/audit/outflow").values;
  if (outflow.size() != kVariables)
    mismatch("array '/audit/outflow' has " + std::to_string(outflow.size()) + " values, not " +
             std::to_string(kVariables));
  std::copy(outflow.begin(), outflow.end(), back.outflow.begin());

  const double steps = h5.read_attribute("/", "step");
  if (steps != static_cast<double>(step))
    mismatch("was taken at step " + std::to_string(static_cast<long long>(steps)) +
             "; the Restore request says step " + std::to_string(step));
  back.steps = static_cast<std::int64_t>(steps);
  const double start_time = h5.read_attribute("/", "start_time");
  if (start_time != zone.start_time)
    mismatch("has start_time " + std::to_string(start_time) + " s; Setup gave " +
             std::to_string(zone.start_time) + " s");
  back.solver_time = h5.read_attribute("/", "solver_time");
  back.scene_text = h5.read_string_attribute("/", "scene");
  return back;
}

}  // namespace

cosim::v1::CheckpointWritten write_checkpoint(const ServedZone& zone,
                                              const cosim::v1::Checkpoint& request) {
  require_one_material(zone, "Checkpoint");
  fs::path file = resolve(zone, request.path(), "Checkpoint");
  if (request.path().empty() || fs::is_directory(file) || file.filename().empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "checkpoint_%06lld.h5",
                  static_cast<long long>(zone.solver.steps()));
    file /= name;
  }
  cosim::v1::CheckpointWritten written;
  try {
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    fs::path partial = file;
    partial += ".partial";
    try {
      write_file(partial, zone);  // closed on return: then complete
      fs::rename(partial, file);
    } catch (...) {
      std::error_code ignored;
      fs::remove(partial, ignored);  // no partial checkpoint is left behind
      throw;
    }
    written.set_bytes(static_cast<std::uint64_t>(fs::file_size(file)));
    written.set_sha256(sha256_hex_of_file(file));
  } catch (const std::exception& error) {
    refuse(cosim::v1::ERROR_CODE_IO,
           "Checkpoint to '" + file.string() + "' failed: " + error.what());
  }
  written.set_path(file.string());
  return written;
}

cosim::v1::Restored restore_checkpoint(ServedZone& zone, const cosim::v1::Restore& request) {
  require_one_material(zone, "Restore");
  if (request.path().empty()) refuse(cosim::v1::ERROR_CODE_IO, "Restore: no path given");
  const fs::path file = resolve(zone, request.path(), "Restore");
  std::optional<ReadBack> back;
  try {
    back.emplace(read_file(file, zone, request.step()));
  } catch (const ProtocolError&) {
    throw;
  } catch (const std::exception& error) {
    refuse(cosim::v1::ERROR_CODE_IO,
           "Restore from '" + file.string() + "' failed: " + error.what());
  }
  if (back->scene_text != zone.scene_text)
    Logger("fdm.serve")
        .warn("Restore: '", file.string(),
              "' was written for another scene text than this Setup's; its grid and materials "
              "match, so the state is restored");
  zone.solver.restore(back->state, back->solver_time, back->steps, back->outflow);
  cosim::v1::Restored restored;
  restored.set_step(static_cast<std::uint64_t>(zone.solver.steps()));
  restored.set_time(zone.time());
  restored.set_stable_dt(zone.solver.stable_dt());
  return restored;
}

}  // namespace mpfd::fdm
