#include "coupler/handshake/interface_nodes.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "common/core/error.hpp"
#include "mpm_solver/shape_functions.hpp"
#include "tests/unit/coupler/handshake/handshake_test_support.hpp"

namespace mpfd::coupler::handshake {
namespace {

using test::Dimensions;

constexpr double kSumTol = 1e-12;  // round-off of sums over up to 64 particles

template <int Dim>
struct Strip {
  std::vector<double> rho;
  std::vector<Vec<Dim>> momentum;
  std::vector<double> energy;
  std::vector<double> pressure;
};

template <int Dim>
struct Added {
  std::vector<double> mass;
  std::vector<Vec<Dim>> momentum;
  std::vector<Vec<Dim>> force;
  explicit Added(std::size_t n)
      : mass(n, 0.0), momentum(n, Vec<Dim>::Zero()), force(n, Vec<Dim>::Zero()) {}
  NodeOutputs<Dim> outputs() { return {mass, momentum, force}; }
};

// The strip of cells [f-1, f+1) along `axis` and [0, 6) across, for a face at
// node layer f (= 4) with the MPM zone on `side`.
template <int Dim>
IndexBox<Dim> strip_box(const ZoneFace& face) {
  auto box = test::cube<Dim>(0, 6);
  box.lo[face.axis] = 3;
  box.hi[face.axis] = 5;
  return box;
}

template <class D>
class InterfaceNodes : public ::testing::Test {};
TYPED_TEST_SUITE(InterfaceNodes, Dimensions);

// Uniform flow across the MPM zone boundary: particles on the zone's side plus
// the FDM cells k-w as particles give the interface nodes the mass, momentum and
// (zero) internal force of any interior node, T (4-7) ... (4-9), on both sides
// and every axis.
TYPED_TEST(InterfaceNodes, Uniform_flow_is_left_unchanged) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  const double rho = 1.2;
  const double pressure = 1.0e5;
  const Vec<Dim> v = test::some_velocity<Dim>();
  for (int axis = 0; axis < Dim; ++axis) {
    for (int side : {1, -1}) {
      const ZoneFace face{axis, side};
      const auto layout = make_strip_layout(strip_box<Dim>(face), face);
      auto zone = test::cube<Dim>(0, 6);  // MPM cells on the zone's side of node layer 4
      if (side > 0)
        zone.lo[axis] = 4;
      else
        zone.hi[axis] = 4;
      const auto particles = test::uniform_particles<Dim>(zone, g, rho, v, 2.0e5);
      auto nodes = test::cube<Dim>(1, 6);  // interface nodes clear of the strip's lateral edges
      nodes.lo[axis] = layout.face_node_layer();
      nodes.hi[axis] = nodes.lo[axis] + 1;
      ASSERT_EQ(nodes.lo[axis], 4);
      auto mpm = test::particles_to_nodes<Dim>(particles, pressure, nodes, g);

      const std::size_t n = layout.box.count();
      const Strip<Dim> strip{std::vector<double>(n, rho), std::vector<Vec<Dim>>(n, rho * v),
                             std::vector<double>(n, 0.0), std::vector<double>(n, pressure)};
      Added<Dim> add(nodes.count());
      interface_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0,
                                layout, make_interface_stencil(layout, nodes), g, add.outputs());
      const double node_mass = rho * g.cell_volume;
      const double force_scale = pressure * g.face_area(axis);
      for (std::size_t i = 0; i < nodes.count(); ++i) {
        EXPECT_NEAR(mpm.mass[i] + add.mass[i], node_mass, kSumTol * node_mass);
        EXPECT_LE((mpm.momentum[i] + add.momentum[i] - node_mass * v).norm(),
                  kSumTol * node_mass * v.norm());
        EXPECT_LE((mpm.force[i] + add.force[i]).norm(), kSumTol * force_scale)
            << "axis " << axis << " side " << side << " node " << i;
        // The FDM term alone is half the node (the outer half-support).
        EXPECT_NEAR(add.mass[i], 0.5 * node_mass, kSumTol * node_mass);
      }
    }
  }
}

// Momentum balance of the correction for arbitrary FDM cells: over all nodes of
// the face, T (4-7), (4-8) add the half of each cell k-w that lies in the
// interface nodes' support (Σ_I N_Ic = 1/2), and T (4-9) adds exactly the
// pressure force p_c A on each cell's face, normal into the zone (no tangential
// force).
TYPED_TEST(InterfaceNodes, Correction_conserves_momentum_for_any_strip_state) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.5, 1.5);
  for (int side : {1, -1}) {
    const ZoneFace face{Dim - 1, side};
    const auto layout = make_strip_layout(strip_box<Dim>(face), face);
    auto nodes = test::cube<Dim>(0, 7);  // every node of the face
    nodes.lo[face.axis] = layout.face_node_layer();
    nodes.hi[face.axis] = nodes.lo[face.axis] + 1;
    const std::size_t n = layout.box.count();
    Strip<Dim> strip{{}, {}, std::vector<double>(n, 0.0), {}};
    for (std::size_t c = 0; c < n; ++c) {
      strip.rho.push_back(unit(random));
      Vec<Dim> m;
      for (int a = 0; a < Dim; ++a) m(a) = 100 * (unit(random) - 1);
      strip.momentum.push_back(m);
      strip.pressure.push_back(1e5 * unit(random));
    }
    Added<Dim> add(nodes.count());
    interface_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0,
                              layout, make_interface_stencil(layout, nodes), g, add.outputs());
    double mass = 0, expected_mass = 0;
    Vec<Dim> momentum = Vec<Dim>::Zero(), expected_momentum = Vec<Dim>::Zero();
    Vec<Dim> force = Vec<Dim>::Zero(), expected_force = Vec<Dim>::Zero();
    for (std::size_t i = 0; i < nodes.count(); ++i) {
      mass += add.mass[i];
      momentum += add.momentum[i];
      force += add.force[i];
    }
    for (std::size_t t = 0; t < layout.face_cells(); ++t) {
      const std::size_t c = layout.outer[t];
      expected_mass += 0.5 * strip.rho[c] * g.cell_volume;
      expected_momentum += 0.5 * strip.momentum[c] * g.cell_volume;
      expected_force(face.axis) += side * strip.pressure[c] * g.face_area(face.axis);
    }
    EXPECT_NEAR(mass, expected_mass, kSumTol * expected_mass);
    EXPECT_LE((momentum - expected_momentum).norm(), kSumTol * expected_momentum.norm());
    EXPECT_LE((force - expected_force).norm(), kSumTol * expected_force.norm());
  }
}

// The FDM push with the MPM's face-cell mass (docs/coupler.md, Deviations):
// face_push_volume is m_t / ρ of each outer cell, and (4-9) with it scales the
// force by V / V_c while (4-7), (4-8) keep T's V_c.
TEST(InterfaceNodes2D, Push_volume_is_the_face_mass_over_the_outer_density) {
  const auto g = test::test_geometry<2>();
  const ZoneFace face{0, 1};
  const auto layout = make_strip_layout(IndexBox<2>{{3, 0}, {5, 4}}, face);
  const std::size_t faces = layout.face_cells(), n = layout.box.count();
  Strip<2> strip{std::vector<double>(n, 1.2), std::vector<Vec<2>>(n, Vec<2>(3.0, -1.0)),
                 std::vector<double>(n, 0.0), std::vector<double>(n, 2e5)};
  strip.rho[layout.outer[1]] = 2.4;
  std::vector<double> face_mass(faces, 0.6 * g.cell_volume);
  face_mass[2] = 0.0;  // an emptied face cell: T's V_c, not a pressure switched off
  const std::vector<double> no_solid(faces, 0.0);
  std::vector<double> volume(faces);
  face_push_volume<2>(face_mass, no_solid, strip.rho, layout, g.cell_volume, volume);
  for (std::size_t t = 0; t < faces; ++t)
    EXPECT_DOUBLE_EQ(volume[t], t == 2 ? g.cell_volume : 0.6 * g.cell_volume / (t == 1 ? 2.4 : 1.2))
        << "face cell " << t;

  const IndexBox<2> nodes{{4, 0}, {5, 5}};
  const auto stencil = make_interface_stencil(layout, nodes);
  const std::vector<double> full(faces, g.cell_volume), half(faces, 0.5 * g.cell_volume);
  Added<2> t_as_printed(nodes.count()), with_full(nodes.count()), with_half(nodes.count());
  interface_node_terms<2>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0, layout,
                          stencil, g, t_as_printed.outputs());
  interface_node_terms<2>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0, layout,
                          stencil, g, with_full.outputs(), full);
  interface_node_terms<2>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0, layout,
                          stencil, g, with_half.outputs(), half);
  for (std::size_t i = 0; i < nodes.count(); ++i) {
    EXPECT_EQ(with_full.force[i], t_as_printed.force[i]);
    EXPECT_LE((with_half.force[i] - 0.5 * t_as_printed.force[i]).norm(),
              kSumTol * t_as_printed.force[i].norm());
    EXPECT_EQ(with_half.mass[i], t_as_printed.mass[i]);
    EXPECT_EQ(with_half.momentum[i], t_as_printed.momentum[i]);
  }
  std::vector<double> short_volume(faces - 1);
  EXPECT_THROW(
      face_push_volume<2>(face_mass, no_solid, strip.rho, layout, g.cell_volume, short_volume),
      Error);
}

// A solid in the face cell resists with its own volume: its mass at the air's
// density would be thousands of cell volumes (docs/coupler.md, Deviations).
TEST(InterfaceNodes2D, Push_volume_counts_a_solid_by_its_own_volume) {
  const auto g = test::test_geometry<2>();
  const auto layout = make_strip_layout(IndexBox<2>{{3, 0}, {5, 3}}, ZoneFace{0, 1});
  const std::size_t faces = layout.face_cells(), n = layout.box.count();
  const std::vector<double> rho(n, 1.2);
  // Face cell 0: air only; 1: steel (7830 kg/m^3) on 0.6 of the cell, air on 0.4;
  // 2: steel only, on half the cell (not V_c, the volume of an empty face cell).
  const std::vector<double> air_mass{1.2 * g.cell_volume, 1.2 * 0.4 * g.cell_volume, 0.0};
  const std::vector<double> solid_volume{0.0, 0.6 * g.cell_volume, 0.5 * g.cell_volume};
  std::vector<double> volume(faces);
  face_push_volume<2>(air_mass, solid_volume, rho, layout, g.cell_volume, volume);
  const std::vector<double> expected{g.cell_volume, g.cell_volume, 0.5 * g.cell_volume};
  for (std::size_t t = 0; t < faces; ++t)
    EXPECT_NEAR(volume[t], expected[t], 1e-15 * g.cell_volume) << "face cell " << t;
}

TEST(InterfaceNodes2D, Node_box_must_lie_on_the_face) {
  const ZoneFace face{0, 1};
  const auto layout = make_strip_layout(IndexBox<2>{{3, 0}, {5, 4}}, face);
  EXPECT_THROW((void)make_interface_stencil(layout, IndexBox<2>{{3, 0}, {4, 5}}), Error);
  EXPECT_NO_THROW((void)make_interface_stencil(layout, IndexBox<2>{{4, 0}, {5, 5}}));
}

// solver.mpm.reference_pressure: the zone's particles leave p_ref out of their
// stress, so the FDM cells' force (4-9) uses p - p_ref. At p = p_ref it vanishes
// (a uniform ambient state pushes no face node); elsewhere it scales with
// p - p_ref; mass and momentum (4-7), (4-8) do not depend on it.
TYPED_TEST(InterfaceNodes, Reference_pressure_comes_off_the_force_only) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  const ZoneFace face{Dim - 1, 1};
  const auto layout = make_strip_layout(strip_box<Dim>(face), face);
  auto nodes = test::cube<Dim>(0, 7);
  nodes.lo[face.axis] = layout.face_node_layer();
  nodes.hi[face.axis] = nodes.lo[face.axis] + 1;
  const std::size_t n = layout.box.count();
  const double p = 1.0e5;
  Vec<Dim> u = Vec<Dim>::Zero();
  u(0) = 30.0;
  const Strip<Dim> strip{std::vector<double>(n, 1.2), std::vector<Vec<Dim>>(n, 1.2 * u),
                         std::vector<double>(n, 0.0), std::vector<double>(n, p)};
  const auto stencil = make_interface_stencil(layout, nodes);
  Added<Dim> full(nodes.count()), at_ambient(nodes.count()), quarter(nodes.count());
  interface_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.0, layout,
                            stencil, g, full.outputs());
  interface_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure, p, layout,
                            stencil, g, at_ambient.outputs());
  interface_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure, 0.25 * p,
                            layout, stencil, g, quarter.outputs());
  const double scale = p * g.face_area(face.axis);
  bool pushed = false;
  for (std::size_t i = 0; i < nodes.count(); ++i) {
    pushed = pushed || full.force[i].norm() > 1e-3 * scale;
    EXPECT_EQ(at_ambient.force[i].norm(), 0.0) << "node " << i;
    EXPECT_LE((quarter.force[i] - 0.75 * full.force[i]).norm(), 1e-12 * scale) << "node " << i;
    EXPECT_EQ(at_ambient.mass[i], full.mass[i]);
    EXPECT_EQ((at_ambient.momentum[i] - full.momentum[i]).norm(), 0.0);
  }
  EXPECT_TRUE(pushed);  // without p_ref the face nodes do feel the cells' pressure
}

// The node layer outside the face (uGIMP MPM): with cells k-w and k-w-1 in the
// same state it is an interior node of the FDM's material, full mass and
// momentum and no force, on both sides and every axis.
TYPED_TEST(InterfaceNodes, Outer_nodes_of_a_uniform_state_are_interior_nodes) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  const double rho = 1.2, pressure = 1.0e5;
  const Vec<Dim> v = test::some_velocity<Dim>();
  for (int axis = 0; axis < Dim; ++axis) {
    for (int side : {1, -1}) {
      const ZoneFace face{axis, side};
      const auto layout = make_strip_layout(strip_box<Dim>(face), face);
      auto nodes = test::cube<Dim>(1, 6);  // clear of the strip's lateral edges
      nodes.lo[axis] = layout.face_node_layer() - side;
      nodes.hi[axis] = nodes.lo[axis] + 1;
      const std::size_t n = layout.box.count(), m = layout.face_cells();
      const Strip<Dim> strip{std::vector<double>(n, rho), std::vector<Vec<Dim>>(n, rho * v),
                             std::vector<double>(n, 0.0), std::vector<double>(n, pressure)};
      const Strip<Dim> beyond{std::vector<double>(m, rho), std::vector<Vec<Dim>>(m, rho * v),
                              std::vector<double>(m, 0.0), std::vector<double>(m, pressure)};
      Added<Dim> add(nodes.count());
      outer_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure,
                            {beyond.rho, beyond.momentum, beyond.energy}, beyond.pressure, 0.0,
                            layout, make_outer_node_stencil(layout, nodes), g, add.outputs());
      const double node_mass = rho * g.cell_volume;
      for (std::size_t i = 0; i < nodes.count(); ++i) {
        EXPECT_NEAR(add.mass[i], node_mass, kSumTol * node_mass);
        EXPECT_LE((add.momentum[i] - node_mass * v).norm(), kSumTol * node_mass * v.norm());
        EXPECT_LE(add.force[i].norm(), kSumTol * pressure * g.face_area(axis))
            << "axis " << axis << " side " << side << " node " << i;
      }
    }
  }
}

// Over the whole outer layer each cell k-w and k-w-1 gives the half of itself
// in the layer's support, and the force is the pressure difference across the
// face between them, p_(k-w-1) - p_(k-w), on each face cell's area.
TYPED_TEST(InterfaceNodes, Outer_nodes_take_half_of_both_cells_and_their_pressure_difference) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.5, 1.5);
  for (int side : {1, -1}) {
    const ZoneFace face{Dim - 1, side};
    const auto layout = make_strip_layout(strip_box<Dim>(face), face);
    auto nodes = test::cube<Dim>(0, 7);  // every node of the layer
    nodes.lo[face.axis] = layout.face_node_layer() - side;
    nodes.hi[face.axis] = nodes.lo[face.axis] + 1;
    const auto fill = [&](std::size_t count) {
      Strip<Dim> cells{{}, {}, std::vector<double>(count, 0.0), {}};
      for (std::size_t c = 0; c < count; ++c) {
        cells.rho.push_back(unit(random));
        Vec<Dim> momentum;
        for (int a = 0; a < Dim; ++a) momentum(a) = 100 * (unit(random) - 1);
        cells.momentum.push_back(momentum);
        cells.pressure.push_back(1e5 * unit(random));
      }
      return cells;
    };
    const Strip<Dim> strip = fill(layout.box.count());
    const Strip<Dim> beyond = fill(layout.face_cells());
    Added<Dim> add(nodes.count());
    outer_node_terms<Dim>({strip.rho, strip.momentum, strip.energy}, strip.pressure,
                          {beyond.rho, beyond.momentum, beyond.energy}, beyond.pressure, 0.0,
                          layout, make_outer_node_stencil(layout, nodes), g, add.outputs());
    double mass = 0, expected_mass = 0;
    Vec<Dim> momentum = Vec<Dim>::Zero(), expected_momentum = Vec<Dim>::Zero();
    Vec<Dim> force = Vec<Dim>::Zero(), expected_force = Vec<Dim>::Zero();
    for (std::size_t i = 0; i < nodes.count(); ++i) {
      mass += add.mass[i];
      momentum += add.momentum[i];
      force += add.force[i];
    }
    for (std::size_t t = 0; t < layout.face_cells(); ++t) {
      const std::size_t c = layout.outer[t];
      expected_mass += 0.5 * (strip.rho[c] + beyond.rho[t]) * g.cell_volume;
      expected_momentum += 0.5 * (strip.momentum[c] + beyond.momentum[t]) * g.cell_volume;
      expected_force(face.axis) +=
          side * (beyond.pressure[t] - strip.pressure[c]) * g.face_area(face.axis);
    }
    EXPECT_NEAR(mass, expected_mass, kSumTol * expected_mass);
    EXPECT_LE((momentum - expected_momentum).norm(), kSumTol * expected_momentum.norm());
    EXPECT_LE((force - expected_force).norm(), 1e-9 * 1e5 * g.face_area(face.axis));
  }
}

// Why the outer layer needs the FDM (1D, uniform state at rest): a uGIMP
// particle (half-width a = 1/4, 2 per cell) 0.05 h from the face reaches the node
// one cell outside with S = (1 + a - r)^2 / (4a) = 0.04 of its mass and pushes it
// with its pressure, p V_p dS/dx. Alone there (linear-shape coupling, which
// never fed that layer) the node accelerates at p S' / (ρ S) = 10 p / (ρ h): the
// particle expands as into a vacuum. With cells k-w and k-w-1 at the same state
// the node holds ρ V_c more and moves at about 0.2 p / (ρ h).
TEST(InterfaceNodes1D, A_gimp_particle_at_the_face_meets_the_fdm_at_the_outer_node) {
  const auto g = test::test_geometry<1>();
  const double rho = 1.2, pressure = 1.0e5, a = 0.25;
  const ZoneFace face{0, 1};
  const auto layout = make_strip_layout(strip_box<1>(face), face);
  const std::int64_t outer = layout.face_node_layer() - 1;
  const IndexBox<1> nodes{{outer}, {outer + 1}};
  const double mass = 0.5 * rho * g.cell_volume, volume = 0.5 * g.cell_volume;
  const double xi = static_cast<double>(layout.face_node_layer()) + 0.05;  // grid units
  mpm::AxisWeights<3> w;
  mpm::gimp_weights(xi, a, 1.0 / g.spacing(0), w);
  ASSERT_EQ(w.first, outer);
  ASSERT_NEAR(w.weight[0], 0.04, 1e-12);
  // f_I = -Σ ∇S σ V = p V ∇S for σ = -p I.
  const double particle_mass = w.weight[0] * mass,
               particle_force = pressure * volume * w.gradient[0];
  const double scale = pressure / (rho * g.spacing(0));
  EXPECT_NEAR(std::abs(particle_force / particle_mass), 10 * scale, 1e-9 * scale);

  const std::size_t n = layout.box.count();
  const Strip<1> strip{std::vector<double>(n, rho), std::vector<Vec<1>>(n, Vec<1>::Zero()),
                       std::vector<double>(n, 0.0), std::vector<double>(n, pressure)};
  const Strip<1> beyond{{rho}, {Vec<1>::Zero()}, {0.0}, {pressure}};
  Added<1> add(1);
  outer_node_terms<1>({strip.rho, strip.momentum, strip.energy}, strip.pressure,
                      {beyond.rho, beyond.momentum, beyond.energy}, beyond.pressure, 0.0, layout,
                      make_outer_node_stencil(layout, nodes), g, add.outputs());
  const double acceleration = (particle_force + add.force[0](0)) / (particle_mass + add.mass[0]);
  EXPECT_NEAR(std::abs(acceleration), 0.2 / 1.02 * scale, 1e-9 * scale);
}

TEST(InterfaceNodes2D, Outer_node_box_must_lie_one_cell_outside_the_face) {
  for (const int side : {1, -1}) {
    const ZoneFace face{0, side};
    const auto layout = make_strip_layout(IndexBox<2>{{3, 0}, {5, 4}}, face);
    const std::int64_t outer = layout.face_node_layer() - side;
    EXPECT_NO_THROW((void)make_outer_node_stencil(layout, IndexBox<2>{{outer, 0}, {outer + 1, 5}}));
    const std::int64_t f = layout.face_node_layer();
    EXPECT_THROW((void)make_outer_node_stencil(layout, IndexBox<2>{{f, 0}, {f + 1, 5}}), Error);
  }
}

}  // namespace
}  // namespace mpfd::coupler::handshake
