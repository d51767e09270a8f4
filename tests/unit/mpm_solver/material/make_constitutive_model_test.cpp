#include <gtest/gtest.h>

#include <string>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "tests/unit/mpm_solver/material/thesis_metals.hpp"

namespace mpfd::mpm {
namespace {

config::Material steel_with(config::AnyStrength strength) {
  config::Material steel;
  steel.name = "plate";
  steel.eos = test_support::steel_1006().eos;
  steel.strength = strength;
  return steel;
}

std::string error_of(const config::Material& material) {
  try {
    (void)make_constitutive_model(material);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(MakeConstitutiveModel, Gives_the_strength_model_on_the_material_eos) {
  const auto elastic = make_constitutive_model(steel_with(config::ElasticStrength{81.8e9}));
  EXPECT_EQ(elastic->name(), "elastic+mie_gruneisen");
  EXPECT_EQ(elastic->history_count(), 0);
  const auto jc = make_constitutive_model(steel_with(test_support::steel_1006().strength));
  EXPECT_EQ(jc->name(), "johnson_cook+mie_gruneisen");
  EXPECT_EQ(jc->history_count(), 1);
}

TEST(MakeConstitutiveModel, Rejects_strength_on_a_gas_or_an_explosive_naming_the_material) {
  config::Material gas = steel_with(test_support::steel_1006().strength);
  gas.eos = eos::IdealGas{1.4};
  EXPECT_EQ(error_of(gas),
            "material 'plate': strength 'johnson_cook' needs a solid equation of state "
            "(mie_gruneisen or polynomial), got 'ideal_gas'");
  config::Material products = steel_with(config::ElasticStrength{1e9});
  products.eos = eos::Jwl{1630, 3.712e11, 3.21e9, 4.15, 0.95, 0.3, 6.993e9};
  EXPECT_EQ(error_of(products),
            "material 'plate': strength 'elastic' needs a solid equation of state "
            "(mie_gruneisen or polynomial), got 'jwl'");
  config::Material explosive = steel_with(config::ElasticStrength{1e9});
  explosive.explosive = config::Explosive{6930};
  EXPECT_EQ(error_of(explosive),
            "material 'plate': strength 'elastic' cannot apply to an explosive (it detonates and "
            "is burnt as a fluid); expected strength 'none'");
}

TEST(ThesisMetals, Unit_conversions_of_the_tables) {
  // T table 3.2: E = 212680 MPa, nu = 0.3 -> G = 81.8 GPa; rho = 0.00789 g/mm^3.
  EXPECT_NEAR(test_support::steel_1006().strength.shear_modulus, 81.8e9, 1e-12 * 81.8e9);
  EXPECT_NEAR(test_support::steel_1006().eos.rho0, 7890.0, 1e-12 * 7890.0);
  // Table 4.5: E = 210000 MPa, nu = 0.28 -> G = 82.03 GPa; A = 950 MPa.
  EXPECT_NEAR(test_support::rha().strength.shear_modulus, 82.03125e9, 1e-12 * 82e9);
  EXPECT_EQ(test_support::rha().strength.a, 950e6);
  // Table 5.5: E = 75000 MPa, nu = 0.33 -> G = 28.195 GPa; rho = 2770 kg/m^3.
  EXPECT_NEAR(test_support::al_2024().strength.shear_modulus, 75e9 / 2.66, 1e-12 * 28e9);
  EXPECT_NEAR(test_support::al_2024().eos.rho0, 2770.0, 1e-12 * 2770.0);
}

}  // namespace
}  // namespace mpfd::mpm
