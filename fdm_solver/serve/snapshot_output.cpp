#include "fdm_solver/serve/snapshot_output.hpp"

#include "common/core/error.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/primitive_fields.hpp"
#include "fdm_solver/snapshot_fields.hpp"

namespace mpfd::fdm {
namespace {

/// The field check of snapshot_fields.hpp, as a protocol error.
void check_field(const std::string& name, const std::string& source) {
  try {
    check_field_name(name);
  } catch (const Error& error) {
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, source + " " + error.what());
  }
}

}  // namespace

SnapshotOutput::SnapshotOutput(std::filesystem::path out_dir, const config::Scene& scene)
    : out_dir_(std::move(out_dir)), scene_(scene) {
  for (const auto field : scene.output.fields) {
    default_fields_.push_back(field_name(field));
    check_field(default_fields_.back(), "scene output.fields:");
  }
}

cosim::v1::OutputWritten SnapshotOutput::write(const EulerSolver& solver, double time,
                                               const cosim::v1::WriteOutput& request) {
  if (out_dir_.empty())
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, "WriteOutput: Setup gave no output_dir");
  if (!request.directory().empty() && std::filesystem::path(request.directory()) != out_dir_)
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO,
                               "WriteOutput directory '" + request.directory() +
                                   "' differs from Setup's output_dir '" + out_dir_.string() +
                                   "'; fdm_solver writes one");
  for (const auto& name : request.fields()) check_field(name, "WriteOutput");
  // Made per output, not kept: 7 values a cell a coupled run would hold between outputs.
  PrimitiveFields primitives;
  primitives.compute(solver.state(), solver.materials());
  const std::vector<std::string> names =
      request.fields().empty()
          ? default_fields_
          : std::vector<std::string>(request.fields().begin(), request.fields().end());
  const SnapshotFields fields(solver, names);
  const std::vector<io::FieldView> views = fields.views(names, scene_, solver, primitives);
  // The tracers as particles, as `fdm_solver run` writes them (docs/output.md).
  std::vector<io::FieldView> tracer_views;
  std::vector<double> tracer_material;  // the tracers' material index as numbers
  if (const auto* tracker = solver.tracker()) {
    const TracerSet& t = tracker->tracers();
    tracer_material.assign(t.material.begin(), t.material.end());
    tracer_views = {{"position", "m", {t.position[0], t.position[1], t.position[2]}},
                    {"material", "", {tracer_material}},
                    {"volume", "m^3", {t.volume}}};
  }
  cosim::v1::OutputWritten written;
  try {
    if (!writer_) writer_.emplace(out_dir_, solver.state().grid);
    written.add_files(writer_->write(solver.steps(), time, views, tracer_views).string());
  } catch (const std::exception& error) {
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, "WriteOutput into '" + out_dir_.string() +
                                                             "' failed: " + error.what());
  }
  written.add_files((out_dir_ / "cells.xmf").string());
  if (!tracer_views.empty()) written.add_files((out_dir_ / "particles.xmf").string());
  return written;
}

std::string SnapshotOutput::history() const {
  return writer_ ? writer_->history() : "[]";
}

void SnapshotOutput::resume(const std::string& history, const grid::UniformGrid& grid) {
  if (out_dir_.empty() || (io::SnapshotWriter::empty_history(history) && !writer_)) return;
  if (!writer_) writer_.emplace(out_dir_, grid);
  writer_->resume(history);
}

}  // namespace mpfd::fdm
