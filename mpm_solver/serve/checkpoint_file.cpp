#include "mpm_solver/serve/checkpoint_file.hpp"

#include <array>

#include "common/io/hdf5_file.hpp"
#include "cosim/serving/checkpoint_reader.hpp"

namespace mpfd::mpm {
namespace {

/// Name of the i-th array of ParticleSet::for_each_double_array.
std::string double_array_name(std::size_t i) {
  return "/particles/double_" + std::to_string(i);
}

std::string material_names(const config::Scene& scene) {
  std::string names;
  for (const auto& m : scene.materials) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

std::vector<std::int64_t> as_int64(const auto& values) {
  return {values.begin(), values.end()};
}

void check_header(const cosim::CheckpointReader& in, const ServedZone& zone) {
  const io::Hdf5File& h5 = in.file();
  const std::string format = h5.read_string_attribute("/", "format");
  if (format != kCheckpointFormat)
    in.mismatch("has format '" + format + "', not an MPM checkpoint ('" + kCheckpointFormat + "')");
  const double version = h5.read_attribute("/", "format_version");
  if (version != static_cast<double>(kCheckpointVersion))
    in.mismatch("has format_version " + std::to_string(static_cast<long long>(version)) +
                "; this solver reads version " + std::to_string(kCheckpointVersion));
  const auto cells = h5.read_dataset("/grid/cells").values;
  const auto& n = zone.solver.grid().cells();
  if (cells.size() != 3 || cells[0] != n[0] || cells[1] != n[1] || cells[2] != n[2])
    in.mismatch("holds another grid than the running scene '" + zone.scene.name + "' (" +
                std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) +
                " cells)");
  const std::string names = h5.read_string_attribute("/", "material_names");
  if (names != material_names(zone.scene))
    in.mismatch("holds materials (" + names + "); the running scene '" + zone.scene.name +
                "' has (" + material_names(zone.scene) + ")");
}

}  // namespace

void write_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone,
                           const std::optional<std::array<grid::Index3, 2>>& next_step_map_box) {
  const MpmSolver& solver = zone.solver;
  const ParticleSet& ps = solver.particles();
  const std::size_t n = ps.size();
  io::Hdf5File h5(file, io::Hdf5File::Mode::create);
  h5.write_attribute("/", "format", std::string(kCheckpointFormat));
  h5.write_attribute("/", "format_version", kCheckpointVersion);
  cosim::write_checkpoint_clock(
      h5, {solver.steps(), solver.time(), zone.start_time, zone.setup_start_time});
  h5.write_attribute("/", "particle_updates", solver.particle_updates());
  h5.write_attribute("/", "scene", zone.scene_text);
  h5.write_text("/snapshots", zone.snapshots ? zone.snapshots->history()
                                             : "[]");  // grows with the outputs: a dataset
  h5.write_attribute("/", "material_names", material_names(zone.scene));
  h5.write_attribute("/", "particle_count", static_cast<std::int64_t>(n));
  h5.write_attribute("/", "history_stride", static_cast<std::int64_t>(ps.history_stride));
  h5.create_group("/grid");
  const auto& cells = solver.grid().cells();
  const std::array<std::int64_t, 3> cell_counts = {cells[0], cells[1], cells[2]};
  h5.write_dataset("/grid/cells", cell_counts, {3});
  h5.create_group("/particles");
  std::size_t index = 0;
  ps.for_each_double_array([&](const std::vector<double>& values, std::size_t) {
    if (!values.empty()) h5.write_dataset(double_array_name(index), values, {values.size()}, "SI");
    ++index;
  });
  if (n > 0) {
    std::vector<std::int64_t> high(n), low(n);  // exact halves: HDF5 reads back as binary64
    for (std::size_t p = 0; p < n; ++p) {
      high[p] = static_cast<std::int64_t>(ps.id[p] >> 32);
      low[p] = static_cast<std::int64_t>(ps.id[p] & 0xffffffffU);
    }
    h5.write_dataset("/particles/id_high", high, {n});
    h5.write_dataset("/particles/id_low", low, {n});
    h5.write_dataset("/particles/material", as_int64(ps.material), {n});
    h5.write_dataset("/particles/body", as_int64(ps.body), {n});
  }
  std::vector<std::int64_t> injected;
  for (std::size_t b = solver.scene_body_count(); b < solver.bodies().size(); ++b)
    injected.push_back(static_cast<std::int64_t>(solver.bodies()[b].material));
  h5.write_attribute("/", "injected_body_count", static_cast<std::int64_t>(injected.size()));
  if (!injected.empty()) h5.write_dataset("/injected_body_material", injected, {injected.size()});
  const BoundaryLedger& ledger = solver.boundary_ledger();
  const std::array<double, 6> audit = {ledger.mass,        ledger.momentum[0],
                                       ledger.momentum[1], ledger.momentum[2],
                                       ledger.energy,      double(ledger.particles_removed)};
  h5.write_dataset("/ledger", audit, {audit.size()}, "kg, kg m/s, kg m/s, kg m/s, J, particles");
  if (next_step_map_box) {
    std::vector<std::int64_t> corners;
    for (const auto& corner : *next_step_map_box)
      for (const int node : corner) corners.push_back(node);
    h5.write_dataset("/next_step_map_box", corners, {corners.size()});  // grid nodes lo, hi
  }
}

CheckpointContents read_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone,
                                        std::uint64_t step) {
  const cosim::CheckpointReader in(file);
  const io::Hdf5File& h5 = in.file();
  check_header(in, zone);
  CheckpointContents back;
  const auto n = static_cast<std::size_t>(h5.read_attribute("/", "particle_count"));
  ParticleSet& ps = back.particles;
  ps.history_stride = static_cast<std::size_t>(h5.read_attribute("/", "history_stride"));
  ps.grow(n);
  std::size_t index = 0;
  ps.for_each_double_array([&](std::vector<double>& values, std::size_t stride) {
    if (!values.empty())
      values =
          in.values(double_array_name(index), n * stride, std::to_string(stride) + " per particle");
    ++index;
  });
  if (n > 0) {
    const auto high = in.values("/particles/id_high", n, "one per particle");
    const auto low = in.values("/particles/id_low", n, "one per particle");
    const auto material = in.values("/particles/material", n, "one per particle");
    const auto body = in.values("/particles/body", n, "one per particle");
    for (std::size_t p = 0; p < n; ++p) {
      ps.id[p] = (static_cast<std::uint64_t>(high[p]) << 32) | static_cast<std::uint64_t>(low[p]);
      ps.material[p] = static_cast<std::uint16_t>(material[p]);
      ps.body[p] = static_cast<std::uint16_t>(body[p]);
    }
  }
  const auto injected = static_cast<std::size_t>(h5.read_attribute("/", "injected_body_count"));
  if (injected > 0)
    for (const double m : in.values("/injected_body_material", injected, "one per injected body"))
      back.injected_body_materials.push_back(static_cast<std::size_t>(m));
  const auto audit = in.values("/ledger", 6, "mass, momentum x/y/z, energy, particles");
  back.ledger = {
      audit[0], {audit[1], audit[2], audit[3]}, audit[4], static_cast<std::int64_t>(audit[5])};
  back.clock = cosim::read_checkpoint_clock(in, step, zone.setup_start_time);
  back.particle_updates = h5.read_attribute("/", "particle_updates");
  back.scene_text = h5.read_string_attribute("/", "scene");
  back.snapshot_history = h5.read_text("/snapshots");
  if (h5.exists("/next_step_map_box")) {  // absent: no map, or a checkpoint from before maps
    const auto corners = in.values("/next_step_map_box", 6, "grid node lo, hi");
    std::array<grid::Index3, 2> box{};
    for (std::size_t c = 0; c < 6; ++c) box[c / 3][c % 3] = static_cast<int>(corners[c]);
    for (int a = 0; a < 3; ++a)
      if (!(box[0][a] >= 0 && box[0][a] < box[1][a] &&
            box[1][a] <= zone.solver.grid().cells()[a] + 1))
        in.mismatch("has a next-step map box outside the grid's nodes on axis " +
                    std::to_string(a));
    back.next_step_map_box = box;
  }
  return back;
}

}  // namespace mpfd::mpm
