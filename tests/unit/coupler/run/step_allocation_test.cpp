// The coupler's step allocates nothing once warm (issue 5; STYLE: no heap
// allocation inside a time step). CfdmpStep is driven through the checked-in
// recording (data/cfdmp_small.mpfdrec, 41 steps, the shock crossing the zone
// face, so deposits, injections and removals happen): every request it builds
// must equal the recorded one bit for bit (operations, descriptors, frames),
// and build + read, counted by this program's global operator new, must not
// allocate in a step whose kinds of operations and array sizes occurred before
// (the first such steps size the kept memory). The transport (Hub, ZeroMQ
// frames, decoding of replies) is not counted: it is not the coupler's step.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <new>
#include <set>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "cosim/player.hpp"
#include "coupler/run/cfdmp_step.hpp"
#include "coupler/run/wire.hpp"
#include "coupler/run/zone_layout.hpp"

namespace {

thread_local bool counting = false;
thread_local long allocations = 0;

}  // namespace

// The replacements pair malloc with free; GCC's check cannot see that through inlining.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace mpfd::coupler {
namespace {

const std::filesystem::path kRecording =
    std::filesystem::path(MPFD_TEST_DATA) / "cfdmp_small.mpfdrec";

struct RecordedStep {
  cosim::Message fdm_request, mpm_request, fdm_reply, mpm_reply;
};

/// Operation kinds and array sizes of a request or reply: what the kept memory must hold.
std::string shape_of(const cosim::Message& message) {
  std::string shape;
  for (const auto& op : message.header.exchange().operations())
    shape += std::to_string(op.op_case()) + ",";
  for (const auto& array : message.header.arrays()) {
    shape += array.group() + "/" + array.name() + ":";
    // The face cell's particle count changes with each injection and removal; the
    // step sums it straight from the message's views and stores nothing.
    if (array.group() == "face_particles") continue;
    for (const auto extent : array.shape()) shape += std::to_string(extent) + " ";
  }
  return shape;
}

void expect_same_request(const cosim::Message& built, const cosim::Message& recorded,
                         std::size_t step, const char* peer) {
  SCOPED_TRACE(std::string(peer) + " request of step " + std::to_string(step));
  ASSERT_EQ(built.header.exchange().SerializeAsString(),
            recorded.header.exchange().SerializeAsString());
  ASSERT_EQ(built.header.arrays_size(), recorded.header.arrays_size());
  ASSERT_EQ(built.frames.size(), recorded.frames.size());
  for (int i = 0; i < built.header.arrays_size(); ++i)
    ASSERT_EQ(built.header.arrays(i).SerializeAsString(),
              recorded.header.arrays(i).SerializeAsString());
  for (std::size_t i = 0; i < built.frames.size(); ++i) {
    ASSERT_EQ(built.frames[i].size(), recorded.frames[i].size());
    EXPECT_EQ(
        std::memcmp(built.frames[i].data(), recorded.frames[i].data(), built.frames[i].size()), 0)
        << "frame " << i;
  }
}

TEST(CoupledStep, Rebuilds_the_recorded_requests_and_allocates_nothing_once_warm) {
  cosim::Player player(kRecording);
  std::string scene_text;
  std::map<std::string, std::vector<cosim::Message>> sent, received;
  std::map<std::string, std::set<std::string>> capabilities;
  while (auto record = player.next()) {
    auto& header = record->message.header;
    if (header.has_hello())
      for (const auto& capability : header.hello().capabilities())
        capabilities[record->peer].insert(capability);
    if (header.has_setup() && record->peer == "fdm") scene_text = header.setup().scene_fragment();
    if (header.has_exchange()) sent[record->peer].push_back(std::move(record->message));
    if (header.has_exchange_result()) received[record->peer].push_back(std::move(record->message));
  }
  ASSERT_FALSE(scene_text.empty());
  ASSERT_EQ(sent["fdm"].size(), received["fdm"].size());
  ASSERT_EQ(sent["mpm"].size(), sent["fdm"].size());
  ASSERT_EQ(received["mpm"].size(), sent["fdm"].size());

  const auto scene = config::parse_scene(scene_text, "cfdmp_small.yaml");
  const ZoneLayout layout = make_zone_layout(scene);
  ASSERT_EQ(layout.dimension, 1);
  // The features coupler run negotiates from the recorded Hellos (protocol v1.1).
  const SolverFeatures features{.fdm_face_crossing = capabilities["fdm"].contains("face_crossing"),
                                .fdm_outflow = capabilities["fdm"].contains("boundary_outflow"),
                                .mpm_outflow = capabilities["mpm"].contains("boundary_outflow")};
  ASSERT_TRUE(features.fdm_face_crossing);
  CfdmpStep<1> step(scene, layout, features);
  cosim::Message fdm, mpm;
  std::set<std::string> seen;
  std::size_t warm_steps = 0, traffic_steps = 0;
  for (std::size_t n = 0; n < sent["fdm"].size(); ++n) {
    const cosim::Message& recorded = sent["fdm"][n];
    StepPlan plan;
    for (const auto& op : recorded.header.exchange().operations()) {
      if (op.has_advance()) {
        plan.advance = true;
        plan.dt = op.advance().dt();
        plan.time = op.advance().time();
      }
      plan.audit =
          plan.audit || (op.has_export_region() && op.export_region().region() == "fdm_owned");
    }
    allocations = 0;
    counting = true;
    clear_for_reuse(fdm);
    clear_for_reuse(mpm);
    step.build(plan, fdm, mpm);
    counting = false;
    expect_same_request(fdm, recorded, n, "fdm");
    expect_same_request(mpm, sent["mpm"][n], n, "mpm");
    counting = true;
    step.read(plan, received["fdm"][n], received["mpm"][n]);
    counting = false;
    const std::string shape = shape_of(fdm) + "|" + shape_of(mpm) + "|" +
                              shape_of(received["fdm"][n]) + "|" + shape_of(received["mpm"][n]);
    const bool known = !seen.insert(shape).second;
    if (n >= 3 && known) {
      EXPECT_EQ(allocations, 0) << "step " << n << " (" << shape << ")";
      ++warm_steps;
    }
    const auto& traffic = step.traffic();
    if (traffic.injected + traffic.removed > 0 || traffic.deposited_mass > 0) ++traffic_steps;
  }
  // Not vacuous: most steps repeat an earlier shape, and the face carries traffic.
  EXPECT_GT(warm_steps, sent["fdm"].size() / 2);
  EXPECT_GT(traffic_steps, 5U);
}

}  // namespace
}  // namespace mpfd::coupler
