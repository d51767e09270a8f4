#include "fdm_solver/euler_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <variant>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/initial/initial_cells.hpp"
#include "fdm_solver/cell_eos.hpp"
#include "fdm_solver/cell_kinematics.hpp"
#include "fdm_solver/pencil_io.hpp"
#include "fdm_solver/sweep_kernel.hpp"
#include "fdm_solver/tracer/tracker_import.hpp"

namespace mpfd::fdm {
namespace {

EulerState initial_state(const config::Scene& scene) {
  const grid::UniformGrid grid = initial::scene_grid(scene);
  const initial::CellFields f = initial::initial_cells(scene, grid);
  EulerState s(grid);
  for (std::size_t n = 0; n < grid.cell_count(); ++n) {
    const double rho = f.density[n];
    const double u2 = f.velocity_x[n] * f.velocity_x[n] + f.velocity_y[n] * f.velocity_y[n] +
                      f.velocity_z[n] * f.velocity_z[n];
    s.u[kDensity][n] = rho;
    s.u[kMomentumX][n] = rho * f.velocity_x[n];
    s.u[kMomentumY][n] = rho * f.velocity_y[n];
    s.u[kMomentumZ][n] = rho * f.velocity_z[n];
    s.u[kEnergy][n] = rho * (f.specific_internal_energy[n] + 0.5 * u2);
    s.material[n] = static_cast<std::uint8_t>(f.material[n]);
  }
  return s;
}

/// How far a sweep can change cells beyond the disturbed box: a cell is left
/// bit for bit unchanged when its neighbours i-2 ... i+2 hold its own state
/// (the viscous exchange of (2-56) multiplies a zero difference whatever the
/// wider reach of its switch theta, so ubar_{i-1..i+1} = U_i and the two face
/// fluxes are equal). kGhost = 3 is what the sweep reads; 2 is what it changes.
constexpr int kChangeReach = 2;

/// Below this many cells a loop runs on one thread (common/core/parallel_for.hpp).
constexpr long long kParallelCells = kMinParallelCount;

std::string position_text(const grid::Vec3& x) {
  return "(" + std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " + std::to_string(x[2]) +
         ") m";
}

}  // namespace

SolverOptions SolverOptions::from_scene(const config::Scene& scene) {
  const auto& fdm = scene.solver.fdm;
  return {.cfl = scene.time.fdm_cfl(),
          .viscosity = fdm.artificial_viscosity,
          .switch_power = fdm.viscosity_switch_power,
          .tracers_per_axis = fdm.tracers_per_axis};
}

EulerSolver::EulerSolver(const config::Scene& scene, SolverOptions options)
    : state_(initial_state(scene)), boundaries_(scene.boundaries), options_(options) {
  if (scene.materials.size() > 255) throw Error("fdm_solver: at most 255 materials");
  if (options.switch_power < 1 || options.switch_power > 4)
    throw Error("fdm_solver: the viscosity switch power must be 1, 2, 3 or 4, got " +
                std::to_string(options.switch_power));
  for (const auto& m : scene.materials) eos_.push_back(m.eos);
  const auto& n = state_.grid.cells();
  const std::size_t longest = static_cast<std::size_t>(std::max({n[0], n[1], n[2]}));
  pencils_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& p : pencils_) p.resize(longest + 2 * kGhost);
  const auto& m = state_.material;
  if (std::any_of(m.begin(), m.end(), [&](std::uint8_t x) { return x != m.front(); })) {
    allocate_multi_material();
    const std::size_t cells = state_.grid.cell_count();
    const std::vector<double> material(m.begin(), m.end());
    parallel_for(cells, [&](std::size_t c) { energy_[c] = specific_internal_energy(state_, c); });
    tracker_.emplace(state_.grid, eos_, material, state_.u[kDensity], energy_,
                     options_.tracers_per_axis);
    update_materials();
  }
  find_still_cells();
  for (int face = 0; face < 6; ++face)
    face_outflow_[static_cast<std::size_t>(face)].assign(
        kVariables * quiet_flux_.flux[static_cast<std::size_t>(face)][0].size(), 0.0);
}

void EulerSolver::allocate_multi_material() {
  const std::size_t cells = state_.grid.cell_count();
  state_.mix_gamma.assign(cells, 0.0);
  state_.mix_pinf.assign(cells, 0.0);
  for (auto& v : velocity_) v.assign(cells, 0.0);
  energy_.assign(cells, 0.0);
  pressure_.assign(cells, 0.0);
  for (int f = 0; f < 6; ++f)
    tracer_faces_[static_cast<std::size_t>(f)] =
        boundaries_[static_cast<config::Face>(f)] == config::BoundaryKind::outflow
            ? TracerFace::outflow
            : TracerFace::reflect;
}

void EulerSolver::find_still_cells() {
  const auto& n = state_.grid.cells();
  box_ = options_.skip_quiet ? disturbed_cells(state_, boundaries_) : whole_grid(state_.grid);
  quiet_flux_ = quiet_face_flux(state_, boundaries_, eos_);
  still_line_limit_.resize(static_cast<std::size_t>(n[1]) * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      still_line_limit_[static_cast<std::size_t>(j + n[1] * k)] =
          line_limit(state_.grid.cell_index(0, j, k), 0, n[0]);
  if (watched_axis_ >= 0) {  // a watched face's cells stay in the box for good
    ActiveBox faces = whole_grid(state_.grid);
    faces.lower[watched_axis_] = watched_index_ - 1;
    faces.upper[watched_axis_] = watched_index_ + 1;
    (void)state_for_update(faces);
  }
}

double EulerSolver::line_limit(std::size_t start, int from, int to) const {
  // One EOS dispatch per segment when it holds one material. The formula is
  // the sweep kernel's (cell_kinematics.hpp), so both give the same bits.
  const auto& g = state_.grid;
  const auto& u = state_.u;
  const auto& mat = state_.material;
  const std::size_t first = start + static_cast<std::size_t>(from);
  const std::size_t last = start + static_cast<std::size_t>(to);
  const double inv_dx[3] = {1.0 / g.spacing()[0], 1.0 / g.spacing()[1], 1.0 / g.spacing()[2]};
  if (first >= last) return std::numeric_limits<double>::infinity();
  double rate = 0.0;
  const auto scan = [&](const auto& sound_speed_at) {
    for (std::size_t i = first; i < last; ++i) {
      const double rho = u[kDensity][i];
      const double inv_rho = 1.0 / rho;
      const double m[3] = {u[kMomentumX][i], u[kMomentumY][i], u[kMomentumZ][i]};
      const double e = internal_energy_per_mass(inv_rho, m[0], m[1], m[2], u[kEnergy][i]);
      const double c = sound_speed_at(i, rho, e);
      for (int a = 0; a < 3; ++a)
        if (g.is_active(a)) rate = std::max(rate, crossing_rate(inv_dx[a], m[a], inv_rho, c));
    }
  };
  const bool one_material =
      mat[first] != kMixedMaterial && std::all_of(mat.begin() + static_cast<std::ptrdiff_t>(first),
                                                  mat.begin() + static_cast<std::ptrdiff_t>(last),
                                                  [&](std::uint8_t m) { return m == mat[first]; });
  if (one_material) {
    std::visit(
        [&](const auto& model) {
          scan([&](std::size_t, double rho, double e) { return model.sound_speed(rho, e); });
        },
        eos_[mat[first]]);
  } else {
    scan([&](std::size_t i, double rho, double e) {
      return cell_sound_speed(state_, eos_, i, rho, e);
    });
  }
  return 1.0 / rate;  // 1/max = min of 1/rate, bit for bit (division is monotonic)
}

double EulerSolver::still_limit() const {
  const auto& n = state_.grid.cells();
  double limit = std::numeric_limits<double>::infinity();
#pragma omp parallel for collapse(2) reduction(min      \
                                               : limit) \
    schedule(static) if (state_.grid.cell_count() >= kParallelCells)
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j) {
      const bool outside = box_.empty() || j < box_.lower[1] || j >= box_.upper[1] ||
                           k < box_.lower[2] || k >= box_.upper[2];
      if (outside) {
        limit = std::min(limit, still_line_limit_[static_cast<std::size_t>(j + n[1] * k)]);
        continue;
      }
      const std::size_t start = state_.grid.cell_index(0, j, k);
      limit = std::min(
          {limit, line_limit(start, 0, box_.lower[0]), line_limit(start, box_.upper[0], n[0])});
    }
  return limit;
}

double EulerSolver::stable_dt() const {
  return 2.0 * options_.cfl * (limit_after_step_ ? *limit_after_step_ : grid_limit());
}

double EulerSolver::grid_limit() const {
  const auto& n = state_.grid.cells();
  double limit = std::numeric_limits<double>::infinity();
  // Lines outside the disturbed box are as they started: use their cached limit.
#pragma omp parallel for collapse(2) reduction(min      \
                                               : limit) \
    schedule(static) if (state_.grid.cell_count() >= kParallelCells)
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j) {
      const bool still = box_.empty() || j < box_.lower[1] || j >= box_.upper[1] ||
                         k < box_.lower[2] || k >= box_.upper[2];
      const double line = still ? still_line_limit_[static_cast<std::size_t>(j + n[1] * k)]
                                : line_limit(state_.grid.cell_index(0, j, k), 0, n[0]);
      limit = std::min(limit, line);
    }
  return limit;
}

double EulerSolver::step_toward(double target) const {
  const double dt = stable_dt();
  const double left = target - time_;
  if (left <= dt) return left;
  return left < 2.0 * dt ? 0.5 * left : dt;
}

void EulerSolver::advance_to(double end) {
  while (time_ < end) advance(step_toward(end));
}

void EulerSolver::advance(double dt) {
  MPFD_ASSERT(dt > 0.0 && std::isfinite(dt), "time step must be positive and finite");
  const auto& g = state_.grid;
  if (tracker_) {  // tracers move with the velocities of time level n, T (3-13)
    const auto& u = state_.u;
    parallel_for(g.cell_count(), [&](std::size_t c) {
      for (std::size_t a = 0; a < 3; ++a) velocity_[a][c] = u[kMomentumX + a][c] / u[kDensity][c];
    });
    tracker_->advect(VelocityView{{velocity_[0], velocity_[1], velocity_[2]}}, dt, tracer_faces_);
  }
  limit_after_step_.reset();
  // One material everywhere and no mixed cells: the sweeps need not look at
  // materials cell by cell. Checked every step (a restore or data from
  // outside may change them; the scan costs ~1e-3 of a step).
  const auto& m = state_.material;
  only_material_.reset();
  if (m.front() != kMixedMaterial &&
      std::all_of(m.begin(), m.end(), [&](std::uint8_t x) { return x == m.front(); }))
    only_material_ = m.front();
  // T (2-52): U^{n+1} = Lz Ly Lx Lx Ly Lz U^n, each over dt/2; the rightmost acts first.
  // Two sweeps in a row along one axis (x x, or the only axis of a 1D grid)
  // run together: their lines are read and written once.
  std::array<int, 6> axes{};
  int count = 0;
  for (const int axis : {2, 1, 0, 0, 1, 2})
    if (g.is_active(axis)) axes[static_cast<std::size_t>(count++)] = axis;
  double limit = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count;) {
    const int axis = axes[static_cast<std::size_t>(k)];
    const bool twice = k + 1 < count && axes[static_cast<std::size_t>(k + 1)] == axis;
    k += twice ? 2 : 1;
    limit = sweep(axis, 0.5 * dt, twice, k == count && !tracker_);
  }
  // The next step's limit comes from the last sweep where cells moved; a
  // mixed cell's EOS is refitted after it, so then a separate scan is needed.
  // Either way the step finds it, so a coupler's ProposeDt only reads it.
  if (!tracker_) {
    limit_after_step_ = std::min(limit, still_limit());
  } else {
    parallel_for(g.cell_count(),
                 [&](std::size_t c) { energy_[c] = specific_internal_energy(state_, c); });
    update_materials();
    limit_after_step_ = grid_limit();
  }
  time_ += dt;
  ++steps_;
}

double EulerSolver::sweep(int axis, double dt, bool twice, bool last_of_step) {
  const auto& g = state_.grid;
  const auto& n = g.cells();
  const int sweeps = twice ? 2 : 1;
  // The range of updated cells along the axis of each sweep: the box grows
  // before each. The lines (the other two axes) are the same for both.
  std::array<std::size_t, 2> first{}, last{};
  for (int k = 0; k < sweeps; ++k) {
    if (options_.skip_quiet) box_.grow(axis, kChangeReach, n[axis]);
    first[k] = static_cast<std::size_t>(box_.lower[axis]);
    last[k] = static_cast<std::size_t>(box_.upper[axis]);
  }
  double fastest = std::numeric_limits<double>::infinity();
  if (box_.empty()) {
    for (int k = 0; k < sweeps; ++k) count_quiet_faces(axis, dt, false, false);
    return fastest;
  }
  // The two other axes; a1 varies fastest from pencil to pencil, and is x
  // whenever possible so that neighbouring pencils share cache lines.
  const int a1 = axis == 0 ? 1 : 0, a2 = 3 - axis - a1;
  const std::size_t stride = g.cell_index(axis == 0, axis == 1, axis == 2);
  const AxisBoundaries faces{boundaries_[static_cast<config::Face>(2 * axis)],
                             boundaries_[static_cast<config::Face>(2 * axis + 1)]};
  const SweepStep step{dt, g.spacing()[axis], options_.viscosity, options_.switch_power};
  const double face_area = g.spacing()[a1] * g.spacing()[a2];
  std::array<bool, 2> at_lower{}, at_upper{};
  for (int k = 0; k < sweeps; ++k) {
    at_lower[k] = first[k] == 0;
    at_upper[k] = last[k] == static_cast<std::size_t>(n[axis]);
  }
  const int lines1 = box_.upper[a1] - box_.lower[a1];
  const int lines2 = box_.upper[a2] - box_.lower[a2];

  // Blocks of neighbouring lines along a1 (lanes), except for x-sweeps whose
  // lines are already contiguous.
  const std::size_t lane_width = axis == 0 ? 1 : kMaxLanes;
  const std::size_t lane_stride = g.cell_index(a1 == 0, a1 == 1, a1 == 2);
  const int blocks1 =
      static_cast<int>((static_cast<std::size_t>(lines1) + lane_width - 1) / lane_width);

  // The pencil slots of the x, y, z momenta (pencil_io.cpp rotates them).
  CrossingTimeRequest crossing{};
  for (int b = 0; b < 3; ++b) {
    crossing.slot[static_cast<std::size_t>(b)] = 1 + static_cast<std::size_t>((b - axis + 3) % 3);
    crossing.inv_spacing[static_cast<std::size_t>(b)] = 1.0 / g.spacing()[b];
    crossing.active[static_cast<std::size_t>(b)] = g.is_active(b);
  }
  double leaving[2][kVariables] = {};  // arrays, for the OpenMP reduction
  // Boundary cells of the faces normal to axis, numbered as in QuietFaceFlux.
  const int q1 = (axis + 1) % 3, q2 = (axis + 2) % 3;
  const auto face_line = [&](const grid::Index3& cell) {
    return static_cast<std::size_t>(cell[q1] + n[q1] * cell[q2]);
  };
  std::vector<double>& lower_outflow = face_outflow_[static_cast<std::size_t>(2 * axis)];
  std::vector<double>& upper_outflow = face_outflow_[static_cast<std::size_t>(2 * axis + 1)];
  const std::size_t tap = axis == watched_axis_ ? static_cast<std::size_t>(watched_index_) : 0;
  std::optional<std::pair<grid::Index3, BadCell>> bad;
  const long long work =
      static_cast<long long>(last[sweeps - 1] - first[sweeps - 1]) * lines1 * lines2;
#pragma omp parallel reduction(+ : leaving[:2][:kVariables]) reduction(min : fastest) if (work >= kParallelCells)
  {
    Pencil& pencil = pencils_[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for collapse(2) schedule(static)
    for (int l2 = 0; l2 < lines2; ++l2)
      for (int b1 = 0; b1 < blocks1; ++b1) {
        grid::Index3 origin{};
        origin[a1] = box_.lower[a1] + b1 * static_cast<int>(lane_width);
        origin[a2] = box_.lower[a2] + l2;
        const std::size_t lanes =
            std::min(lane_width, static_cast<std::size_t>(box_.upper[a1] - origin[a1]));
        const PencilBlock block{axis,        g.cell_index(origin),
                                stride,      static_cast<std::size_t>(n[axis]),
                                lane_stride, lanes};
        const BlockTransfer t1{state_, block, faces, first[0], last[0], only_material_, tap};
        const BlockTransfer t2{state_, block, faces, first[1], last[1], only_material_, tap};
        std::array<EndFluxes, 2> ends;
        const CrossingTimeRequest* asked = last_of_step ? &crossing : nullptr;
        const auto problem =
            twice ? sweep_block_twice(pencil, t1, t2, step, eos_, ends, asked, &fastest)
                  : sweep_block(pencil, t1, step, eos_, ends[0], asked, &fastest);
        if (problem) {
#pragma omp critical(mpfd_fdm_bad_cell)
          if (!bad) {
            grid::Index3 cell = origin;
            cell[axis] = static_cast<int>(problem->position - kGhost);
            cell[a1] += static_cast<int>(problem->lane);
            bad.emplace(cell, *problem);
          }
          continue;
        }
        // Momentum slots are rotated in the pencil; map them back to x, y, z.
        // Each block owns its lines' entries of the per-line arrays.
        for (int k = 0; k < sweeps; ++k)
          for (std::size_t lane = 0; lane < lanes; ++lane) {
            grid::Index3 cell = origin;
            cell[a1] += static_cast<int>(lane);
            const std::size_t line = face_line(cell);
            for (std::size_t s = 0; s < kVariables; ++s) {
              std::size_t v = s;
              if (s >= 1 && s <= 3) v = 1 + (static_cast<std::size_t>(axis) + s - 1) % 3;
              const double down = ends[k].lower[lane][s] * face_area;
              const double up = ends[k].upper[lane][s] * face_area;
              if (at_lower[k]) {
                leaving[k][v] -= down;
                lower_outflow[line * kVariables + v] -= down;
              }
              if (at_upper[k]) {
                leaving[k][v] += up;
                upper_outflow[line * kVariables + v] += up;
              }
              if (tap != 0)
                watched_crossing_[line * kVariables + v] += ends[k].tapped[lane][s] * face_area;
            }
          }
      }
  }
  if (bad) {
    const auto& [cell, value] = *bad;
    // p <= 0 in a scene with water or a solid is tension or the reference state (e = 0), not
    // an overshoot a smaller step avoids: water or steel beside air stops at step 0 at CFL 0.1
    // as at 0.5, a steel body at e = 0 has p = 0 from the start (docs/stability.md, part 2).
    // The cell's own label may still be the gas's while the contact's flux has brought the
    // water or solid in (cell 49 beside the water at step 0), so the scene's materials decide.
    const bool holds_condensed = std::any_of(eos_.begin(), eos_.end(), [](const eos::AnyEos& eos) {
      return std::holds_alternative<eos::MieGruneisen>(eos) ||
             std::holds_alternative<eos::Polynomial>(eos);
    });
    const bool condensed = value.density > 0.0 && value.pressure <= 0.0 && holds_condensed;
    throw Error("fdm_solver: unphysical state in cell (" + std::to_string(cell[0]) + ", " +
                std::to_string(cell[1]) + ", " + std::to_string(cell[2]) + ") at " +
                position_text(g.cell_center(cell)) + ", t = " + std::to_string(time_) +
                " s (step " + std::to_string(steps_) + "): density " +
                std::to_string(value.density) + " kg/m^3, pressure " +
                std::to_string(value.pressure) + " Pa; both must stay positive. " +
                (condensed ? std::string("With water or a solid in the scene, a pressure <= 0 is "
                                         "tension or a body at its reference state (e = 0), which "
                                         "the FDM cannot hold (no strength or cavitation model); "
                                         "a water or solid body beside a gas reaches it in the "
                                         "first steps: keep such bodies out of the FDM's grid "
                                         "(time.cfl does not help).")
                           : std::string("Reduce time.cfl or refine the grid.")));
  }
  for (int k = 0; k < sweeps; ++k) {
    for (std::size_t v = 0; v < kVariables; ++v) outflow_[v] += leaving[k][v];
    count_quiet_faces(axis, dt, at_lower[k], at_upper[k]);
    // A cell-update is one cell advanced by one whole step: a share of the
    // step's sweeps.
    cell_updates_ +=
        static_cast<double>(last[k] - first[k]) * lines1 * lines2 / (2.0 * g.dimension());
  }
  return fastest;
}

void EulerSolver::count_quiet_faces(int axis, double dt, bool lower_updated, bool upper_updated) {
  const auto& g = state_.grid;
  if (!g.is_active(axis)) return;
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double impulse = dt * g.spacing()[a1] * g.spacing()[a2];
  const bool covers_face = box_.lower[a1] == 0 && box_.upper[a1] == g.cells()[a1] &&
                           box_.lower[a2] == 0 && box_.upper[a2] == g.cells()[a2];
  for (const int side : {0, 1}) {
    const int face = 2 * axis + side;
    const bool updated = side == 0 ? lower_updated : upper_updated;
    const double sign = side == 0 ? -1.0 : 1.0;  // leaving: -x through the lower face
    for (std::size_t v = 0; v < kVariables; ++v) {
      if (updated && covers_face) continue;  // the sweep counted every line itself
      double still = quiet_flux_.total[face][v];
      if (updated)  // the box's lines were counted by the sweep itself
        for (int l2 = box_.lower[a2]; l2 < box_.upper[a2]; ++l2)
          for (int l1 = box_.lower[a1]; l1 < box_.upper[a1]; ++l1)
            still -= quiet_flux_.flux[face][v][static_cast<std::size_t>(l1 + g.cells()[a1] * l2)];
      outflow_[v] += sign * still * impulse;
    }
    // The same per boundary cell, for face_outflow().
    auto& cells = face_outflow_[static_cast<std::size_t>(face)];
    for (int l2 = 0; l2 < g.cells()[a2]; ++l2)
      for (int l1 = 0; l1 < g.cells()[a1]; ++l1) {
        const bool swept = updated && l1 >= box_.lower[a1] && l1 < box_.upper[a1] &&
                           l2 >= box_.lower[a2] && l2 < box_.upper[a2];
        if (swept) continue;
        const auto line = static_cast<std::size_t>(l1 + g.cells()[a1] * l2);
        for (std::size_t v = 0; v < kVariables; ++v)
          cells[line * kVariables + v] += sign * quiet_flux_.flux[face][v][line] * impulse;
      }
  }
}

void EulerSolver::watch_face(int axis, int index) {
  const auto& g = state_.grid;
  if (axis < 0 || axis > 2 || !g.is_active(axis) || index <= 0 || index >= g.cells()[axis])
    throw Error(
        "fdm_solver: a watched face must lie between two cells of an active axis; got "
        "axis " +
        std::to_string(axis) + ", face below cell " + std::to_string(index));
  ActiveBox faces = whole_grid(g);
  faces.lower[axis] = index - 1;
  faces.upper[axis] = index + 1;
  (void)state_for_update(faces);
  watched_axis_ = axis;
  watched_index_ = index;
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  watched_crossing_.assign(kVariables * static_cast<std::size_t>(g.cells()[a1]) * g.cells()[a2],
                           0.0);
}

void EulerSolver::clear_watched_crossing() {
  std::fill(watched_crossing_.begin(), watched_crossing_.end(), 0.0);
}

void EulerSolver::update_materials() {
  closure_ = tracker_->update_pressure(state_.u[kDensity], energy_, pressure_);
  const MaterialMap& map = tracker_->materials();
  const MaterialStates& parts = tracker_->states();
  const std::size_t cells = state_.grid.cell_count();
  for (std::size_t c = 0; c < cells; ++c) {
    if (!map.is_mixed(c)) {
      state_.material[c] = static_cast<std::uint8_t>(map.material[c]);
      continue;
    }
    // Wood's mixture sound speed: 1/(rho c^2) = sum_r theta_r / (rho_r c_r^2).
    const double rho = state_.u[kDensity][c];
    double compliance = 0.0;
    for (int r = 0; r < map.material_count; ++r) {
      const double theta = map.theta[static_cast<std::size_t>(r) * cells + c];
      if (theta <= 0.0) continue;
      const std::size_t k = parts.at(r, c);
      const double cr =
          eos::sound_speed(eos_[static_cast<std::size_t>(r)], parts.density[k], parts.energy[k]);
      compliance += theta / (parts.density[k] * cr * cr);
    }
    const StiffenedGas fit =
        fit_stiffened_gas(rho, energy_[c], pressure_[c], 1.0 / (rho * compliance));
    state_.material[c] = kMixedMaterial;
    state_.mix_gamma[c] = fit.gamma;
    state_.mix_pinf[c] = fit.pinf;
  }
}

EulerState& EulerSolver::state_for_update(const ActiveBox& region) {
  if (region.empty()) return state_;
  limit_after_step_.reset();
  if (box_.empty()) {
    box_ = region;
  } else {
    for (int a = 0; a < 3; ++a) {
      box_.lower[a] = std::min(box_.lower[a], region.lower[a]);
      box_.upper[a] = std::max(box_.upper[a], region.upper[a]);
    }
  }
  return state_;
}

void EulerSolver::restore(const EulerState& state, double time, std::int64_t steps,
                          const Totals& outflow, const FaceOutflow& face_outflow,
                          std::optional<TrackerState> tracker) {
  if (tracker_ && !tracker)
    throw Error("fdm_solver: restore without tracer state into a solver of " +
                std::to_string(eos_.size()) + " materials with tracers");
  check_grid_of(state, "restored");
  if (state.material.size() != state_.material.size())
    throw Error("fdm_solver: restored state does not match the solver's grid of " +
                std::to_string(state_.grid.cell_count()) + " cells");
  const std::size_t mixture_size = tracker ? state_.grid.cell_count() : 0;
  if (state.mix_gamma.size() != mixture_size || state.mix_pinf.size() != mixture_size)
    throw Error("fdm_solver: restored mixed-cell fields hold " +
                std::to_string(state.mix_gamma.size()) + " and " +
                std::to_string(state.mix_pinf.size()) + " values; with" + (tracker ? "" : "out") +
                " tracer state they need " + std::to_string(mixture_size));
  for (std::size_t f = 0; f < face_outflow_.size(); ++f)
    if (face_outflow[f].size() != face_outflow_[f].size())
      throw Error(std::string("fdm_solver: restored outflow of face ") + config::kFaceNames[f] +
                  " holds " + std::to_string(face_outflow[f].size()) + " values; its " +
                  std::to_string(face_outflow_[f].size() / kVariables) + " boundary cells need " +
                  std::to_string(face_outflow_[f].size()));
  if (tracker_) {
    tracker_->restore(std::move(*tracker));  // checks before it changes anything
  } else if (tracker) {                      // tracers an import gave a zone of one material
    tracker_.emplace(state_.grid, eos_, std::move(*tracker));  // checks, as restore
    allocate_multi_material();
  }
  if (tracker_) closure_ = closure_report(tracker_->states());
  state_.u = state.u;
  state_.material = state.material;
  state_.mix_gamma = state.mix_gamma;
  state_.mix_pinf = state.mix_pinf;
  time_ = time;
  steps_ = steps;
  outflow_ = outflow;
  face_outflow_ = face_outflow;
  clear_watched_crossing();
  limit_after_step_.reset();
  // Exactness over speed: every cell is updated from here on (skip_quiet would
  // need the still region, which a checkpoint does not record).
  box_ = whole_grid(state_.grid);
}

void EulerSolver::check_grid_of(const EulerState& state, const char* what) const {
  const std::size_t cells = state_.grid.cell_count();
  if (state.grid.cells() != state_.grid.cells() ||
      std::any_of(state.u.begin(), state.u.end(),
                  [&](const std::vector<double>& v) { return v.size() != cells; }))
    throw Error(std::string("fdm_solver: ") + what + " state does not match the solver's grid of " +
                std::to_string(cells) + " cells");
}

void EulerSolver::import_state(EulerState cells, std::optional<TracerSet> tracers,
                               const MaterialStartView& start) {
  check_grid_of(cells, "imported");
  const std::size_t count = state_.grid.cell_count();
  const bool was_multi_material = tracker_.has_value();
  std::optional<TrackerState> next;
  std::vector<double> energy(count);
  parallel_for(count, [&](std::size_t c) { energy[c] = specific_internal_energy(cells, c); });
  if (tracers || tracker_) {
    // Where the grid holds no tracer at all the cells keep their material.
    std::vector<int> fallback(count);
    for (std::size_t c = 0; c < count; ++c)
      fallback[c] = state_.material[c] == kMixedMaterial ? 0 : state_.material[c];
    TracerSet points = tracers ? std::move(*tracers) : tracker_->tracers();
    // Once the points are accepted nothing throws (but for memory): the old
    // tracker goes before the new one is built, one tracker's memory at a time.
    next =
        tracker_from_points(state_.grid, static_cast<int>(eos_.size()), std::move(points), fallback,
                            cells.u[kDensity], energy, start, [this] { tracker_.reset(); });
  }
  // Nothing below throws (but for memory): the import is all or nothing. A
  // state from tracker_from_points passes the tracker's restore checks.
  if (next) {
    // A solver of one material validates its EOS here, first: so it stays unchanged if that throws.
    tracker_.emplace(state_.grid, eos_, std::move(*next));
    if (!was_multi_material) allocate_multi_material();
  }
  state_.u = std::move(cells.u);
  if (next) {
    energy_ = std::move(energy);
    update_materials();
  }
  limit_after_step_.reset();
  find_still_cells();
}

Totals EulerSolver::totals() const {
  Totals sum{};
  const double volume = state_.grid.cell_volume();
  for (std::size_t v = 0; v < kVariables; ++v) {
    double s = 0.0;
    const auto& u = state_.u[v];
#pragma omp parallel for reduction(+ : s) schedule(static) if (u.size() >= kParallelCells)
    for (std::size_t i = 0; i < u.size(); ++i) s += u[i];
    sum[v] = s * volume;
  }
  return sum;
}

}  // namespace mpfd::fdm
