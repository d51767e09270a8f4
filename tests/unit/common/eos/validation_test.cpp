// validate() reports a bad material by model, parameter, rule and value, so
// the scene parser can pass the message to the user as is.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <ostream>
#include <string>

#include "common/core/error.hpp"
#include "common/eos/any_eos.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kAir;
using test_materials::kSteel;
using test_materials::kTnt;
using test_materials::kWater;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct BadMaterial {
  std::string label;
  AnyEos eos;
  std::string message;
};

void PrintTo(const BadMaterial& bad, std::ostream* os) {
  *os << bad.label;
}

std::string bad_label(const ::testing::TestParamInfo<BadMaterial>& info) {
  return info.param.label;
}

template <class Model, class Edit>
AnyEos edited(Model model, Edit edit) {
  edit(model);
  return model;
}

class Validation : public ::testing::TestWithParam<BadMaterial> {};

TEST_P(Validation, Message_names_model_parameter_rule_and_value) {
  const BadMaterial& bad = GetParam();
  EXPECT_THAT([&] { validate(bad.eos); }, ThrowsMessage<Error>(HasSubstr(bad.message)));
}

INSTANTIATE_TEST_SUITE_P(
    EveryRule, Validation,
    ::testing::Values(
        BadMaterial{"ideal_gas_gamma_at_most_1", IdealGas{.gamma = 0.9},
                    "ideal_gas: gamma must be > 1, got 0.9"},
        BadMaterial{"ideal_gas_gamma_nan", IdealGas{.gamma = kNan},
                    "ideal_gas: gamma must be > 1, got nan"},
        BadMaterial{"jwl_rho0", edited(kTnt, [](Jwl& m) { m.rho0 = 0.0; }),
                    "jwl: rho0 must be > 0, got 0"},
        BadMaterial{"jwl_a", edited(kTnt, [](Jwl& m) { m.a = -1.0; }),
                    "jwl: a must be >= 0, got -1"},
        BadMaterial{"jwl_b", edited(kTnt, [](Jwl& m) { m.b = -3.21e9; }),
                    "jwl: b must be >= 0, got -3.21e+09"},
        BadMaterial{"jwl_r2", edited(kTnt, [](Jwl& m) { m.r2 = 0.0; }),
                    "jwl: r2 must be > 0, got 0"},
        BadMaterial{"jwl_r1_below_r2", edited(kTnt, [](Jwl& m) { m.r1 = 0.9; }),
                    "jwl: r1 must be > r2 = 0.95, got 0.9"},
        BadMaterial{"jwl_omega", edited(kTnt, [](Jwl& m) { m.omega = 1.0; }),
                    "jwl: omega must be in (0, 1), got 1"},
        BadMaterial{"jwl_energy", edited(kTnt, [](Jwl& m) { m.detonation_energy = 0.0; }),
                    "jwl: detonation_energy must be > 0, got 0"},
        BadMaterial{"jwl_a_infinite", edited(kTnt, [](Jwl& m) { m.a = kInf; }),
                    "jwl: a must be >= 0, got inf"},
        BadMaterial{"mie_gruneisen_rho0", edited(kSteel, [](MieGruneisen& m) { m.rho0 = -7890.0; }),
                    "mie_gruneisen: rho0 must be > 0, got -7890"},
        BadMaterial{"mie_gruneisen_c0", edited(kSteel, [](MieGruneisen& m) { m.c0 = 0.0; }),
                    "mie_gruneisen: c0 must be > 0, got 0"},
        BadMaterial{"mie_gruneisen_s", edited(kSteel, [](MieGruneisen& m) { m.s = -1.49; }),
                    "mie_gruneisen: s must be > 0, got -1.49"},
        BadMaterial{"mie_gruneisen_gamma0",
                    edited(kSteel, [](MieGruneisen& m) { m.gamma0 = -0.5; }),
                    "mie_gruneisen: gamma0 must be >= 0, got -0.5"},
        BadMaterial{"polynomial_rho0", edited(kWater, [](Polynomial& m) { m.rho0 = kInf; }),
                    "polynomial: rho0 must be > 0, got inf"},
        BadMaterial{"polynomial_a1", edited(kWater, [](Polynomial& m) { m.a1 = 0.0; }),
                    "polynomial: a1 must be > 0"},
        BadMaterial{"polynomial_t1", edited(kWater, [](Polynomial& m) { m.t1 = -2.2e9; }),
                    "polynomial: t1 must be > 0"},
        BadMaterial{"polynomial_b1_nan", edited(kWater, [](Polynomial& m) { m.b1 = kNan; }),
                    "polynomial: b1 must be finite, got nan"}),
    bad_label);

TEST(Validation, Seed_materials_are_valid) {
  for (const AnyEos& eos : {AnyEos{kAir}, AnyEos{kTnt}, AnyEos{kSteel}, AnyEos{kWater}}) {
    EXPECT_NO_THROW(validate(eos)) << name(eos);
  }
}

TEST(Validation, Mie_gruneisen_accepts_zero_gruneisen_and_slope_below_one) {
  EXPECT_NO_THROW(validate(edited(kSteel, [](MieGruneisen& m) {
    m.gamma0 = 0.0;
    m.s = 0.8;
  })));
}

}  // namespace
}  // namespace mpfd::eos
