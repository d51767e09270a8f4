#include "coupler/run/replay.hpp"

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/hub.hpp"
#include "cosim/player.hpp"

namespace mpfd::coupler {
namespace {

namespace v1 = cosim::v1;

std::string value_text(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

class Comparison {
 public:
  Comparison(const cosim::Message& expected, const cosim::Message& got, double tolerance)
      : expected_(expected), got_(got), tolerance_(tolerance) {}

  std::optional<std::string> run(std::uint64_t& values) {
    const std::string e = cosim::body_name(expected_.header), g = cosim::body_name(got_.header);
    if (e != g) return "reply '" + g + "', recorded '" + e + "'";
    if (auto d = results()) return d;
    return arrays(values);
  }

 private:
  bool differ(double a, double b) const {
    if (tolerance_ == 0) return std::memcmp(&a, &b, sizeof a) != 0;
    return std::abs(a - b) > tolerance_ * std::max(std::abs(a), std::abs(b));
  }

  std::optional<std::string> number(const std::string& field, double e, double g) const {
    if (!differ(e, g)) return std::nullopt;
    return field + ": recorded " + value_text(e) + ", live " + value_text(g);
  }

  std::optional<std::string> results() const {
    const auto& eh = expected_.header;
    const auto& gh = got_.header;
    if (eh.has_setup_ack())
      return number("SetupAck.stable_dt", eh.setup_ack().stable_dt(), gh.setup_ack().stable_dt());
    if (eh.has_activate_ack())
      return number("ActivateAck.stable_dt", eh.activate_ack().stable_dt(),
                    gh.activate_ack().stable_dt());
    if (eh.has_shutdown_ack() && eh.shutdown_ack().steps_done() != gh.shutdown_ack().steps_done())
      return "ShutdownAck.steps_done: recorded " + std::to_string(eh.shutdown_ack().steps_done()) +
             ", live " + std::to_string(gh.shutdown_ack().steps_done());
    if (eh.has_field_import_done()) {
      const auto& e = eh.field_import_done();
      const auto& g = gh.field_import_done();
      if (auto d = number("FieldImportDone.stable_dt", e.stable_dt(), g.stable_dt())) return d;
      if (e.totals_size() != g.totals_size())
        return "FieldImportDone.totals: " + std::to_string(g.totals_size()) + " values, recorded " +
               std::to_string(e.totals_size());
      for (int k = 0; k < e.totals_size(); ++k)
        if (auto d = number("FieldImportDone.totals[" + std::to_string(k) + "]", e.totals(k),
                            g.totals(k)))
          return d;
      return std::nullopt;
    }
    if (!eh.has_exchange_result()) return std::nullopt;
    const auto& e = eh.exchange_result().results();
    const auto& g = gh.exchange_result().results();
    if (e.size() != g.size())
      return "ExchangeResult: " + std::to_string(g.size()) + " results, recorded " +
             std::to_string(e.size());
    for (int i = 0; i < e.size(); ++i) {
      const std::string op = "operation " + std::to_string(i);
      if (e[i].result_case() != g[i].result_case()) return op + ": another kind of result";
      std::optional<std::string> d;
      if (e[i].has_advanced())
        d = number(op + " advanced.time", e[i].advanced().time(), g[i].advanced().time());
      if (e[i].has_proposed())
        d = number(op + " proposed.stable_dt", e[i].proposed().stable_dt(),
                   g[i].proposed().stable_dt());
      if (e[i].has_exported() && e[i].exported().count() != g[i].exported().count())
        d = op + " exported.count: recorded " + std::to_string(e[i].exported().count()) +
            ", live " + std::to_string(g[i].exported().count());
      if (e[i].has_removed() && e[i].removed().removed() != g[i].removed().removed())
        d = op + " removed: recorded " + std::to_string(e[i].removed().removed()) + ", live " +
            std::to_string(g[i].removed().removed());
      if (e[i].has_injected() && e[i].injected().injected() != g[i].injected().injected())
        d = op + " injected: recorded " + std::to_string(e[i].injected().injected()) + ", live " +
            std::to_string(g[i].injected().injected());
      if (d) return d;
    }
    return std::nullopt;
  }

  std::optional<std::string> arrays(std::uint64_t& values) const {
    for (const auto& e : expected_.header.arrays()) {
      const std::string field = e.group() + "/" + e.name();
      const v1::ArrayDescriptor* g = nullptr;
      for (const auto& candidate : got_.header.arrays())
        if (candidate.group() == e.group() && candidate.name() == e.name()) g = &candidate;
      if (g == nullptr) return "array " + field + " missing from the live reply";
      const auto& ef = expected_.frames.at(e.frame_index());
      const auto& gf = got_.frames.at(g->frame_index());
      if (g->dtype() != e.dtype() || ef.size() != gf.size())
        return "array " + field + ": live " + std::to_string(gf.size()) + " bytes of " +
               v1::DType_Name(g->dtype()) + ", recorded " + std::to_string(ef.size()) +
               " bytes of " + v1::DType_Name(e.dtype());
      if (e.dtype() != v1::DTYPE_F64) {
        if (std::memcmp(ef.data(), gf.data(), ef.size()) != 0)
          return "array " + field + ": bytes differ";
        continue;
      }
      const std::size_t n = ef.size() / sizeof(double);
      for (std::size_t i = 0; i < n; ++i) {
        double a = 0, b = 0;
        std::memcpy(&a, static_cast<const char*>(ef.data()) + i * sizeof a, sizeof a);
        std::memcpy(&b, static_cast<const char*>(gf.data()) + i * sizeof b, sizeof b);
        if (differ(a, b))
          return "array " + field + " index " + std::to_string(i) + ": recorded " + value_text(a) +
                 ", live " + value_text(b);
      }
      values += n;
    }
    return std::nullopt;
  }

  const cosim::Message& expected_;
  const cosim::Message& got_;
  double tolerance_;
};

}  // namespace

ReplayReport replay(const std::filesystem::path& recording, const ReplayOptions& options,
                    ServeFunction serve) {
  cosim::Player player(recording);
  std::vector<cosim::RecordedMessage> records;
  while (auto record = player.next())
    if (record->peer == options.solver) records.push_back(std::move(*record));
  std::string run_id;
  for (const auto& r : records)
    if (r.direction == v1::DIRECTION_SENT && r.message.header.has_hello_ack())
      run_id = r.message.header.hello_ack().run_id();
  if (run_id.empty())
    throw Error("recording '" + recording.string() + "' holds no session with solver '" +
                options.solver + "'");

  cosim::TransportOptions transport;
  transport.reply_timeout = std::chrono::milliseconds(std::llround(options.timeout_seconds * 1e3));
  zmq::context_t context;
  cosim::Hub hub(context, "inproc://mpfd-replay-" + std::to_string(::getpid()), transport);
  auto solver = start_thread(options.solver, serve, context, hub.endpoint());
  const std::vector<std::string> peers = {options.solver};
  ReplayReport report;
  try {
    hub.accept(peers, run_id);
    for (std::size_t i = 0; i < records.size(); ++i) {
      const auto& r = records[i];
      if (r.direction != v1::DIRECTION_SENT || r.message.header.has_hello_ack()) continue;
      cosim::Message request;
      request.header = r.message.header;
      for (const auto& frame : r.message.frames)
        request.frames.emplace_back(frame.data(), frame.size());
      if (request.header.has_setup())
        request.header.mutable_setup()->set_output_dir(options.out_dir.string());
      const auto& envelope = r.message.header.envelope();
      hub.set_clock(envelope.step(), envelope.sim_time());
      const std::string label = "step " + std::to_string(envelope.step()) + ", " +
                                cosim::body_name(r.message.header) + " (sequence " +
                                std::to_string(envelope.sequence()) + ")";
      hub.send(options.solver, std::move(request));
      ++report.requests;
      // Every message received before the next request answers this one: one
      // reply, or a stream of FieldChunks for a FieldExportRequest (proto §15).
      std::vector<std::size_t> replies;
      for (std::size_t j = i + 1; j < records.size() && records[j].direction != v1::DIRECTION_SENT;
           ++j)
        if (records[j].direction == v1::DIRECTION_RECEIVED) replies.push_back(j);
      if (replies.empty()) {  // the recording ends before the reply
        (void)hub.receive_from(options.solver);
        break;
      }
      for (std::size_t k = 0; k < replies.size() && !report.divergence; ++k) {
        const cosim::Message live = hub.receive_from(options.solver);
        if (auto d = Comparison(records[replies[k]].message, live, options.tolerance)
                         .run(report.values_compared))
          report.divergence =
              label + (replies.size() > 1 ? ", reply " + std::to_string(k + 1) : "") + ": " + *d;
      }
      if (report.divergence) break;
    }
  } catch (const std::exception& error) {
    solver->finish(std::chrono::milliseconds(0));
    throw Error("replay against solver '" + options.solver + "' failed: " + error.what());
  }
  if (report.divergence) {
    cosim::Message stop;
    stop.header.mutable_shutdown()->set_reason("replay diverged");
    try {
      hub.send(options.solver, std::move(stop));
      (void)hub.receive_from(options.solver);
    } catch (const std::exception&) {
      // The solver is stopping anyway; its idle timeout ends it.
    }
  }
  solver->finish(std::chrono::milliseconds(5000));
  return report;
}

}  // namespace mpfd::coupler
