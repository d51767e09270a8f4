#include "coupler/run/wire.hpp"

#include <algorithm>
#include <array>

#include "common/core/error.hpp"

namespace mpfd::coupler {

v1::Exchange& exchange_of(cosim::Message& message) {
  return *message.header.mutable_exchange();
}

namespace {

/// Empties the body of an operation and keeps it (Operation::Clear() would delete it).
void clear_body(v1::Operation& operation) {
  switch (operation.op_case()) {
    case v1::Operation::kApply:
      operation.mutable_apply()->Clear();
      break;
    case v1::Operation::kExportRegion:
      operation.mutable_export_region()->Clear();
      break;
    case v1::Operation::kInject:
      operation.mutable_inject()->Clear();
      break;
    case v1::Operation::kRemove:
      operation.mutable_remove()->Clear();
      break;
    case v1::Operation::kAdvance:
      operation.mutable_advance()->Clear();
      break;
    case v1::Operation::kProposeDt:
      operation.mutable_propose_dt()->Clear();
      break;
    case v1::Operation::kSample:
      operation.mutable_sample()->Clear();
      break;
    default:  // none, or a kind newer than this code: not kept
      operation.Clear();
  }
}

}  // namespace

void clear_for_reuse(cosim::Message& message) {
  message.frames.clear();
  message.header.mutable_arrays()->Clear();  // keeps the descriptors and their strings for reuse
  // Clear() would delete each operation's body (a oneof, owned by pointer). So
  // the bodies are cleared in place and the operations parked in order (the
  // spares of a longer step after them): next_operation() hands them back, and
  // mutable_<kind>() reuses the body when the kind is the same.
  auto& operations = *exchange_of(message).mutable_operations();
  const int live = operations.size();
  const int spare = operations.ClearedCount();
  std::array<v1::Operation*, 64> parked{};
  if (live + spare > static_cast<int>(parked.size())) {
    operations.Clear();
    return;
  }
  operations.ExtractSubrange(0, live, parked.data());
  for (int i = live; i < live + spare; ++i)
    parked[static_cast<std::size_t>(i)] = operations.ReleaseCleared();
  for (int i = 0; i < live + spare; ++i) {
    v1::Operation& operation = *parked[static_cast<std::size_t>(i)];
    clear_body(operation);
    operations.AddCleared(&operation);
  }
}

v1::Operation& next_operation(cosim::Message& message, v1::Operation::OpCase kind) {
  auto& operations = *exchange_of(message).mutable_operations();
  for (int spares = operations.ClearedCount(); spares > 0; --spares) {
    v1::Operation* next = operations.Add();
    if (next->op_case() == kind) return *next;
    operations.ExtractSubrange(operations.size() - 1, 1, &next);  // to the back of the spares
    operations.AddCleared(next);
  }
  // None of this kind is parked: a new one, so that the spares keep their bodies.
  operations.AddAllocated(google::protobuf::Arena::CreateMessage<v1::Operation>(nullptr));
  return *operations.Mutable(operations.size() - 1);
}

void add_apply(cosim::Message& message, std::string_view region, v1::ApplyRegion::Mode mode) {
  auto& apply = *next_operation(message, v1::Operation::kApply).mutable_apply();
  apply.Clear();
  apply.set_region(region.data(), region.size());
  apply.set_mode(mode);
}

void add_export(cosim::Message& message, std::string_view region,
                std::initializer_list<const char*> quantities) {
  auto& op = *next_operation(message, v1::Operation::kExportRegion).mutable_export_region();
  op.Clear();
  op.set_region(region.data(), region.size());
  for (const char* q : quantities) op.add_quantities(q);
}

void add_advance(cosim::Message& message, double dt, double time) {
  auto& op = *next_operation(message, v1::Operation::kAdvance).mutable_advance();
  op.Clear();
  op.set_dt(dt);
  op.set_time(time);
}

void add_propose_dt(cosim::Message& message) {
  next_operation(message, v1::Operation::kProposeDt).mutable_propose_dt();
}

void add_inject(cosim::Message& message, std::string_view group) {
  auto& op = *next_operation(message, v1::Operation::kInject).mutable_inject();
  op.Clear();
  op.set_group(group.data(), group.size());
}

void add_remove(cosim::Message& message, std::string_view group, std::string_view left_region) {
  auto& op = *next_operation(message, v1::Operation::kRemove).mutable_remove();
  op.Clear();
  op.set_group(group.data(), group.size());
  op.set_left_region(left_region.data(), left_region.size());
}

v1::Region make_region(std::string_view name, v1::RegionKind kind, const WireBox& box,
                       std::initializer_list<const char*> quantities) {
  v1::Region region;
  region.set_name(std::string(name));
  region.set_kind(kind);
  for (int a = 0; a < 3; ++a) {
    region.mutable_box()->add_lo(box.lo[a]);
    region.mutable_box()->add_hi(box.hi[a]);
  }
  for (const char* q : quantities) region.add_quantities(q);
  return region;
}

void check_value_count(const cosim::Message& reply, std::string_view peer, std::string_view group,
                       std::string_view name, std::size_t got, std::size_t expected) {
  if (got != expected)
    throw Error("solver '" + std::string(peer) + "' step " +
                std::to_string(reply.header.envelope().step()) + ": array " + std::string(group) +
                "/" + std::string(name) + " holds " + std::to_string(got) + " values, expected " +
                std::to_string(expected));
}

void read_doubles(const cosim::Message& reply, std::string_view peer, std::string_view group,
                  std::string_view name, std::size_t values, std::vector<double>& out) {
  const auto view = cosim::view_array<double>(reply, group, name);
  check_value_count(reply, peer, group, name, view.values().size(), values);
  out.assign(view.values().begin(), view.values().end());
}

const v1::OperationResult& result_of(const cosim::Message& reply, std::string_view peer,
                                     int index) {
  if (!reply.header.has_exchange_result() || reply.header.exchange_result().results_size() <= index)
    throw Error("solver '" + std::string(peer) + "' answered an Exchange with '" +
                cosim::body_name(reply.header) + "' lacking result " + std::to_string(index));
  return reply.header.exchange_result().results(index);
}

}  // namespace mpfd::coupler
