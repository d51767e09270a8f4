// Requests `mpm_solver serve` must refuse: each Error names the region,
// quantity, group or field at fault, and the solver stops after a fatal one.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(MpmServeErrors, ExportOfAnUndeclaredRegionNamesItAndTheDeclaredOnes) {
  ServedMpm served;
  served.request(setup(blast_text(), cfdmp_regions()));
  cosim::Message exchange;
  add_export(exchange, "ghost_cells");
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("region 'ghost_cells'"), HasSubstr("ghost_nodes")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("UNKNOWN_REGION"));
}

TEST(MpmServeErrors, ApplyOfAQuantityTheRegionDoesNotDeclareNamesRegionAndQuantity) {
  ServedMpm served;
  served.request(setup(blast_text(), cfdmp_regions()));
  cosim::Message exchange;
  auto& apply = *add_op(exchange).mutable_apply();
  apply.set_region("ghost_nodes");
  apply.set_mode(v1::ApplyRegion::MODE_ADD);
  const std::vector<double> force(3 * 17 * 3, 1.0);
  cosim::add_array(exchange, {"ghost_nodes", "internal_force", {51, 3}, "N"},
                   std::span<const double>(force));
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("region 'ghost_nodes'"), HasSubstr("quantity 'internal_force'")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("UNKNOWN_REGION"));
}

TEST(MpmServeErrors, ApplyWithTheWrongNodeCountNamesExpectedAndGot) {
  ServedMpm served;
  served.request(setup(blast_text(), cfdmp_regions()));
  cosim::Message exchange;
  auto& apply = *add_op(exchange).mutable_apply();
  apply.set_region("interface_nodes");
  apply.set_mode(v1::ApplyRegion::MODE_SET);
  const std::vector<double> mass(16, 1.0);
  cosim::add_array(exchange, {"interface_nodes", "mass", {}, "kg"}, std::span<const double>(mass));
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("region 'interface_nodes'"), HasSubstr("quantity 'mass'"),
                    HasSubstr("expected 17 values"), HasSubstr("got 16")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("MALFORMED"));
}

TEST(MpmServeErrors, InjectionWithoutVolumeNamesTheGroupAndTheField) {
  ServedMpm served;
  served.request(setup(blast_text(), {}));
  cosim::Message exchange;
  add_op(exchange).mutable_inject()->set_group("injected");
  const std::vector<std::uint64_t> id = {7};
  const std::vector<double> vector3 = {0.5, 0.5, 0.03};
  const std::vector<double> one = {1.0};
  const std::vector<std::uint32_t> material = {0};
  cosim::add_array(exchange, {"injected", "id", {}, "1"}, std::span<const std::uint64_t>(id));
  cosim::add_array(exchange, {"injected", "position", {1, 3}, "m"},
                   std::span<const double>(vector3));
  cosim::add_array(exchange, {"injected", "velocity", {1, 3}, "m/s"},
                   std::span<const double>(vector3));
  cosim::add_array(exchange, {"injected", "mass", {}, "kg"}, std::span<const double>(one));
  cosim::add_array(exchange, {"injected", "internal_energy", {}, "J"},
                   std::span<const double>(one));
  cosim::add_array(exchange, {"injected", "material", {}, "1"},
                   std::span<const std::uint32_t>(material));
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("group 'injected'"), HasSubstr("array 'volume' is missing")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("MALFORMED"));
}

TEST(MpmServeErrors, InjectionOffTheGridNamesTheParticle) {
  ServedMpm served;
  served.request(setup(blast_text(), {}));
  cosim::Message exchange;
  add_op(exchange).mutable_inject()->set_group("in");
  const std::vector<std::uint64_t> id = {42};
  const std::vector<double> position = {1.5, 0.5, 0.03};
  const std::vector<double> one = {1.0};
  const std::vector<std::uint32_t> material = {0};
  cosim::add_array(exchange, {"in", "id", {}, "1"}, std::span<const std::uint64_t>(id));
  cosim::add_array(exchange, {"in", "position", {1, 3}, "m"}, std::span<const double>(position));
  cosim::add_array(exchange, {"in", "velocity", {1, 3}, "m/s"}, std::span<const double>(position));
  for (const char* name : {"mass", "volume", "internal_energy"})
    cosim::add_array(exchange, {"in", name, {}, ""}, std::span<const double>(one));
  cosim::add_array(exchange, {"in", "material", {}, "1"}, std::span<const std::uint32_t>(material));
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("(id 42)"), HasSubstr("off the grid")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("MALFORMED"));
}

TEST(MpmServeErrors, RemovalOfAnUnknownIdNamesIt) {
  ServedMpm served;
  served.request(setup(blast_text(), {}));
  cosim::Message exchange;
  add_op(exchange).mutable_remove()->set_group("gone");
  const std::vector<std::uint64_t> id = {12345};
  cosim::add_array(exchange, {"gone", "id", {}, "1"}, std::span<const std::uint64_t>(id));
  EXPECT_THAT(served.refusal(std::move(exchange)),
              AllOf(HasSubstr("group 'gone'"), HasSubstr("particle 12345")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("MALFORMED"));
}

TEST(MpmServeErrors, SetupRegionOutsideTheGridNamesTheRegionAndAxis) {
  ServedMpm served;
  EXPECT_THAT(served.refusal(setup(blast_text(), {region("ghost_nodes", v1::REGION_KIND_NODES,
                                                         {3, 0, 0}, {6, 18, 1})})),
              AllOf(HasSubstr("region 'ghost_nodes'"), HasSubstr("axis 1"),
                    HasSubstr("<= 17 (node indices)")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("UNKNOWN_REGION"));
}

TEST(MpmServeErrors, SetupRegionWithAnUnknownQuantityNamesIt) {
  ServedMpm served;
  EXPECT_THAT(served.refusal(setup(blast_text(), {region("mpm_zone", v1::REGION_KIND_PARTICLES,
                                                         {4, 0, 0}, {12, 16, 1}, {"rho"})})),
              AllOf(HasSubstr("region 'mpm_zone'"), HasSubstr("unknown quantity 'rho'")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("UNKNOWN_REGION"));
}

TEST(MpmServeErrors, AnAdvanceFromAnotherTimeIsRefused) {
  ServedMpm served;
  const double dt = served.request(setup(blast_text(), {})).header.setup_ack().stable_dt();
  cosim::Message exchange;
  add_advance(exchange, dt, 1.0);
  EXPECT_THAT(served.refusal(std::move(exchange)), HasSubstr("the solver is at 0 s"));
  EXPECT_THAT(served.stop_reason(), HasSubstr("UNEXPECTED"));
}

TEST(MpmServeErrors, AFieldExportOfAnUnknownRegionIsRefusedWithoutStopping) {
  ServedMpm served;
  served.request(setup(blast_text(), {}));
  cosim::Message handoff;
  handoff.header.mutable_field_export()->set_transfer_id("t");
  handoff.header.mutable_field_export()->add_fields("nowhere/mass");
  EXPECT_THAT(served.refusal(std::move(handoff)),
              AllOf(HasSubstr("UNKNOWN_REGION"), HasSubstr("'nowhere/mass'"),
                    HasSubstr("region 'nowhere' was not declared")));
  cosim::Message exchange;
  add_propose(exchange);
  EXPECT_GT(served.request(std::move(exchange))
                .header.exchange_result()
                .results(0)
                .proposed()
                .stable_dt(),
            0.0);
}

}  // namespace
}  // namespace mpfd::mpm
