// SphericalMpm::restore: a solver given the particles and clock of another run's
// step goes on bit for bit as that run (AFDMP's 1D stage restarts so); a state
// of other particles is refused and leaves the solver as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "common/core/error.hpp"
#include "underwater_case.hpp"

namespace mpfd::mpm::spherical {
namespace {

using ::testing::HasSubstr;

SphericalOptions detonating() {
  SphericalOptions o;
  o.grid_spacing = 0.02;
  o.outer_boundary = OuterBoundary::transmitting;
  return o;
}

void advance(SphericalMpm& mpm, int steps) {
  for (int n = 0; n < steps; ++n) mpm.advance(mpm.stable_dt());
}

TEST(SphericalRestore, A_solver_given_a_steps_particles_goes_on_bit_for_bit) {
  SphericalMpm run(testing::underwater_layers(1.0), detonating());
  advance(run, 5);  // ~7 us: the 0.1 m charge half burnt (F between 0 and 1 in play)
  const SphericalParticles at_5 = run.particles();
  const double time_5 = run.time();
  ASSERT_GT(std::count_if(at_5.burn_fraction.begin(), at_5.burn_fraction.end(),
                          [](double f) { return f > 0 && f < 1; }),
            0);
  advance(run, 40);

  SphericalMpm restarted(testing::underwater_layers(1.0), detonating());
  restarted.restore(at_5, time_5);
  advance(restarted, 40);
  EXPECT_EQ(restarted.time(), run.time());
  const auto expected = run.particles().scalar_fields();
  const auto got = restarted.particles().scalar_fields();
  for (std::size_t f = 0; f < expected.size(); ++f)
    EXPECT_EQ(*got[f].second, *expected[f].second) << expected[f].first;
  EXPECT_EQ(restarted.particles().history, run.particles().history);
  for (std::size_t p = 0; p < run.particles().size(); ++p)
    ASSERT_EQ(restarted.particles().deviatoric_stress[p], run.particles().deviatoric_stress[p])
        << p;
}

TEST(SphericalRestore, Particles_of_another_seeding_are_refused_and_the_solver_kept) {
  SphericalMpm mpm(testing::underwater_layers(1.0), detonating());
  const SphericalParticles own = mpm.particles();
  const auto refusal = [&](const SphericalParticles& state, double time) {
    try {
      mpm.restore(state, time);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const SphericalParticles longer =
      SphericalMpm(testing::underwater_layers(1.5), detonating()).particles();
  EXPECT_THAT(refusal(longer, 0.0), HasSubstr("particles; this run seeds"));
  SphericalParticles reordered = own;
  std::swap(reordered.material.front(), reordered.material.back());
  EXPECT_THAT(refusal(reordered, 0.0), HasSubstr("particle 0 has material"));
  SphericalParticles short_materials = own;
  short_materials.material.pop_back();
  EXPECT_THAT(refusal(short_materials, 0.0), HasSubstr("materials; expected one per particle"));
  SphericalParticles short_field = own;
  short_field.temperature.pop_back();
  EXPECT_THAT(refusal(short_field, 0.0), HasSubstr("'temperature'"));
  EXPECT_THAT(refusal(own, -1.0), HasSubstr("expected a finite time >= 0"));
  EXPECT_EQ(mpm.time(), 0.0);
  EXPECT_EQ(mpm.particles().radius, own.radius);
}

}  // namespace
}  // namespace mpfd::mpm::spherical
