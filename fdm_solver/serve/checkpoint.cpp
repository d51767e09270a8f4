#include "fdm_solver/serve/checkpoint.hpp"

#include <string>

#include "common/core/log.hpp"
#include "common/io/snapshot_writer.hpp"
#include "cosim/serving/checkpoint_files.hpp"
#include "fdm_solver/serve/checkpoint_file.hpp"

namespace mpfd::fdm {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& text) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, text, false);
}

}  // namespace

cosim::v1::CheckpointWritten write_checkpoint(const ServedZone& zone,
                                              const cosim::v1::Checkpoint& request) {
  const fs::path file =
      cosim::checkpoint_target(zone.output_dir, request.path(), zone.solver.steps());
  return cosim::write_checkpoint_atomically(
      file, zone.solver.steps(),
      [&](const fs::path& partial) { write_checkpoint_file(partial, zone); });
}

cosim::v1::Restored restore_checkpoint(ServedZone& zone, const cosim::v1::Restore& request) {
  const fs::path file = cosim::verified_restore_file(zone.output_dir, request.path());
  bool changed = false;  // once the solver holds the checkpoint's state
  try {
    CheckpointContents back = read_checkpoint_file(file, zone, request.step());
    io::SnapshotWriter::check_history(back.snapshot_history);  // before anything changes
    if (back.scene_text != zone.scene_text)
      Logger("fdm.serve")
          .warn("Restore: '", file.string(),
                "' was written for another scene text than this Setup's; its grid and materials "
                "match, so the state is restored");
    zone.solver.restore(back.state, back.clock.solver_time, back.clock.steps, back.outflow,
                        back.face_outflow,
                        std::move(back.tracker));  // checks before it changes anything
    changed = true;
    zone.start_time = back.clock.start_time;
    zone.output.resume(back.snapshot_history, zone.solver.state().grid);
  } catch (const cosim::ProtocolError&) {
    throw;
  } catch (const std::exception& error) {
    if (changed) throw cosim::half_restored("fdm_solver", file, error.what());
    refuse("Restore from '" + file.string() + "' failed: " + error.what());
  }
  cosim::v1::Restored restored;
  restored.set_step(static_cast<std::uint64_t>(zone.solver.steps()));
  restored.set_time(zone.time());
  restored.set_stable_dt(zone.solver.stable_dt());
  return restored;
}

}  // namespace mpfd::fdm
