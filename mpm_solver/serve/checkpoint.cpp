#include "mpm_solver/serve/checkpoint.hpp"

#include <chrono>
#include <string>

#include "common/core/log.hpp"
#include "common/io/snapshot_writer.hpp"
#include "cosim/serving/checkpoint_files.hpp"
#include "mpm_solver/serve/checkpoint_file.hpp"
#include "mpm_solver/serve/write_output.hpp"

namespace mpfd::mpm {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& text) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, text, false);
}

}  // namespace

cosim::v1::CheckpointWritten write_checkpoint(ServedZone& zone,
                                              const cosim::v1::Checkpoint& request) {
  if (zone.solver.queued_node_loads() > 0)
    refuse("Checkpoint: " + std::to_string(zone.solver.queued_node_loads()) +
           " ApplyRegion node values wait for the next Advance and are not part of a checkpoint; "
           "checkpoint after the Advance (proto/README.md §6: flush first)");
  const fs::path file =
      cosim::checkpoint_target(zone.output_dir, request.path(), zone.solver.steps());
  return cosim::write_checkpoint_atomically(
      file, zone.solver.steps(), [&](const fs::path& partial) {
        write_checkpoint_file(partial, zone, zone.solver.next_step_map_for_checkpoint());
      });
}

cosim::v1::Restored restore_checkpoint(ServedZone& zone, const cosim::v1::Restore& request) {
  const fs::path file = cosim::verified_restore_file(zone.output_dir, request.path());
  bool changed = false;  // once the solver holds the checkpoint's particles
  try {
    CheckpointContents back = read_checkpoint_file(file, zone, request.step());
    io::SnapshotWriter::check_history(back.snapshot_history);  // before anything changes
    if (back.scene_text != zone.scene_text)
      Logger("mpm.serve")
          .warn("Restore: '", file.string(),
                "' was written for another scene text than this Setup's; its grid and materials "
                "match, so the state is restored");
    zone.solver.restore(std::move(back.particles), back.injected_body_materials,
                        back.clock.solver_time, back.clock.steps, back.ledger,
                        back.particle_updates);  // checks before it changes anything
    changed = true;
    // The running zone adds its later injections to its map: so must this one.
    zone.next_step_map_seconds = 0.0;
    if (back.next_step_map_box) {
      const auto start = std::chrono::steady_clock::now();
      zone.solver.map_next_step((*back.next_step_map_box)[0], (*back.next_step_map_box)[1]);
      zone.next_step_map_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    zone.start_time = back.clock.start_time;
    zone.dormant = false;
    resume_snapshots(zone, back.snapshot_history);
  } catch (const cosim::ProtocolError&) {
    throw;
  } catch (const std::exception& error) {
    if (changed) throw cosim::half_restored("mpm_solver", file, error.what());
    refuse("Restore from '" + file.string() + "' failed: " + error.what());
  }
  cosim::v1::Restored restored;
  restored.set_step(static_cast<std::uint64_t>(zone.solver.steps()));
  restored.set_time(zone.time());
  restored.set_stable_dt(zone.solver.stable_dt());
  return restored;
}

}  // namespace mpfd::mpm
