#pragma once
// A solver stub for transport tests: answers Exchange by returning, for each
// ExportRegion, the last array applied to that region doubled, and proposes a
// fixed dt; answers Shutdown and stops. Runs on its own thread.

#include <exception>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/participant.hpp"

namespace mpfd::cosim::testing {

inline void serve_echo(Participant& participant) {
  std::map<std::string, std::vector<double>> regions;
  while (true) {
    Message request = participant.receive();
    Message reply;
    if (request.header.has_shutdown()) {
      reply.header.mutable_shutdown_ack();
      participant.reply(request, std::move(reply));
      return;
    }
    auto& results = *reply.header.mutable_exchange_result();
    for (const auto& operation : request.header.exchange().operations()) {
      auto& result = *results.add_results();
      if (operation.has_apply()) {
        const auto view = view_array<double>(request, operation.apply().region(), "rho");
        regions[operation.apply().region()].assign(view.values().begin(), view.values().end());
        result.set_applied(true);
      } else if (operation.has_export_region()) {
        const auto& region = operation.export_region().region();
        std::vector<double> values = regions[region];
        for (auto& value : values) value *= 2.0;
        result.mutable_exported()->set_region(region);
        result.mutable_exported()->set_count(values.size());
        add_array(reply, {region, "rho", {}, "kg/m^3"}, std::move(values));
      } else if (operation.has_propose_dt()) {
        result.mutable_proposed()->set_stable_dt(participant.name() == "fdm" ? 2e-7 : 1e-7);
      }
    }
    participant.reply(request, std::move(reply));
  }
}

/// Runs `body` on a thread, keeping any exception for the test to rethrow.
class SolverThread {
 public:
  template <typename Body>
  explicit SolverThread(Body body)
      : thread_([this, body]() mutable {
          try {
            body();
          } catch (...) {
            error_ = std::current_exception();
          }
        }) {}
  ~SolverThread() {
    if (thread_.joinable()) thread_.join();
  }
  void join_and_rethrow() {
    thread_.join();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace mpfd::cosim::testing
