#include "coupler/remap/spherical_to_cartesian.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "coupler/remap/ball_box_overlap.hpp"

namespace mpfd::coupler::remap {
namespace {

// A box relative to the centre, in the dimension of the symmetry (3: sphere,
// 2: cylinder about z). `thickness` turns an area into a volume in 2D.
struct RelativeBox {
  int dim;
  std::array<double, 3> lower;
  std::array<double, 3> upper;
  double thickness;

  [[nodiscard]] double overlap(double radius) const {
    return thickness * ball_box_overlap(std::span<const double>(lower.data(), dim),
                                        std::span<const double>(upper.data(), dim), radius);
  }
  [[nodiscard]] double volume() const {
    double v = thickness;
    for (int a = 0; a < dim; ++a) v *= upper[a] - lower[a];
    return v;
  }
  [[nodiscard]] double nearest_distance() const {
    double d2 = 0.0;
    for (int a = 0; a < dim; ++a) {
      const double d = std::max({lower[a], -upper[a], 0.0});
      d2 += d * d;
    }
    return std::sqrt(d2);
  }
  [[nodiscard]] double farthest_distance() const {
    double d2 = 0.0;
    for (int a = 0; a < dim; ++a) {
      const double d = std::max(std::abs(lower[a]), std::abs(upper[a]));
      d2 += d * d;
    }
    return std::sqrt(d2);
  }
};

int symmetry_dimension(const grid::UniformGrid& grid) {
  if (grid.dimension() == 3) return 3;
  if (grid.dimension() == 2 && grid.is_active(0) && grid.is_active(1)) return 2;
  throw Error("remap_radial_profile: the grid must be 3D (spherical profile) or 2D in x and y " +
              std::string("(cylindrical profile about z), got cells ") +
              std::to_string(grid.cells()[0]) + " x " + std::to_string(grid.cells()[1]) + " x " +
              std::to_string(grid.cells()[2]));
}

RelativeBox relative_box(int dim, const grid::Vec3& lower, const grid::Vec3& upper,
                         const grid::Vec3& centre) {
  RelativeBox box{dim, {}, {}, dim == 2 ? upper[2] - lower[2] : 1.0};
  for (int a = 0; a < 3; ++a) {
    box.lower[a] = lower[a] - centre[a];
    box.upper[a] = upper[a] - centre[a];
  }
  return box;
}

RelativeBox cell_box(const grid::UniformGrid& grid, const grid::Index3& c, int dim,
                     const grid::Vec3& centre) {
  grid::Vec3 lower{};
  grid::Vec3 upper{};
  for (int a = 0; a < 3; ++a) {
    lower[a] = grid.origin()[a] + c[a] * grid.spacing()[a];
    upper[a] = lower[a] + grid.spacing()[a];
  }
  return relative_box(dim, lower, upper, centre);
}

// Calls visit(k, V_ck) for every shell k overlapping the box, V_ck > 0.
template <class Visit>
void for_each_shell_overlap(const RelativeBox& box, std::span<const double> edges,
                            const Visit& visit) {
  const double near = box.nearest_distance();
  const double far = box.farthest_distance();
  const double full = box.volume();
  const auto inner_ball = [&](double r) {
    if (r <= near) return 0.0;
    if (r >= far) return full;
    return box.overlap(r);
  };
  // First shell whose outer edge passes the nearest point of the box.
  const auto first = std::upper_bound(edges.begin() + 1, edges.end(), near) - edges.begin() - 1;
  double below = inner_ball(edges[static_cast<std::size_t>(first)]);
  for (auto k = static_cast<std::size_t>(first); k + 1 < edges.size(); ++k) {
    const double above = inner_ball(edges[k + 1]);
    if (above > below) visit(k, above - below);
    if (edges[k + 1] >= far) break;
    below = above;
  }
}

}  // namespace

CartesianFields remap_radial_profile(const grid::UniformGrid& grid, const grid::Vec3& centre,
                                     const RadialProfile& profile) {
  check_profile(profile);
  const int dim = symmetry_dimension(grid);
  const std::size_t cells = grid.cell_count();
  int materials = 0;
  for (const int m : profile.material) materials = std::max(materials, m + 1);
  const bool has_stress = !profile.radial_stress.empty();

  CartesianFields out;
  out.density.assign(cells, 0.0);
  for (auto& p : out.momentum) p.assign(cells, 0.0);
  out.total_energy.assign(cells, 0.0);
  out.covered_fraction.assign(cells, 0.0);
  out.material_count = materials;
  out.volume_fraction.assign(static_cast<std::size_t>(materials) * cells, 0.0);
  out.material_mass.assign(static_cast<std::size_t>(materials) * cells, 0.0);
  out.material_internal_energy.assign(static_cast<std::size_t>(materials) * cells, 0.0);
  if (has_stress)
    for (auto& s : out.stress) s.assign(cells, 0.0);

  const double volume = grid.cell_volume();
  parallel_for(cells, [&](std::size_t c) {
    const grid::Index3 index = grid.cell_of_index(c);
    const RelativeBox box = cell_box(grid, index, dim, centre);
    double mass = 0.0;
    double radial_momentum = 0.0;
    double energy = 0.0;
    double covered = 0.0;
    double sigma_rr = 0.0;
    double sigma_tt = 0.0;
    for_each_shell_overlap(box, profile.edges, [&](std::size_t k, double v) {
      const double m = profile.density[k] * v;
      const double u = profile.velocity[k];
      mass += m;
      radial_momentum += m * u;
      energy += m * (profile.internal_energy[k] + 0.5 * u * u);
      covered += v;
      const std::size_t at =
          c * static_cast<std::size_t>(materials) + static_cast<std::size_t>(profile.material[k]);
      out.volume_fraction[at] += v / volume;
      out.material_mass[at] += m;
      out.material_internal_energy[at] += m * profile.internal_energy[k];
      if (has_stress) {
        sigma_rr += profile.radial_stress[k] * v;
        sigma_tt += profile.hoop_stress[k] * v;
      }
    });
    // n: S (17), the radial unit vector at the cell centre.
    const grid::Vec3 x = grid.cell_center(index);
    std::array<double, 3> n{};
    double length2 = 0.0;
    for (int a = 0; a < dim; ++a) {
      n[a] = x[a] - centre[a];
      length2 += n[a] * n[a];
    }
    const double length = std::sqrt(length2);
    for (int a = 0; a < dim; ++a) n[a] = length > 0.0 ? n[a] / length : 0.0;
    out.density[c] = mass / volume;
    for (int a = 0; a < 3; ++a) out.momentum[a][c] = radial_momentum * n[a] / volume;  // S (18)
    out.total_energy[c] = energy / volume;
    out.covered_fraction[c] = covered / volume;
    if (has_stress && covered > 0.0) {
      // S (19): B = R^T diag(rr, tt, tt) R = tt I + (rr - tt) n n^T, volume-averaged
      // rr, tt. For the cylinder (2D) the axial stress is taken as the hoop stress.
      const double rr = sigma_rr / covered;
      const double tt = sigma_tt / covered;
      constexpr std::array<std::array<int, 2>, 6> kVoigt{
          {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}};
      for (std::size_t s = 0; s < 6; ++s) {
        const auto [i, j] = kVoigt[s];
        out.stress[s][c] = (i == j ? tt : 0.0) + (rr - tt) * n[i] * n[j];
      }
    }
  });
  return out;
}

RemapTotals totals_inside_grid(const grid::UniformGrid& grid, const grid::Vec3& centre,
                               const RadialProfile& profile) {
  check_profile(profile);
  const RelativeBox box =
      relative_box(symmetry_dimension(grid), grid.origin(), grid.upper(), centre);
  RemapTotals totals;
  for_each_shell_overlap(box, profile.edges, [&](std::size_t k, double v) {
    const double m = profile.density[k] * v;
    const double u = profile.velocity[k];
    totals.mass += m;
    totals.energy += m * (profile.internal_energy[k] + 0.5 * u * u);
    totals.radial_impulse += m * u;
  });
  return totals;
}

}  // namespace mpfd::coupler::remap
