// Quadratic interpolation of cell-centre velocities, T (3-9)-(3-12).

#include "fdm_solver/tracer/quadratic_stencil.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace mpfd::fdm {
namespace {

// Interpolation reorders a handful of products of O(1) numbers: round-off only.
constexpr double kStencilTol = 1e-12;

/// A field that is a polynomial of degree <= 2 in each coordinate separately
/// (x^2 y^2 z^2 included): what the tensor-product stencil reproduces.
struct TensorQuadratic {
  std::array<double, 27> c{};
  [[nodiscard]] double operator()(const grid::Vec3& x) const {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          sum += c[i + 3 * (j + 3 * k)] * std::pow(x[0], i) * std::pow(x[1], j) * std::pow(x[2], k);
    return sum;
  }
};

TensorQuadratic random_field(std::mt19937_64& rng, const grid::UniformGrid& g) {
  std::uniform_real_distribution<double> coef(-1.0, 1.0);
  TensorQuadratic f;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const bool used =
            (i == 0 || g.is_active(0)) && (j == 0 || g.is_active(1)) && (k == 0 || g.is_active(2));
        f.c[i + 3 * (j + 3 * k)] = used ? coef(rng) : 0.0;
      }
  return f;
}

/// Samples three fields on the cell centres and checks the interpolant at
/// random points, edge cells (one-sided stencils) included.
void expect_reproduces_tensor_quadratics(const grid::UniformGrid& g) {
  std::mt19937_64 rng(311);
  std::array<TensorQuadratic, 3> f{random_field(rng, g), random_field(rng, g),
                                   random_field(rng, g)};
  std::array<std::vector<double>, 3> u;
  for (int a = 0; a < 3; ++a) {
    u[a].resize(g.cell_count());
    for (std::size_t c = 0; c < g.cell_count(); ++c)
      u[a][c] = f[a](g.cell_center(g.cell_of_index(c)));
  }
  const VelocityView v{{u[0], u[1], u[2]}};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int sample = 0; sample < 500; ++sample) {
    grid::Vec3 x{};
    for (int a = 0; a < 3; ++a)
      x[a] = g.is_active(a) ? g.origin()[a] + unit(rng) * (g.upper()[a] - g.origin()[a])
                            : g.cell_center({0, 0, 0})[a];
    const grid::Vec3 got = interpolate_velocity(g, v, x);
    for (int a = 0; a < 3; ++a) {
      if (!g.is_active(a)) {
        EXPECT_EQ(got[a], 0.0);
        continue;
      }
      EXPECT_NEAR(got[a], f[a](x), kStencilTol * 10.0) << "axis " << a << " sample " << sample;
    }
  }
}

TEST(QuadraticInterpolation, ReproducesAnyQuadraticField1D) {
  expect_reproduces_tensor_quadratics(grid::UniformGrid({-0.3, 0, 0}, {0.1, 1, 1}, {9, 1, 1}));
}

TEST(QuadraticInterpolation, ReproducesAnyTensorQuadraticField2D) {
  expect_reproduces_tensor_quadratics(grid::UniformGrid({0, -0.5, 0}, {0.2, 0.125, 1}, {6, 8, 1}));
}

TEST(QuadraticInterpolation, ReproducesAnyTensorQuadraticField3D) {
  expect_reproduces_tensor_quadratics(
      grid::UniformGrid({0.1, 0.2, -0.4}, {0.25, 0.2, 0.3}, {4, 5, 3}));
}

TEST(QuadraticInterpolation, TwoCellAxisReproducesLinearField) {
  const grid::UniformGrid g({0, 0, 0}, {0.5, 1, 1}, {2, 1, 1});
  const std::vector<double> u{3.0 + 2.0 * 0.25, 3.0 + 2.0 * 0.75};  // u = 3 + 2 x
  const VelocityView v{{u, {}, {}}};
  for (const double x : {0.0, 0.1, 0.25, 0.6, 0.99})
    EXPECT_NEAR(interpolate_velocity(g, v, {x, 0.5, 0.5})[0], 3.0 + 2.0 * x, kStencilTol);
}

// Doc and code must not drift: (3-11) as documented in quadratic_stencil.hpp,
// written out again, against the kernel's weights.
TEST(QuadraticInterpolation, Eq311AsDocumentedMatchesKernelWeights) {
  const auto documented = [](double v1, double v2, double v3, double xi) {
    return (v1 - 2.0 * v2 + v3) / 2.0 * xi * xi + (v3 - v1) / 2.0 * xi + v2;
  };
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> value(-100.0, 100.0);
  std::uniform_real_distribution<double> xi(-1.5, 1.5);
  for (int n = 0; n < 1000; ++n) {
    const double v1 = value(rng), v2 = value(rng), v3 = value(rng), x = xi(rng);
    const std::array<double, 3> w = quadratic_weights(x);
    EXPECT_NEAR(w[0] * v1 + w[1] * v2 + w[2] * v3, documented(v1, v2, v3, x), 1e-12 * 100.0);
  }
}

// The thesis prints (3-11) with (v3 - v2)/2 as the linear coefficient; that
// would halve a linear field's slope, which is why the code (and its header)
// use (v3 - v1)/2. Fails if the kernel ever follows the printed typo.
TEST(QuadraticInterpolation, Eq311AsPrintedDoesNotReproduceLinearFieldButKernelDoes) {
  const auto printed = [](double v1, double v2, double v3, double xi) {
    return (v1 - 2.0 * v2 + v3) / 2.0 * xi * xi + (v3 - v2) / 2.0 * xi + v2;
  };
  const std::array<double, 3> w = quadratic_weights(0.5);
  EXPECT_NEAR(w[0] * -1.0 + w[1] * 0.0 + w[2] * 1.0, 0.5, kStencilTol);  // v = xi
  EXPECT_NEAR(printed(-1.0, 0.0, 1.0, 0.5), 0.25, kStencilTol);
}

TEST(QuadraticInterpolation, EdgeStencilIsOneSidedInsideTheDomain) {
  const AxisStencil lower = axis_stencil(0.2, 5);  // in cell 0
  EXPECT_EQ(lower.cell, (std::array<int, 3>{0, 1, 2}));
  const AxisStencil upper = axis_stencil(4.9, 5);  // in cell 4
  EXPECT_EQ(upper.cell, (std::array<int, 3>{2, 3, 4}));
  const AxisStencil inner = axis_stencil(2.7, 5);
  EXPECT_EQ(inner.cell, (std::array<int, 3>{1, 2, 3}));
  EXPECT_NEAR(inner.weight[1], 1.0 - 0.2 * 0.2, kStencilTol);  // xi = 2.7 - 2.5, T (3-9)
}

}  // namespace
}  // namespace mpfd::fdm
