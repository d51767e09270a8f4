#pragma once
// Test-side MPM: a lattice of air particles, 2 per axis per cell, mapped to
// nodes with the (tri)linear shape functions of T (2-7), so the handshake
// kernels can be checked against what a real MPM grid would hold.

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

#include "coupler/handshake/index_box.hpp"

namespace mpfd::coupler::handshake::test {

template <int D>
using DimTag = std::integral_constant<int, D>;
using Dimensions = ::testing::Types<DimTag<1>, DimTag<2>, DimTag<3>>;

/// Unequal spacings so that no formula can silently assume a cube.
template <int Dim>
CellGeometry<Dim> test_geometry() {
  CellGeometry<Dim> g;
  const double spacing[3] = {0.002, 0.003, 0.0025};
  const double origin[3] = {-0.1, 0.05, 0.2};
  g.cell_volume = 1;
  for (int a = 0; a < Dim; ++a) {
    g.spacing(a) = spacing[a];
    g.origin(a) = origin[a];
    g.cell_volume *= spacing[a];
  }
  g.cell_volume *= Dim == 3 ? 1.0 : 0.5;  // thickness of the missing axes
  return g;
}

template <int Dim>
struct Particles {
  std::vector<Vec<Dim>> position;
  std::vector<double> mass;
  std::vector<double> volume;
  std::vector<Vec<Dim>> velocity;
  std::vector<double> internal_energy;  // J
};

/// 2^Dim particles per cell of `cells`, at the quarter points, all with
/// density rho, velocity v and specific internal energy e.
template <int Dim>
Particles<Dim> uniform_particles(const IndexBox<Dim>& cells, const CellGeometry<Dim>& g, double rho,
                                 const Vec<Dim>& v, double e) {
  Particles<Dim> p;
  const int per_cell = 1 << Dim;
  const double volume = g.cell_volume / per_cell;
  for (std::size_t c = 0; c < cells.count(); ++c) {
    const Vec<Dim> corner = g.lower_corner(cells.at(c));
    for (int q = 0; q < per_cell; ++q) {
      Vec<Dim> x = corner;
      for (int a = 0; a < Dim; ++a) x(a) += (((q >> a) & 1) != 0 ? 0.75 : 0.25) * g.spacing(a);
      p.position.push_back(x);
      p.mass.push_back(rho * volume);
      p.volume.push_back(volume);
      p.velocity.push_back(v);
      p.internal_energy.push_back(rho * volume * e);
    }
  }
  return p;
}

/// Nodal mass, momentum and internal force f_I = -Σ ∇N σ V with σ = -p I,
/// T (2-12), (2-9), (2-10), on the nodes of `nodes` (C order).
template <int Dim>
struct NodeData {
  std::vector<double> mass;
  std::vector<Vec<Dim>> momentum;
  std::vector<Vec<Dim>> force;
};

template <int Dim>
NodeData<Dim> particles_to_nodes(const Particles<Dim>& p, double pressure,
                                 const IndexBox<Dim>& nodes, const CellGeometry<Dim>& g) {
  NodeData<Dim> n{std::vector<double>(nodes.count(), 0.0),
                  std::vector<Vec<Dim>>(nodes.count(), Vec<Dim>::Zero()),
                  std::vector<Vec<Dim>>(nodes.count(), Vec<Dim>::Zero())};
  for (std::size_t i = 0; i < p.mass.size(); ++i) {
    Index<Dim> cell{};
    Vec<Dim> local;
    for (int a = 0; a < Dim; ++a) {
      const double s = (p.position[i](a) - g.origin(a)) / g.spacing(a);
      cell[a] = static_cast<std::int64_t>(std::floor(s));
      local(a) = s - static_cast<double>(cell[a]);
    }
    for (int q = 0; q < (1 << Dim); ++q) {
      Index<Dim> node = cell;
      Vec<Dim> w1;  // 1-D weights
      Vec<Dim> dw;  // their derivatives
      for (int a = 0; a < Dim; ++a) {
        const bool upper = ((q >> a) & 1) != 0;
        node[a] += upper ? 1 : 0;
        w1(a) = upper ? local(a) : 1 - local(a);
        dw(a) = (upper ? 1.0 : -1.0) / g.spacing(a);
      }
      if (!nodes.contains(node)) continue;
      double weight = 1;
      for (int a = 0; a < Dim; ++a) weight *= w1(a);
      Vec<Dim> gradient;
      for (int a = 0; a < Dim; ++a) {
        gradient(a) = dw(a);
        for (int b = 0; b < Dim; ++b)
          if (b != a) gradient(a) *= w1(b);
      }
      const std::size_t k = nodes.flat(node);
      n.mass[k] += weight * p.mass[i];
      n.momentum[k] += weight * p.mass[i] * p.velocity[i];
      n.force[k] += pressure * p.volume[i] * gradient;
    }
  }
  return n;
}

template <int Dim>
IndexBox<Dim> cube(std::int64_t lo, std::int64_t hi) {
  IndexBox<Dim> box;
  box.lo.fill(lo);
  box.hi.fill(hi);
  return box;
}

template <int Dim>
Vec<Dim> some_velocity() {
  const double v[3] = {120.0, -45.0, 30.0};
  Vec<Dim> u;
  for (int a = 0; a < Dim; ++a) u(a) = v[a];
  return u;
}

}  // namespace mpfd::coupler::handshake::test
