#pragma once
// What the checkpoint tests share: a temporary folder, the Checkpoint and
// Restore requests, a small 2D two-material scene, and the whole state of a
// zone's solver (cells, clock, outflow, tracker) to compare bit for bit.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fdm_solver/serve/served_zone.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm::testing {

/// A fresh temporary folder, removed at the end of the test.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(std::filesystem::temp_directory_path() /
              ("mpfd-fdm-checkpoint-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline cosim::Message checkpoint_to(const std::string& path) {
  cosim::Message message;
  message.header.mutable_checkpoint()->set_path(path);
  return message;
}

inline cosim::Message restore_from(const std::string& path, std::uint64_t step) {
  cosim::Message message;
  message.header.mutable_restore()->set_path(path);
  message.header.mutable_restore()->set_step(step);
  return message;
}

/// TNT detonation products at their CJ state (configs/jwl_air_tube.yaml) in
/// the 4 x 4 cell corner of an `nx` x `ny` grid of 1 cm cells, air at rest
/// elsewhere; walls on the lower faces (symmetry planes), outflow on the upper
/// ones. 3 x 3 tracers per cell: steps 2-13 have mixed cells, from step 11 on
/// cells without tracers are filled, from step 15 on tracers leave the grid.
/// `products: false` leaves only air.
inline std::string corner_charge_text(int nx, int ny, bool products = true) {
  std::string text =
      "name: corner_charge\ntime: {end: 1.0e-4, cfl: 0.5}\n"
      "domain: {lower: [0, 0, 0], upper: [" +
      std::to_string(0.01 * nx) + ", " + std::to_string(0.01 * ny) + ", 0.01], cells: [" +
      std::to_string(nx) + ", " + std::to_string(ny) +
      ", 1]}\n"
      "materials:\n"
      "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n";
  if (products)
    text +=
        "  products:\n"
        "    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3,\n"
        "          E0: 6.993e9}\n";
  text +=
      "initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}\n"
      "boundaries: {x_lower: wall, x_upper: outflow, y_lower: wall, y_upper: outflow}\n"
      "output: {interval: 1.0}\n"
      "solver: {fdm: {tracers_per_axis: 3}}\n";
  if (products)
    text +=
        "bodies:\n"
        "  - {name: charge, material: products, density: 2227.47, pressure: 2.0984e10,\n"
        "     shape: {box: {lower: [0, 0, 0], upper: [0.04, 0.04, 0.01]}}}\n";
  return text;
}

/// The zone a Setup of `scene` builds, driven directly (no transport), so that
/// a test sees its tracers.
inline std::unique_ptr<ServedZone> zone_of(const std::string& scene,
                                           const std::filesystem::path& output_dir = {}) {
  return set_up_zone(setup(scene, {}, output_dir.string()).header.setup());
}

/// Advances `steps` steps, each of the solver's stable dt.
inline void advance_stable(ServedZone& zone, int steps) {
  for (int s = 0; s < steps; ++s) zone.solver.advance(zone.solver.stable_dt());
}

/// Everything a zone's next step reads, and its clock, to compare with ==.
struct SolverImage {
  std::array<std::vector<double>, kVariables> u;
  std::vector<std::uint8_t> material;
  std::vector<double> mix_gamma, mix_pinf;
  double time = 0.0;
  std::int64_t steps = 0;
  std::array<double, kVariables> outflow{};
  FaceOutflow face_outflow;
  std::array<std::vector<double>, 3> tracer_position;
  std::vector<int> tracer_material;
  std::vector<double> tracer_volume;
  std::vector<int> cell_material;
  std::vector<double> theta, material_energy, material_density, cell_energy;
  std::vector<ClosureStatus> status;
  std::size_t mixed_cells = 0;

  explicit SolverImage(const EulerSolver& solver)
      : u(solver.state().u),
        material(solver.state().material),
        mix_gamma(solver.state().mix_gamma),
        mix_pinf(solver.state().mix_pinf),
        time(solver.time()),
        steps(solver.steps()),
        outflow(solver.outflow()),
        face_outflow(solver.face_outflow()),
        mixed_cells(solver.last_closure().mixed_cells) {
    if (const MultiMaterialTracker* tracker = solver.tracker()) {
      tracer_position = tracker->tracers().position;
      tracer_material = tracker->tracers().material;
      tracer_volume = tracker->tracers().volume;
      cell_material = tracker->materials().material;
      theta = tracker->materials().theta;
      material_energy = tracker->states().energy;
      material_density = tracker->states().density;
      cell_energy = tracker->states().cell_energy;
      status = tracker->states().status;
    }
  }
  bool operator==(const SolverImage&) const = default;
};

}  // namespace mpfd::fdm::testing
