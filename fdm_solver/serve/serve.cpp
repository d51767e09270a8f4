#include "fdm_solver/serve/serve.hpp"

#include <unistd.h>

#include <memory>
#include <string_view>

#include "common/core/log.hpp"
#include "cosim/participant.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "cosim/serving/replies.hpp"
#include "fdm_solver/serve/checkpoint.hpp"
#include "fdm_solver/serve/exchange.hpp"
#include "fdm_solver/serve/field_export.hpp"
#include "fdm_solver/serve/field_import.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {
namespace {

using Clock = std::chrono::steady_clock;

cosim::v1::Hello hello(const ServeOptions& options) {
  cosim::v1::Hello hello;
  hello.set_role(cosim::v1::ROLE_EULER_SOLVER);
  hello.set_software("mpfd fdm_solver");
  hello.set_min_major(cosim::protocol_major);
  hello.set_max_major(cosim::protocol_major);
  for (const char* capability : {"cell_regions", "gauges", "write_output", "checkpoint"})
    hello.add_capabilities(capability);
  if (!options.offer_v1_0_only)  // v1.1 (proto/README.md §14) and v1.2 (§15)
    for (const char* capability : {"face_crossing", "boundary_outflow", "field_chunks",
                                   "tracer_regions", "material_fields", "material_import"}) {
      const std::string_view name(capability);
      if ((name == "boundary_outflow" && !options.offer_boundary_outflow) ||
          (name == "material_import" && !options.offer_material_import))
        continue;
      hello.add_capabilities(capability);
    }
  hello.set_pid(static_cast<std::uint32_t>(::getpid()));
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) == 0) hello.set_host(host);
  return hello;
}

/// The replies to any request but Shutdown (and Ping, which Participant
/// answers): one, or the FieldChunks of a FieldExportRequest.
cosim::Replies answer(std::unique_ptr<ServedZone>& zone, const cosim::Message& request) {
  const auto& header = request.header;
  const std::string_view body = cosim::body_name(header);  // only for messages
  const bool fields =
      header.has_field_export() || header.has_field_chunk() || header.has_field_import_commit();
  if (!header.has_setup() && !header.has_exchange() && !header.has_write_output() &&
      !header.has_checkpoint() && !header.has_restore() && !header.has_activate() && !fields)
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNEXPECTED,
                               "'" + std::string(body) + "' is not a request to a solver");
  if (header.has_setup() == (zone != nullptr))
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_UNEXPECTED,
        zone ? "a second Setup" : "'" + std::string(body) + "' before Setup");
  if (header.has_field_export()) return export_fields(*zone, request);
  cosim::Message reply;
  if (header.has_field_chunk()) {
    reply = add_import_chunk(*zone, request);
  } else if (header.has_field_import_commit()) {
    reply = commit_import(*zone, request);
    Logger("fdm.serve")
        .info("import '", header.field_import_commit().transfer_id(),
              "' committed at t = ", zone->time(), " s, stable dt ",
              reply.header.field_import_done().stable_dt(), " s");
  } else if (header.has_setup()) {
    zone = set_up_zone(header.setup());
    *reply.header.mutable_setup_ack() = setup_ack(header.setup(), *zone);
    Logger("fdm.serve")
        .info("scene '", zone->scene.name, "' set up: ", zone->regions.size(),
              " regions, stable dt ", reply.header.setup_ack().stable_dt(), " s");
  } else if (header.has_exchange()) {
    reply = run_exchange(*zone, request);
  } else if (header.has_write_output()) {
    *reply.header.mutable_output_written() =
        zone->output.write(zone->solver, zone->time(), header.write_output());
  } else if (header.has_checkpoint()) {
    *reply.header.mutable_checkpoint_written() = write_checkpoint(*zone, header.checkpoint());
  } else if (header.has_restore()) {
    *reply.header.mutable_restored() = restore_checkpoint(*zone, header.restore());
  } else {
    reply.header.mutable_activate_ack()->set_stable_dt(zone->solver.stable_dt());
  }
  return reply;
}

/// Answers `request` with Error. A fatal one is sent best effort (the coupler
/// may be gone) and then thrown, naming the code and the coupler.
void report_error(cosim::Participant& participant, const cosim::Message& request,
                  cosim::v1::ErrorCode code, const std::string& text, bool fatal) {
  if (fatal) {
    participant.send_error(&request, code, text);
    throw Error("fdm_solver serve: stopped after reporting " + cosim::v1::ErrorCode_Name(code) +
                " to the coupler at " + participant.coupler_endpoint() + ": " + text);
  }
  cosim::Message reply;
  auto& error = *reply.header.mutable_error();
  error.set_code(code);
  error.set_message(text);
  error.set_fatal(false);
  participant.reply(request, std::move(reply));
}

}  // namespace

void serve(zmq::context_t& context, const ServeOptions& options) {
  const Logger logger("fdm.serve");
  const auto start = Clock::now();
  cosim::TransportOptions transport;
  transport.idle_timeout = options.idle_timeout;
  cosim::Participant participant(context, options.endpoint, options.name, transport);
  const cosim::v1::HelloAck session = participant.connect(hello(options));
  if (session.major() != cosim::protocol_major) {
    const std::string text = "the coupler chose protocol v" + std::to_string(session.major()) +
                             "; solver '" + options.name + "' speaks v" +
                             std::to_string(cosim::protocol_major);
    participant.send_error(nullptr, cosim::v1::ERROR_CODE_VERSION_MISMATCH, text);
    throw Error("fdm_solver serve: " + text + " (coupler at " + options.endpoint + ")");
  }
  logger.info("'", options.name, "' connected to ", options.endpoint, ", run ", session.run_id());

  std::unique_ptr<ServedZone> zone;
  while (true) {
    const cosim::Message request = participant.receive();
    if (request.header.has_shutdown()) {
      const auto steps = zone ? static_cast<std::uint64_t>(zone->solver.steps()) : 0U;
      cosim::Message reply;
      reply.header.mutable_shutdown_ack()->set_steps_done(steps);
      reply.header.mutable_shutdown_ack()->set_wall_seconds(
          std::chrono::duration<double>(Clock::now() - start).count());
      participant.reply(request, std::move(reply));
      logger.info("shut down (", request.header.shutdown().reason(), ") after ", steps, " steps");
      return;
    }
    try {
      for (auto replies = answer(zone, request); auto reply = replies.next();)
        participant.reply(request, std::move(*reply));
    } catch (const cosim::ProtocolError& error) {
      report_error(participant, request, error.code(), error.what(), error.fatal());
    } catch (const std::exception& error) {
      report_error(participant, request, cosim::v1::ERROR_CODE_INTERNAL, error.what(), true);
    }
  }
}

}  // namespace mpfd::fdm
