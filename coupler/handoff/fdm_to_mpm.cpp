#include "coupler/handoff/fdm_to_mpm.hpp"

#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "coupler/handoff/grid_stencil.hpp"

namespace mpfd::coupler::handoff {
namespace {

// Tracer indices grouped by cell (counting sort): the tracers of cell c are
// order[start[c] .. start[c + 1]).
struct TracerBins {
  std::vector<std::size_t> start;
  std::vector<std::size_t> order;
};

TracerBins bin_tracers(const grid::UniformGrid& grid, const TracerView& tracers) {
  const std::size_t cells = grid.cell_count();
  std::vector<std::size_t> cell_of(tracers.size());
  TracerBins bins{std::vector<std::size_t>(cells + 1, 0), std::vector<std::size_t>(tracers.size())};
  for (std::size_t t = 0; t < tracers.size(); ++t) {
    const grid::Vec3 x{tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]};
    const auto where = grid.locate(x);
    if (!where)
      throw Error("fdm_to_mpm: tracer " + std::to_string(t) + " at (" + shortest_text(x[0]) + ", " +
                  shortest_text(x[1]) + ", " + shortest_text(x[2]) + ") must lie inside the grid");
    cell_of[t] = grid.cell_index(where->cell);
    ++bins.start[cell_of[t] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) bins.start[c + 1] += bins.start[c];
  std::vector<std::size_t> fill(bins.start.begin(), bins.start.end() - 1);
  for (std::size_t t = 0; t < tracers.size(); ++t) bins.order[fill[cell_of[t]]++] = t;
  return bins;
}

void check_state(const grid::UniformGrid& grid, const FdmEnd& state) {
  const std::size_t cells = grid.cell_count();
  check_sizes(state.cells, cells);
  check_sizes(state.tracers);
  require(state.material_count >= 1, "fdm_to_mpm", "material_count", state.material_count, ">= 1");
  const std::size_t per_material = static_cast<std::size_t>(state.material_count) * cells;
  const auto expect = [](std::size_t got, std::size_t want, const char* name) {
    if (got != want)
      throw Error(std::string("fdm_to_mpm: ") + name + " must have " + std::to_string(want) +
                  " entries, got " + std::to_string(got));
  };
  expect(state.pressure.size(), cells, "pressure");
  expect(state.cell_material.size(), cells, "cell_material");
  expect(state.volume_fraction.size(), per_material, "volume_fraction");
  expect(state.material_density.size(), per_material, "material_density");
  expect(state.material_energy.size(), per_material, "material_energy");
  const auto in_range = [&](int r) { return r >= 0 && r < state.material_count; };
  for (std::size_t c = 0; c < cells; ++c)
    if (state.cell_material[c] != kMixedCell && !in_range(state.cell_material[c]))
      throw Error("fdm_to_mpm: cell_material[" + std::to_string(c) + "] must be " +
                  std::to_string(kMixedCell) + " (mixed) or in [0, " +
                  std::to_string(state.material_count) + "), got " +
                  std::to_string(state.cell_material[c]));
  for (std::size_t t = 0; t < state.tracers.size(); ++t)
    if (!in_range(state.tracers.material[t]))
      throw Error("fdm_to_mpm: tracer " + std::to_string(t) + " material must be in [0, " +
                  std::to_string(state.material_count) + "), got " +
                  std::to_string(state.tracers.material[t]));
}

// What one cell hands over: its velocity, pressure and internal energy.
struct CellState {
  double mass;
  std::array<double, 3> velocity;
  double internal_energy;  // [J]
  double pressure;
};

CellState cell_state(const FdmEnd& state, std::size_t c, double volume) {
  CellState s{};
  const double rho = state.cells.density[c];
  s.mass = rho * volume;
  double kinetic = 0.0;
  for (int a = 0; a < 3; ++a) {
    s.velocity[a] = state.cells.momentum[a][c] / rho;  // T (3-15)
    kinetic += 0.5 * s.mass * s.velocity[a] * s.velocity[a];
  }
  s.internal_energy = state.cells.total_energy[c] * volume - kinetic;
  s.pressure = state.pressure[c];
  return s;
}

class ParticleWriter {
 public:
  ParticleWriter(const grid::UniformGrid& grid, ParticleSet& out) : grid_(grid), out_(out) {}

  void put(std::size_t p, const grid::Vec3& x, double mass, double energy, double volume,
           const CellState& s, int material) const {
    for (int a = 0; a < 3; ++a) {
      out_.position[a][p] = x[a];
      out_.velocity[a][p] = s.velocity[a];
    }
    out_.mass[p] = mass;
    out_.volume[p] = volume;
    out_.internal_energy[p] = energy;
    out_.pressure[p] = s.pressure;  // T (3-17): sigma_p = -p_c I
    out_.material[p] = material;
  }

  // 2^d particles at x_c +- h / 4 on the active axes (T (3-18)) sharing
  // `mass`, `energy` and `volume` equally (T (3-14), (3-16)); returns the next index.
  std::size_t put_regular(std::size_t p, const grid::Index3& cell, double mass, double energy,
                          double volume, const CellState& s, int material) const {
    const grid::Vec3 centre = grid_.cell_center(cell);
    const int n = corner_count(grid_);
    for (int corner = 0; corner < n; ++corner) {
      grid::Vec3 x = centre;
      int bit = 0;
      for (int a = 0; a < 3; ++a) {
        if (!grid_.is_active(a)) continue;
        x[a] += (((corner >> bit) & 1) ? 0.25 : -0.25) * grid_.spacing()[a];  // T (3-18)
        ++bit;
      }
      put(p++, x, mass / n, energy / n, volume / n, s, material);
    }
    return p;
  }

 private:
  const grid::UniformGrid& grid_;
  ParticleSet& out_;
};

}  // namespace

ParticleSet fdm_to_mpm(const grid::UniformGrid& grid, const FdmEnd& state) {
  check_state(grid, state);
  const std::size_t cells = grid.cell_count();
  const auto regular = static_cast<std::size_t>(corner_count(grid));
  const double volume = grid.cell_volume();
  const TracerBins bins = bin_tracers(grid, state.tracers);
  const auto index = [&](int r, std::size_t c) {
    return c * static_cast<std::size_t>(state.material_count) + static_cast<std::size_t>(r);
  };
  const auto theta = [&](int r, std::size_t c) { return state.volume_fraction[index(r, c)]; };
  const auto tracers_of = [&](int r, std::size_t c) {
    std::size_t n = 0;
    for (std::size_t i = bins.start[c]; i < bins.start[c + 1]; ++i)
      if (state.tracers.material[bins.order[i]] == r) ++n;
    return n;
  };

  // Particles per cell, then offsets, then an independent fill per cell.
  std::vector<std::size_t> first(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    std::size_t n = 0;
    if (state.cells.density[c] > 0.0) {
      if (state.cell_material[c] != kMixedCell) {
        n = regular;
      } else {
        for (int r = 0; r < state.material_count; ++r) {
          if (!(theta(r, c) > 0.0)) continue;
          const std::size_t nb = tracers_of(r, c);
          n += nb > 0 ? nb : regular;
        }
      }
    }
    first[c + 1] = first[c] + n;
  }

  ParticleSet out;
  out.resize(first[cells]);
  const ParticleWriter writer(grid, out);
  // Serial: the mixed-cell check throws, and a handoff runs once.
  for (std::size_t c = 0; c < cells; ++c) {
    if (first[c + 1] == first[c]) continue;
    const grid::Index3 cell = grid.cell_of_index(c);
    const CellState s = cell_state(state, c, volume);
    std::size_t p = first[c];
    if (state.cell_material[c] != kMixedCell) {
      writer.put_regular(p, cell, s.mass, s.internal_energy, volume, s, state.cell_material[c]);
      continue;
    }
    double raw_mass = 0.0;
    double theta_sum = 0.0;
    for (int r = 0; r < state.material_count; ++r) {
      if (!(theta(r, c) > 0.0)) continue;
      raw_mass += state.material_density[index(r, c)] * theta(r, c);
      theta_sum += theta(r, c);
    }
    raw_mass *= volume;
    if (!(raw_mass > 0.0))
      throw Error("fdm_to_mpm: mixed cell " + std::to_string(c) + " holds mass " +
                  shortest_text(s.mass) + " kg but sum_r rho_r theta_r V_c = " +
                  shortest_text(raw_mass) + "; it must be > 0 (T (3-28))");
    const double scale = s.mass / raw_mass;
    double material_internal = 0.0;
    for (int r = 0; r < state.material_count; ++r) {
      const std::size_t at = index(r, c);
      if (theta(r, c) > 0.0)
        material_internal +=
            scale * state.material_density[at] * theta(r, c) * volume * state.material_energy[at];
    }
    const double defect = s.internal_energy - material_internal;
    for (int r = 0; r < state.material_count; ++r) {
      if (!(theta(r, c) > 0.0)) continue;
      const std::size_t at = index(r, c);
      const double mass = scale * state.material_density[at] * theta(r, c) * volume;  // T (3-19)
      const double energy = mass * state.material_energy[at] + theta(r, c) * defect;
      const double material_volume = theta(r, c) / theta_sum * volume;
      const std::size_t nb = tracers_of(r, c);
      if (nb == 0) {
        p = writer.put_regular(p, cell, mass, energy, material_volume, s, r);
        continue;
      }
      for (std::size_t i = bins.start[c]; i < bins.start[c + 1]; ++i) {
        const std::size_t t = bins.order[i];
        if (state.tracers.material[t] != r) continue;
        const grid::Vec3 x{state.tracers.position[0][t], state.tracers.position[1][t],
                           state.tracers.position[2][t]};
        const auto share = static_cast<double>(nb);
        writer.put(p++, x, mass / share, energy / share, material_volume / share, s,
                   r);  // T (3-19), (3-20)
      }
    }
  }
  return out;
}

}  // namespace mpfd::coupler::handoff
