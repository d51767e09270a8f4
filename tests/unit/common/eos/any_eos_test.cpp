// AnyEos dispatch: the free functions give the model's own kernels, names are
// the scene-file keys, and the house way of running a hot loop (visit once,
// loop inside) gives the same numbers.

#include "common/eos/any_eos.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <string_view>
#include <variant>

#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kAir;
using test_materials::kSteel;
using test_materials::kTnt;
using test_materials::kWater;

// The concept rejects a model whose kernels may throw: hot loops rely on noexcept.
struct ThrowingModel {
  static constexpr std::string_view name() noexcept { return "throwing"; }
  double pressure(double rho, double e) const { return rho * e; }
  double sound_speed(double /*rho*/, double e) const noexcept { return e; }
  double internal_energy(double rho, double p) const noexcept { return p / rho; }
};
[[maybe_unused]] void validate(const ThrowingModel& /*model*/) {}
static_assert(!EquationOfState<ThrowingModel>);
static_assert(EquationOfState<IdealGas> && EquationOfState<Jwl> && EquationOfState<MieGruneisen> &&
              EquationOfState<Polynomial>);

TEST(AnyEos, Names_are_the_scene_file_keys) {
  EXPECT_EQ(name(AnyEos{kAir}), "ideal_gas");
  EXPECT_EQ(name(AnyEos{kTnt}), "jwl");
  EXPECT_EQ(name(AnyEos{kSteel}), "mie_gruneisen");
  EXPECT_EQ(name(AnyEos{kWater}), "polynomial");
}

TEST(AnyEos, Free_functions_dispatch_to_the_model_kernels) {
  const AnyEos steel = kSteel;
  const double rho = 8200.0;
  const double e = 1.0e5;
  EXPECT_EQ(pressure(steel, rho, e), kSteel.pressure(rho, e));
  EXPECT_EQ(sound_speed(steel, rho, e), kSteel.sound_speed(rho, e));
  EXPECT_EQ(internal_energy(steel, rho, 1.0e9), kSteel.internal_energy(rho, 1.0e9));
}

TEST(AnyEos, Hot_loop_visits_once_and_matches_per_call_dispatch) {
  const std::array<double, 4> rho{1500.0, 1630.0, 2000.0, 800.0};
  const std::array<double, 4> e{3.0e6, 4.29e6, 5.0e6, 2.0e6};
  std::array<double, 4> p{};
  const AnyEos tnt = kTnt;
  std::visit(
      [&](const auto& eos) {
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = eos.pressure(rho[i], e[i]);
      },
      tnt);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i], pressure(tnt, rho[i], e[i]));
}

}  // namespace
}  // namespace mpfd::eos
