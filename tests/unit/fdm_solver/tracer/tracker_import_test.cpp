// A tracker built from imported tracer points (positions and materials only).

#include "fdm_solver/tracer/tracker_import.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::fdm {
namespace {

namespace tm = eos::test_materials;

/// 2D, 6 x 5 cells of 1 cm: products (material 0) in the 3 x 2 lower corner, air elsewhere.
struct Corner {
  grid::UniformGrid g{{0, 0, 0}, {0.01, 0.01, 0.01}, {6, 5, 1}};
  std::vector<double> material, rho, e;
  std::vector<int> fallback;
  Corner() {
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 6; ++i) {
        const bool products = i < 3 && j < 2;
        material.push_back(products ? 0.0 : 1.0);
        rho.push_back(products ? 50.0 : tm::kAirDensity);
        e.push_back(products ? 4.0e6 : tm::kAirEnergy);
        fallback.push_back(1);
      }
  }
  MultiMaterialTracker seeded() const { return {g, {tm::kTnt, tm::kAir}, material, rho, e, 3}; }
  MultiMaterialTracker from_points(const TracerSet& points) const {
    return {g, {tm::kTnt, tm::kAir}, tracker_from_points(g, 2, points, fallback, rho, e)};
  }
};

TEST(TrackerImport, TrackerFromPoints_OfSeededTracersEqualsTheSeededTracker) {
  const Corner c;
  MultiMaterialTracker seeded = c.seeded();
  MultiMaterialTracker imported = c.from_points(seeded.tracers());
  EXPECT_EQ(imported.materials().material, seeded.materials().material);
  EXPECT_EQ(imported.materials().theta, seeded.materials().theta);
  EXPECT_EQ(imported.tracers().volume, seeded.tracers().volume);  // V_c / 9, T (3-21)
  EXPECT_EQ(imported.tracers().position, seeded.tracers().position);
  std::vector<double> p_seeded(c.rho.size()), p_imported(c.rho.size());
  seeded.update_pressure(c.rho, c.e, p_seeded);
  imported.update_pressure(c.rho, c.e, p_imported);
  EXPECT_EQ(p_imported, p_seeded);
  EXPECT_EQ(imported.states().energy, seeded.states().energy);
  EXPECT_EQ(imported.states().density, seeded.states().density);
}

TEST(TrackerImport, MovedTracersGiveTheTrackersClassificationWithThetaFromCounts) {
  const Corner c;
  MultiMaterialTracker moving = c.seeded();
  const std::vector<double> u(c.rho.size(), 2.0), v(c.rho.size(), 1.0);
  constexpr TracerBoundaries walls{TracerFace::reflect, TracerFace::reflect, TracerFace::reflect,
                                   TracerFace::reflect, TracerFace::reflect, TracerFace::reflect};
  std::vector<double> p(c.rho.size());
  for (int s = 0; s < 3; ++s) {  // 0.2 and 0.1 cell per step: mixed cells appear
    moving.advect({{u, v, {}}}, 1e-3, walls);
    moving.update_pressure(c.rho, c.e, p);
  }
  const MaterialMap& map = moving.materials();
  std::size_t mixed = 0;
  for (std::size_t cell = 0; cell < map.cell_count(); ++cell) mixed += map.is_mixed(cell) ? 1 : 0;
  ASSERT_GT(mixed, 0u);
  const MultiMaterialTracker imported = c.from_points(moving.tracers());
  EXPECT_EQ(imported.materials().material, map.material);
  const auto& bins = moving.bins();
  for (std::size_t cell = 0; cell < map.cell_count(); ++cell) {
    if (!map.is_mixed(cell)) continue;
    const double counted =
        static_cast<double>(bins.count(cell, 0)) / static_cast<double>(bins.count(cell));
    EXPECT_EQ(imported.materials().volume_fraction(cell, 0), counted) << "cell " << cell;
    EXPECT_DOUBLE_EQ(imported.materials().volume_fraction(cell, 0) +
                         imported.materials().volume_fraction(cell, 1),
                     1.0);
  }
}

TEST(TrackerImport, RefusesATracerOutsideTheGridNamingIt) {
  const Corner c;
  TracerSet points = c.seeded().tracers();
  points.position[1][7] = 0.2;
  try {
    (void)c.from_points(points);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("tracer 7"), std::string::npos) << error.what();
  }
}

TEST(TrackerImport, RefusesACellOfThreeMaterialsBeforeAcceptingThePoints) {
  const Corner c;
  TracerSet points = c.seeded().tracers();
  points.add({0.015, 0.005, 0.005}, 1, 0.0);  // cell (1, 0) of products: air ...
  points.add({0.016, 0.004, 0.005}, 2, 0.0);  // ... and a third material
  int accepted = 0;
  try {
    (void)tracker_from_points(c.g, 3, points, c.fallback, c.rho, c.e, {}, [&] { ++accepted; });
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("cell (1, 0, 0)"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("materials 0, 1, 2"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(accepted, 0);  // a solver still holds its old tracker
}

TEST(TrackerImport, AcceptsOnceAfterEveryCheckAndTheStateDoesNotDependOnIt) {
  const Corner c;
  const TracerSet points = c.seeded().tracers();
  int accepted = 0;
  const TrackerState with =
      tracker_from_points(c.g, 2, points, c.fallback, c.rho, c.e, {}, [&] { ++accepted; });
  EXPECT_EQ(accepted, 1);
  const TrackerState without = tracker_from_points(c.g, 2, points, c.fallback, c.rho, c.e);
  EXPECT_EQ(with.materials.theta, without.materials.theta);
  EXPECT_EQ(with.tracers.volume, without.tracers.volume);
  EXPECT_EQ(with.states.energy, without.states.energy);

  // Every refusal comes before `accepted`: a tracer outside the grid, a
  // material start of the wrong size, a fallback material out of range.
  const auto refused = [&](const TracerSet& p, const MaterialStartView& start,
                           const std::vector<int>& fallback) {
    EXPECT_THROW(
        (void)tracker_from_points(c.g, 2, p, fallback, c.rho, c.e, start, [&] { ++accepted; }),
        Error);
  };
  TracerSet outside = points;
  outside.position[0][3] = -1.0;
  refused(outside, {}, c.fallback);
  const std::vector<double> short_start(c.rho.size(), 0.5);  // one material's worth of two
  refused(points, {short_start, short_start, short_start}, c.fallback);
  std::vector<int> bad_fallback = c.fallback;
  bad_fallback[4] = 2;
  refused(points, {}, bad_fallback);
  EXPECT_EQ(accepted, 1);
}

/// A 1D row of 3 cells of 1 cm imported with each material's own state:
/// products (0) in cell 0, air (1) in cell 2, and cell 1 mixed with two
/// tracers of each (theta 1/2 by counts) but theta_products = 0.6 in the start.
struct MixedStart {
  static constexpr std::size_t kMixed = 1;
  grid::UniformGrid g{{0, 0, 0}, {0.01, 0.01, 0.01}, {3, 1, 1}};
  TracerSet points;
  std::vector<int> fallback{1, 1, 1};
  std::vector<double> rho, e;             // cells
  std::vector<double> theta, rho_r, e_r;  // [r * 3 + c]
  double theta_p = 0.6;
  double rho_p, e_p, rho_a, e_a;

  MixedStart(double rho_products, double e_products, double rho_air, double e_air)
      : rho_p(rho_products), e_p(e_products), rho_a(rho_air), e_a(e_air) {
    for (const double x : {0.0025, 0.0075, 0.011, 0.013}) points.add({x, 0.005, 0.005}, 0, 0.0);
    for (const double x : {0.017, 0.019, 0.025, 0.0275}) points.add({x, 0.005, 0.005}, 1, 0.0);
    const double rho_mixed = theta_p * rho_p + (1 - theta_p) * rho_a;  // T (3-28)
    const double e_mixed = (theta_p * rho_p * e_p + (1 - theta_p) * rho_a * e_a) / rho_mixed;
    rho = {rho_p, rho_mixed, rho_a};
    e = {e_p, e_mixed, e_a};
    theta = {1, theta_p, 0, 0, 1 - theta_p, 1};
    rho_r = {rho_p, rho_p, 0, 0, rho_a, rho_a};
    e_r = {e_p, e_p, 0, 0, e_a, e_a};
  }
  [[nodiscard]] MaterialStartView start() const { return {theta, rho_r, e_r}; }
  [[nodiscard]] TrackerState state(const MaterialStartView& view) const {
    return tracker_from_points(g, 2, points, fallback, rho, e, view);
  }
  /// The cell pressures after the first closure.
  std::vector<double> pressure(MultiMaterialTracker& tracker) const {
    std::vector<double> p(3);
    tracker.update_pressure(rho, e, p);
    return p;
  }
  [[nodiscard]] MultiMaterialTracker tracker(const MaterialStartView& view) const {
    return {g, {tm::kTnt, tm::kAir}, state(view)};
  }
};

TEST(TrackerImport, MaterialStart_HotDenseProductsAndColdAirStartTheClosureFromTheirOwnStates) {
  // Products 1000 kg/m^3 at 4 MJ/kg (2.2 GPa), air 1.2 kg/m^3 at 0.2 MJ/kg (0.1 MPa).
  const MixedStart m(1000.0, 4.0e6, 1.2, 2.0e5);
  const std::size_t c = MixedStart::kMixed;
  const TrackerState state = m.state(m.start());
  EXPECT_EQ(state.materials.volume_fraction(c, 0), 0.6);  // the start's, not 1/2 by counts
  EXPECT_EQ(state.materials.volume_fraction(c, 1), 1.0 - 0.6);
  EXPECT_EQ(state.states.energy[state.states.at(0, c)], m.e_p);
  EXPECT_EQ(state.states.energy[state.states.at(1, c)], m.e_a);
  EXPECT_EQ(state.states.density[state.states.at(0, c)], m.rho_p);
  EXPECT_EQ(state.states.density[state.states.at(1, c)], m.rho_a);
  // Carried volumes follow theta, T (3-22): theta_r V_c / n_br.
  EXPECT_DOUBLE_EQ(state.tracers.volume[2], 0.6 * m.g.cell_volume() / 2);
  EXPECT_DOUBLE_EQ(state.tracers.volume[4], 0.4 * m.g.cell_volume() / 2);

  MultiMaterialTracker tracker = m.tracker(m.start());
  const std::vector<double> p = m.pressure(tracker);
  const MaterialStates& s = tracker.states();
  ASSERT_EQ(s.status[c], ClosureStatus::converged);
  const double rho1 = s.density[s.at(0, c)], rho2 = s.density[s.at(1, c)];
  const double e1 = s.energy[s.at(0, c)], e2 = s.energy[s.at(1, c)];
  const double p1 = eos::pressure(eos::AnyEos{tm::kTnt}, rho1, e1);
  const double p2 = eos::pressure(eos::AnyEos{tm::kAir}, rho2, e2);
  EXPECT_NEAR(p1, p2, 1e-10 * std::abs(p1));  // T (3-24)
  EXPECT_NEAR(p[c], p1, 1e-10 * std::abs(p1));
  EXPECT_NEAR(0.6 * rho1 + 0.4 * rho2, m.rho[c], 1e-13 * m.rho[c]);  // T (3-28)
  EXPECT_NEAR(e1 / e2, m.e_p / m.e_a, 1e-12 * m.e_p / m.e_a);        // the start's ratio kept
  EXPECT_NEAR((0.6 * rho1 * e1 + 0.4 * rho2 * e2) / m.rho[c], m.e[c], 1e-12 * m.e[c]);

  // The old rule starts both from e_c: no temperature contrast, another pressure.
  MultiMaterialTracker old = m.tracker({});
  const std::vector<double> p_old = m.pressure(old);
  EXPECT_EQ(old.states().energy[s.at(0, c)], old.states().energy[s.at(1, c)]);
  EXPECT_EQ(old.materials().volume_fraction(c, 0), 0.5);
  EXPECT_GT(std::abs(p_old[c] - p[c]), 0.05 * p[c]);
  RecordProperty("pressure_new_rule_Pa", std::to_string(p[c]));
  RecordProperty("pressure_old_rule_Pa", std::to_string(p_old[c]));
  // Single-material cells are the same either way.
  EXPECT_EQ(p[0], p_old[0]);
  EXPECT_EQ(p[2], p_old[2]);
}

TEST(TrackerImport, MaterialStart_InPressureEquilibriumIsWhatTheClosureGivesBack) {
  // Hot light products (20 kg/m^3, 3 MJ/kg) and cold air at the products'
  // pressure: the closure's root is the start itself.
  const eos::AnyEos tnt{tm::kTnt};
  const double p_products = eos::pressure(tnt, 20.0, 3.0e6);
  const double e_air = 2.0e5;
  const double rho_air = p_products / ((tm::kAir.gamma - 1.0) * e_air);
  const MixedStart m(20.0, 3.0e6, rho_air, e_air);
  const std::size_t c = MixedStart::kMixed;
  MultiMaterialTracker tracker = m.tracker(m.start());
  const std::vector<double> p = m.pressure(tracker);
  const MaterialStates& s = tracker.states();
  EXPECT_NEAR(p[c], p_products, 1e-9 * p_products);
  EXPECT_NEAR(s.density[s.at(0, c)], 20.0, 1e-9 * 20.0);
  EXPECT_NEAR(s.density[s.at(1, c)], rho_air, 1e-9 * rho_air);
  EXPECT_NEAR(s.energy[s.at(0, c)], 3.0e6, 1e-9 * 3.0e6);
  EXPECT_NEAR(s.energy[s.at(1, c)], e_air, 1e-9 * e_air);
  MultiMaterialTracker old = m.tracker({});
  const std::vector<double> p_old = m.pressure(old);
  RecordProperty("pressure_old_rule_over_equilibrium", std::to_string(p_old[c] / p_products));
  EXPECT_GT(std::abs(p_old[c] - p_products), 0.02 * p_products);  // 2.9 % measured
}

TEST(TrackerImport, MaterialStart_FallsBackToTheCellStateWhereItDoesNotFitTheCell) {
  const MixedStart m(1000.0, 4.0e6, 1.2, 2.0e5);
  const std::size_t c = MixedStart::kMixed;
  const auto expect_cell_state = [&](const TrackerState& state, const char* why) {
    EXPECT_EQ(state.materials.volume_fraction(c, 0), 0.5) << why;  // by tracer counts
    for (const int r : {0, 1}) {
      EXPECT_EQ(state.states.energy[state.states.at(r, c)], m.e[c]) << why;
      EXPECT_EQ(state.states.density[state.states.at(r, c)], m.rho[c]) << why;
    }
  };
  {  // the coupler's fallback: no state for the cell
    std::vector<double> theta = m.theta, rho_r = m.rho_r, e_r = m.e_r;
    for (const std::size_t i : {c, 3 + c}) theta[i] = rho_r[i] = e_r[i] = 0.0;
    expect_cell_state(m.state({theta, rho_r, e_r}), "no state");
  }
  {  // a material the tracers put in the cell that the start lacks
    std::vector<double> theta = m.theta;
    theta[3 + c] = 0.0;
    expect_cell_state(m.state({theta, m.rho_r, m.e_r}), "one material");
  }
  {  // a non-positive energy
    std::vector<double> e_r = m.e_r;
    e_r[3 + c] = 0.0;
    expect_cell_state(m.state({m.theta, m.rho_r, e_r}), "e_r = 0");
  }
  {  // a non-finite density
    std::vector<double> rho_r = m.rho_r;
    rho_r[c] = std::nan("");
    expect_cell_state(m.state({m.theta, rho_r, m.e_r}), "rho_r NaN");
  }
  // Single-material cells always start from their cell's state.
  std::vector<double> rho_r = m.rho_r;
  rho_r[0] = 5.0;
  const TrackerState state = m.state({m.theta, rho_r, m.e_r});
  EXPECT_EQ(state.states.density[state.states.at(0, 0)], m.rho[0]);
  // A start of the wrong size is refused.
  const std::vector<double> short_theta(5, 0.0);
  EXPECT_THROW((void)m.state({short_theta, m.rho_r, m.e_r}), Error);
}

}  // namespace
}  // namespace mpfd::fdm
