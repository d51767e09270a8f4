// fdm_solver serve refuses what it cannot do with an Error naming what is
// wrong, then stops (fatal errors) or carries on (unsupported requests).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zmq_addon.hpp>

#include "cosim/codec.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(FdmServeErrors, RegionOutsideTheGridIsRefusedAtSetupNamingRegionAndBounds) {
  ServedFdm fdm;
  const auto text = fdm.refusal(setup(sod_text(100), {cell_box("ghost_cells", {95}, {101})}));
  EXPECT_THAT(text, AllOf(HasSubstr("ERROR_CODE_UNKNOWN_REGION"), HasSubstr("'ghost_cells'"),
                          HasSubstr("hi [101]"), HasSubstr("0 <= lo < hi <= 100")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("stopped after reporting ERROR_CODE_UNKNOWN_REGION"));
}

TEST(FdmServeErrors, ApplyToARegionNotDeclaredInSetupNamesItAndTheDeclaredOnes) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(100), {cell_box("strip_cells", {40}, {42})}));
  cosim::Message exchange;
  add_apply(exchange, "deposit_cells", v1::ApplyRegion::MODE_ADD);
  EXPECT_THAT(fdm.refusal(std::move(exchange)),
              AllOf(HasSubstr("ERROR_CODE_UNKNOWN_REGION"), HasSubstr("'deposit_cells'"),
                    HasSubstr("declared: strip_cells")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_UNKNOWN_REGION"));
}

TEST(FdmServeErrors, ApplyArrayOfTheWrongLengthNamesRegionQuantityExpectedAndGot) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(100), {cell_box("ghost_cells", {60}, {63})}));
  cosim::Message exchange;
  add_apply(exchange, "ghost_cells", v1::ApplyRegion::MODE_SET);
  cosim::add_array(exchange, {"ghost_cells", "momentum", {}, "kg/(m^2*s)"},
                   std::vector<double>(3, 0.0));
  EXPECT_THAT(
      fdm.refusal(std::move(exchange)),
      AllOf(HasSubstr("ERROR_CODE_MALFORMED"), HasSubstr("region 'ghost_cells'"),
            HasSubstr("quantity 'momentum'"), HasSubstr("expected 9 values"), HasSubstr("got 3")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_MALFORMED"));
}

TEST(FdmServeErrors, AdvanceFromAnotherTimeThanTheSolversNamesBothTimes) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(100), {}));
  cosim::Message exchange;
  add_advance(exchange, 1e-3, 0.5);
  EXPECT_THAT(fdm.refusal(std::move(exchange)),
              AllOf(HasSubstr("ERROR_CODE_UNEXPECTED"), HasSubstr("Advance from time 0.5 s"),
                    HasSubstr("the solver is at 0 s")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_UNEXPECTED"));
}

TEST(FdmServeErrors, NegativeDensityBreaksTheAdvanceAndIsReportedAsNumerical) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(100), {cell_box("cell", {30}, {31}, {"rho"})}));
  cosim::Message exchange;
  add_apply(exchange, "cell", v1::ApplyRegion::MODE_SET);
  cosim::add_array(exchange, {"cell", "rho", {}, "kg/m^3"}, std::vector<double>{-1.0});
  add_advance(exchange, 1e-3, 0.0);
  EXPECT_THAT(fdm.refusal(std::move(exchange)),
              AllOf(HasSubstr("ERROR_CODE_NUMERICAL"), HasSubstr("unphysical state in cell")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_NUMERICAL"));
}

TEST(FdmServeErrors, FieldExportOfAnUndeclaredRegionIsRefusedAndTheSolverCarriesOn) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(100), {}));
  cosim::Message field_export;
  field_export.header.mutable_field_export()->set_transfer_id("never");
  field_export.header.mutable_field_export()->add_fields("nowhere/rho");
  EXPECT_THAT(fdm.refusal(std::move(field_export)),
              AllOf(HasSubstr("ERROR_CODE_UNKNOWN_REGION"), HasSubstr("'nowhere'")));
  cosim::Message exchange;
  exchange.header.mutable_exchange()->add_operations()->mutable_propose_dt();
  EXPECT_GT(
      fdm.request(std::move(exchange)).header.exchange_result().results(0).proposed().stable_dt(),
      0.0);
  fdm.shut_down();
  EXPECT_EQ(fdm.stop_reason(), "");
}

/// A coupler that answers the solver's Hello with `answer` on a raw ROUTER;
/// returns the Hello it received and what serve() threw.
std::pair<v1::Hello, std::string> hello_answered_with(cosim::Message answer) {
  zmq::context_t context;
  zmq::socket_t router(context, zmq::socket_type::router);
  router.set(zmq::sockopt::linger, 0);
  const std::string endpoint = cosim::testing::unique_bind_endpoint(cosim::Transport::inproc);
  router.bind(endpoint);
  std::string stop_reason;
  cosim::testing::SolverThread solver([&] {
    try {
      serve(context, {.endpoint = endpoint, .idle_timeout = std::chrono::milliseconds{2000}});
    } catch (const Error& error) {
      stop_reason = error.what();
    }
  });
  std::vector<zmq::message_t> parts;
  EXPECT_TRUE(zmq::recv_multipart(router, std::back_inserter(parts)));
  const std::string peer = parts.front().to_string();
  parts.erase(parts.begin());
  const v1::Hello hello = cosim::decode(std::move(parts)).header.hello();
  auto& envelope = *answer.header.mutable_envelope();
  envelope.set_protocol_major(cosim::protocol_major);
  envelope.set_sender("coupler");
  envelope.set_sequence(1);
  std::vector<zmq::message_t> reply = cosim::encode(std::move(answer));
  reply.insert(reply.begin(), zmq::message_t(peer));
  zmq::send_multipart(router, reply);
  solver.join_and_rethrow();
  return {hello, stop_reason};
}

TEST(FdmServeErrors, VersionMismatchFromTheCouplerStopsTheSolverWithTheCouplersReason) {
  cosim::Message refusal;
  refusal.header.mutable_error()->set_code(v1::ERROR_CODE_VERSION_MISMATCH);
  refusal.header.mutable_error()->set_message("the coupler speaks v7 only");
  const auto [hello, reason] = hello_answered_with(std::move(refusal));
  EXPECT_EQ(hello.role(), v1::ROLE_EULER_SOLVER);
  EXPECT_EQ(hello.software(), "mpfd fdm_solver");
  EXPECT_EQ(hello.min_major(), 1U);
  EXPECT_EQ(hello.max_major(), 1U);
  for (const char* capability :
       {"cell_regions", "field_chunks", "tracer_regions", "material_fields"})
    EXPECT_THAT(hello.capabilities(), ::testing::Contains(capability));
  EXPECT_THAT(reason, AllOf(HasSubstr("ERROR_CODE_VERSION_MISMATCH"),
                            HasSubstr("the coupler speaks v7 only")));
}

TEST(FdmServeErrors, CouplerChoosingAnotherMajorVersionIsRefused) {
  cosim::Message ack;
  ack.header.mutable_hello_ack()->set_major(2);
  EXPECT_THAT(hello_answered_with(std::move(ack)).second,
              HasSubstr("the coupler chose protocol v2; solver 'fdm' speaks v1"));
}

}  // namespace
}  // namespace mpfd::fdm
