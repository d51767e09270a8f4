#include "coupler/run/wire.hpp"

#include "common/core/error.hpp"

namespace mpfd::coupler {

v1::Exchange& exchange_of(cosim::Message& message) {
  return *message.header.mutable_exchange();
}

void add_apply(cosim::Message& message, std::string_view region, v1::ApplyRegion::Mode mode) {
  auto& apply = *exchange_of(message).add_operations()->mutable_apply();
  apply.set_region(std::string(region));
  apply.set_mode(mode);
}

void add_export(cosim::Message& message, std::string_view region,
                std::initializer_list<const char*> quantities) {
  auto& op = *exchange_of(message).add_operations()->mutable_export_region();
  op.set_region(std::string(region));
  for (const char* q : quantities) op.add_quantities(q);
}

void add_advance(cosim::Message& message, double dt, double time) {
  auto& op = *exchange_of(message).add_operations()->mutable_advance();
  op.set_dt(dt);
  op.set_time(time);
}

void add_propose_dt(cosim::Message& message) {
  exchange_of(message).add_operations()->mutable_propose_dt();
}

void add_inject(cosim::Message& message, std::string_view group) {
  exchange_of(message).add_operations()->mutable_inject()->set_group(std::string(group));
}

void add_remove(cosim::Message& message, std::string_view group, std::string_view left_region) {
  auto& op = *exchange_of(message).add_operations()->mutable_remove();
  op.set_group(std::string(group));
  op.set_left_region(std::string(left_region));
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

std::vector<double> read_doubles(const cosim::Message& reply, std::string_view peer,
                                 std::string_view group, std::string_view name,
                                 std::size_t values) {
  const auto view = cosim::view_array<double>(reply, group, name);
  if (view.values().size() != values)
    throw Error("solver '" + std::string(peer) + "' step " +
                std::to_string(reply.header.envelope().step()) + ": array " + std::string(group) +
                "/" + std::string(name) + " holds " + std::to_string(view.values().size()) +
                " values, expected " + std::to_string(values));
  return {view.values().begin(), view.values().end()};
}

const v1::OperationResult& result_of(const cosim::Message& reply, std::string_view peer,
                                     int index) {
  if (!reply.header.has_exchange_result() || reply.header.exchange_result().results_size() <= index)
    throw Error("solver '" + std::string(peer) + "' answered an Exchange with '" +
                cosim::body_name(reply.header) + "' lacking result " + std::to_string(index));
  return reply.header.exchange_result().results(index);
}

}  // namespace mpfd::coupler
