#include "tools/scene/scene_commands.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>
#include <variant>

#include "common/core/require.hpp"
#include "common/eos/jwl_cj.hpp"
#include "common/initial/initial_cells.hpp"
#include "common/io/gauge_recorder.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "common/io/snapshot_writer.hpp"

namespace mpfd::tools {
namespace {

std::string sci(double x) {
  return number_text(x, 4);
}

std::string vec(const grid::Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v[0], v[1], v[2]);
  return text;
}

constexpr const char* kFaceName[] = {"x_lower", "x_upper", "y_lower",
                                     "y_upper", "z_lower", "z_upper"};
// In config::BoundaryKind order.
constexpr const char* kBoundaryName[] = {"outflow", "wall", "symmetry", "non_reflecting"};

/// The cell fields of a snapshot, in the names and units of docs/output.md.
std::vector<io::FieldView> field_views(const initial::CellFields& f) {
  std::vector<io::FieldView> views{
      {"density", "kg/m^3", {f.density}},
      {"velocity", "m/s", {f.velocity_x, f.velocity_y, f.velocity_z}},
      {"pressure", "Pa", {f.pressure}},
      {"specific_internal_energy", "J/kg", {f.specific_internal_energy}},
      {"sound_speed", "m/s", {f.sound_speed}},
      {"material", "", {f.material}},
      {"burn_fraction", "", {f.burn_fraction}},
  };
  return views;
}

}  // namespace

void describe_scene(const config::Scene& scene, std::ostream& out) {
  const grid::UniformGrid grid = initial::scene_grid(scene);
  out << "scene '" << scene.name << "': " << grid.dimension() << "D, end time "
      << sci(scene.time.end) << " s, CFL " << scene.time.fdm_cfl() << " (FDM), "
      << scene.time.mpm_cfl() << " (MPM)\n";
  out << "  grid: " << grid.cells()[0] << " x " << grid.cells()[1] << " x " << grid.cells()[2]
      << " cells of " << vec(grid.spacing()) << " m from " << vec(grid.origin()) << " to "
      << vec(grid.upper()) << " m\n";
  out << "  materials:\n";
  for (const auto& m : scene.materials) {
    out << "    " << m.name << ": eos " << eos::name(m.eos);
    if (const auto* jwl = std::get_if<eos::Jwl>(&m.eos)) {
      const auto cj = eos::chapman_jouguet_state(*jwl);
      out << " (CJ state: p = " << sci(cj.pressure * 1e-9)
          << " GPa, D = " << sci(cj.detonation_velocity) << " m/s, rho = " << sci(cj.density)
          << " kg/m^3)";
    }
    if (m.explosive)
      out << ", detonation velocity " << sci(m.explosive->detonation_velocity) << " m/s";
    out << "\n";
  }
  out << "  initial: " << scene.initial.material << " at " << sci(scene.initial.density)
      << " kg/m^3\n";
  for (const auto& b : scene.bodies)
    out << "  body '" << b.name << "': " << b.state.material << " at " << sci(b.state.density)
        << " kg/m^3\n";
  for (const auto& c : scene.charges)
    out << "  charge '" << c.name << "': " << c.material << ", "
        << (c.burn == config::Burn::program ? "program burn" : "instantaneous burn") << "\n";
  out << "  boundaries:";
  for (std::size_t f = 0; f < 6; ++f)
    out << " " << kFaceName[f] << "=" << kBoundaryName[static_cast<int>(scene.boundaries.faces[f])];
  out << "\n";
  for (const auto& g : scene.gauges)
    out << "  gauge '" << g.name << "' at " << vec(g.position) << " m\n";
  out << "  output every " << sci(scene.output.interval) << " s\n";
}

void write_initial_state(const config::Scene& scene, const std::filesystem::path& scene_file,
                         const std::filesystem::path& out_dir, bool overwrite) {
  const auto start = std::chrono::steady_clock::now();
  const grid::UniformGrid grid = initial::scene_grid(scene);
  const initial::CellFields cells =
      initial::initial_cells(scene, grid);  // may throw: nothing written yet
  io::prepare_output_directory(out_dir, overwrite);

  io::SnapshotWriter snapshots(out_dir, grid);
  snapshots.write(0, 0.0, field_views(cells));

  std::vector<io::GaugePoint> points;
  for (const auto& g : scene.gauges) points.push_back({g.name, g.position});
  io::GaugeRecorder gauges(out_dir, points,
                           {{"density", "kg/m^3"}, {"pressure", "Pa"}, {"velocity_x", "m/s"}});
  std::vector<double> sample;
  for (const auto& g : scene.gauges) {
    const auto where = grid.locate(g.position);
    const std::size_t n = where ? grid.cell_index(where->cell) : 0;
    sample.insert(sample.end(), {cells.density[n], cells.pressure[n], cells.velocity_x[n]});
  }
  gauges.record(0.0, sample);
  gauges.flush();

  double mass = 0.0, energy = 0.0;
  for (std::size_t n = 0; n < grid.cell_count(); ++n) {
    const double u2 = cells.velocity_x[n] * cells.velocity_x[n] +
                      cells.velocity_y[n] * cells.velocity_y[n] +
                      cells.velocity_z[n] * cells.velocity_z[n];
    mass += cells.density[n] * grid.cell_volume();
    energy +=
        cells.density[n] * grid.cell_volume() * (cells.specific_internal_energy[n] + 0.5 * u2);
  }
  io::RunSummary summary("mpfd_scene init", scene.name, scene_file);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.set_progress(0, 0.0, scene.time.end, wall);
  summary.set_conservation({{"mass", "kg", mass, mass, 0.0}, {"energy", "J", energy, energy, 0.0}});
  summary.set_detail("cells", grid.cell_count());
  summary.set_status("completed");
  summary.write(out_dir / "summary.json");
}

}  // namespace mpfd::tools
