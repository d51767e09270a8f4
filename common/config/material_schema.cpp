#include <memory>

#include "common/config/scene_schema.hpp"

namespace mpfd::config::schema {
namespace {

const Number kDensity{"kg/m^3", Range::above(0)};
const Number kPositive{"-", Range::above(0)};
const Number kNonNegative{"-", Range::at_least(0)};
const Number kAny{"-"};

std::shared_ptr<const Table<eos::IdealGas>> ideal_gas() {
  auto t =
      make_table<eos::IdealGas>("eos: ideal_gas", "Ideal gas, T (2-59): p = (gamma - 1) rho e.");
  t->required("gamma", &eos::IdealGas::gamma, Number("-", Range::above(1)),
              "ratio of specific heats");
  return t;
}

std::shared_ptr<const Table<eos::Jwl>> jwl() {
  using eos::Jwl;
  auto t = make_table<Jwl>("eos: jwl", "Jones-Wilkins-Lee detonation products, T (2-60).");
  t->required("rho0", &Jwl::rho0, kDensity, "density of the unreacted explosive")
      .required("A", &Jwl::a, Number("Pa", Range::above(0)), "coefficient of the R1 term")
      .required("B", &Jwl::b, Number("Pa", Range::at_least(0)), "coefficient of the R2 term")
      .required("R1", &Jwl::r1, kPositive, "exponent of the high-pressure term")
      .required("R2", &Jwl::r2, kPositive, "exponent of the low-pressure term")
      .required("omega", &Jwl::omega, kPositive, "Grueneisen coefficient of the products")
      .required("E0", &Jwl::detonation_energy, Number("J/m^3", Range::above(0)),
                "detonation energy per unit initial volume (e0 = E0 / rho0)")
      .rule("R1 > R2 (R1 belongs to the high-pressure term A)", [](const Jwl& j, const Cursor& c) {
        if (j.r1 <= j.r2) {
          c.error_at("R1", "expected R1 > R2, got R1 = " + format_number(j.r1) +
                               " <= R2 = " + format_number(j.r2));
        }
      });
  return t;
}

std::shared_ptr<const Table<eos::MieGruneisen>> mie_gruneisen() {
  using eos::MieGruneisen;
  auto t = make_table<MieGruneisen>(
      "eos: mie_gruneisen", "Mie-Grueneisen with a linear Us-up Hugoniot, T (2-65), (2-66).");
  t->required("rho0", &MieGruneisen::rho0, kDensity, "reference density")
      .required("C0", &MieGruneisen::c0, Number("m/s", Range::above(0)),
                "bulk sound speed (intercept of Us-up)")
      .required("S", &MieGruneisen::s, kNonNegative, "slope of Us-up")
      .required("gamma0", &MieGruneisen::gamma0, kNonNegative, "Grueneisen coefficient");
  return t;
}

std::shared_ptr<const Table<eos::Polynomial>> polynomial() {
  using eos::Polynomial;
  auto t =
      make_table<Polynomial>("eos: polynomial",
                             "Polynomial EOS (AUTODYN form), mu = rho/rho0 - 1; see "
                             "common/eos/polynomial.hpp. Water: rho0 1000, A1 2.2e9, A2 9.54e9, "
                             "A3 1.457e10, B0 = B1 = 0.28, T1 2.2e9.");
  const Number pascals{"Pa"};
  t->required("rho0", &Polynomial::rho0, kDensity, "reference density")
      .required("A1", &Polynomial::a1, Number("Pa", Range::above(0)), "compression, linear term")
      .optional("A2", &Polynomial::a2, pascals, "compression, quadratic term")
      .optional("A3", &Polynomial::a3, pascals, "compression, cubic term")
      .optional("B0", &Polynomial::b0, kAny, "energy term")
      .optional("B1", &Polynomial::b1, kAny, "energy term, linear in mu")
      .optional("T1", &Polynomial::t1, pascals, "tension, linear term")
      .optional("T2", &Polynomial::t2, pascals, "tension, quadratic term");
  return t;
}

std::shared_ptr<const Table<ElasticStrength>> elastic() {
  auto t = make_table<ElasticStrength>("strength: elastic", "Linear elastic deviatoric response.");
  t->required("shear_modulus", &ElasticStrength::shear_modulus, Number("Pa", Range::above(0)),
              "shear modulus G");
  return t;
}

std::shared_ptr<const Table<JohnsonCook>> johnson_cook() {
  auto t = make_table<JohnsonCook>(
      "strength: johnson_cook",
      "Johnson-Cook flow stress, T (2-64): (A + B eps_p^n)(1 + C ln(epsdot/epsdot0))(1 - T*^m).");
  const Number pascals{"Pa", Range::at_least(0)};
  const Number kelvin{"K", Range::above(0)};
  t->required("A", &JohnsonCook::a, pascals, "yield stress")
      .required("B", &JohnsonCook::b, pascals, "hardening modulus")
      .required("n", &JohnsonCook::n, kNonNegative, "hardening exponent")
      .required("C", &JohnsonCook::c, kNonNegative, "strain-rate coefficient")
      .required("m", &JohnsonCook::m, kPositive, "thermal-softening exponent")
      .optional("T_room", &JohnsonCook::room_temperature, kelvin, "room temperature")
      .required("T_melt", &JohnsonCook::melt_temperature, kelvin, "melting temperature")
      .optional("reference_strain_rate", &JohnsonCook::reference_strain_rate,
                Number("1/s", Range::above(0)), "epsdot0")
      .required("specific_heat", &JohnsonCook::specific_heat, Number("J/(kg K)", Range::above(0)),
                "for the adiabatic temperature rise")
      .required("shear_modulus", &JohnsonCook::shear_modulus, Number("Pa", Range::above(0)),
                "shear modulus G")
      .optional("failure_strain", &JohnsonCook::failure_strain, kPositive,
                "equivalent plastic strain at which the material fails: no deviatoric stress, "
                "no tension; absent: never fails")
      .rule("T_melt > T_room", [](const JohnsonCook& j, const Cursor& c) {
        if (j.melt_temperature <= j.room_temperature) {
          c.error_at("T_melt", "expected T_melt > T_room = " + format_number(j.room_temperature) +
                                   ", got " + format_number(j.melt_temperature));
        }
      });
  return t;
}

std::shared_ptr<const Table<Explosive>> explosive() {
  auto t = make_table<Explosive>("materials.<name>.explosive",
                                 "Present for a material that detonates (charges must use one).");
  t->required("detonation_velocity", &Explosive::detonation_velocity,
              Number("m/s", Range::above(0)), "D of the program burn, T (3-1)");
  return t;
}

}  // namespace

std::shared_ptr<const Table<Material>> material_table() {
  static const std::shared_ptr<const Table<Material>> built = [] {
    Choice<eos::AnyEos> eos("materials.<name>.eos", "Equation of state.");
    eos.add("ideal_gas", ideal_gas())
        .add("jwl", jwl())
        .add("mie_gruneisen", mie_gruneisen())
        .add("polynomial", polynomial());
    Choice<AnyStrength> strength("materials.<name>.strength", "Deviatoric strength model.");
    strength
        .add<NoStrength>("none", make_table<NoStrength>("strength: none", "No strength (fluids)."))
        .add("elastic", elastic())
        .add("johnson_cook", johnson_cook())
        .planned("drucker_prager")
        .planned("hjc")
        .planned("jh2")
        .planned("rht");
    auto t = make_table<Material>("materials.<name>", "One material, named by its key.");
    t->required("eos", &Material::eos, eos, "equation of state")
        .optional("strength", &Material::strength, strength, "strength model")
        .optional("explosive", &Material::explosive, Nested<Explosive>(explosive()),
                  "detonation data; makes the material usable by charges");
    return t;
  }();
  return built;
}

}  // namespace mpfd::config::schema
