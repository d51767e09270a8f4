#pragma once
// WriteOutput of protocol v1 (proto/README.md §8): cell snapshots in the
// layout of docs/output.md (snapshots/snapshot_NNNNNN.h5 and cells.xmf)
// under the Setup's output_dir, written by common/io's SnapshotWriter; a
// multi-material zone's tracers (position, material, volume) as its particles
// (particles.xmf), as `fdm_solver run` writes them.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/io/snapshot_writer.hpp"
#include "cosim/message.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/snapshot_fields.hpp"

namespace mpfd::fdm {

class SnapshotOutput {
 public:
  /// `out_dir` may be empty (then WriteOutput is an error); the scene's
  /// output.fields are the default set.
  SnapshotOutput(std::filesystem::path out_dir, const config::Scene& scene);

  /// Writes one snapshot of `fields` (docs/output.md names; none: the
  /// default set) at `time`. `request.directory` must be empty or out_dir;
  /// `basename` is not used (docs/output.md fixes the names). The files:
  /// the snapshot, cells.xmf and, with tracers, particles.xmf. Throws
  /// cosim::ProtocolError{IO} naming the folder, field or the writer's failure.
  cosim::v1::OutputWritten write(const EulerSolver& solver, double time,
                                 const cosim::v1::WriteOutput& request);

  /// The series written so far (io::SnapshotWriter::history), "[]" before the first.
  [[nodiscard]] std::string history() const;
  /// Continues a checkpoint's series `history` in out_dir (io::SnapshotWriter::resume), so
  /// that a restored run numbers its snapshots on (from 0 again for a checkpoint taken
  /// before the first). Nothing without an out_dir. Throws mpfd::Error.
  void resume(const std::string& history, const grid::UniformGrid& grid);

 private:
  std::filesystem::path out_dir_;
  config::Scene scene_;
  std::vector<std::string> default_fields_;
  std::optional<io::SnapshotWriter> writer_;  // made at the first write: it creates the folder
};

}  // namespace mpfd::fdm
