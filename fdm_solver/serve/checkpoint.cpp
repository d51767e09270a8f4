#include "fdm_solver/serve/checkpoint.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include "common/core/log.hpp"
#include "common/io/snapshot_writer.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "cosim/serving/sha256.hpp"
#include "fdm_solver/serve/checkpoint_file.hpp"

namespace mpfd::fdm {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& text) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, text, false);
}

/// `requested` resolved against Setup.output_dir; an empty one is output_dir.
fs::path resolve(const ServedZone& zone, const std::string& requested,
                 const std::string& operation) {
  if (requested.empty()) {
    if (zone.output_dir.empty()) refuse(operation + ": no path given and Setup gave no output_dir");
    return zone.output_dir / "checkpoints";
  }
  const fs::path path(requested);
  return path.is_relative() && !zone.output_dir.empty() ? zone.output_dir / path : path;
}

fs::path sidecar_of(const fs::path& file) {
  fs::path sidecar = file;
  sidecar += ".sha256";
  return sidecar;
}

fs::path partial_of(const fs::path& file) {
  fs::path partial = file;
  partial += ".partial";
  return partial;
}

/// `file`'s digest, as `sha256sum -c` reads it.
void write_sidecar(const fs::path& sidecar, const std::string& digest, const fs::path& file) {
  std::ofstream out(sidecar, std::ios::trunc);
  out << digest << "  " << file.filename().string() << '\n';
  out.close();
  if (!out) throw Error("cannot write '" + sidecar.string() + "'");
}

/// Refuses a file whose SHA-256 is not the one Checkpoint recorded beside it.
void verify_digest(const fs::path& file) {
  const fs::path sidecar = sidecar_of(file);
  std::ifstream in(sidecar);
  std::string recorded;
  if (!(in >> recorded))
    refuse("Restore: '" + file.string() + "' has no readable '" + sidecar.string() +
           "' beside it (Checkpoint writes one) to check it against");
  const std::string actual = cosim::sha256_hex_of_file(file);
  if (actual != recorded)
    refuse("Restore: '" + file.string() + "' (" + std::to_string(fs::file_size(file)) +
           " bytes) has SHA-256 " + actual + "; '" + sidecar.string() + "' records " + recorded +
           ": the file is truncated or corrupt, or not the one Checkpoint wrote");
}

}  // namespace

cosim::v1::CheckpointWritten write_checkpoint(const ServedZone& zone,
                                              const cosim::v1::Checkpoint& request) {
  fs::path file = resolve(zone, request.path(), "Checkpoint");
  if (request.path().empty() || fs::is_directory(file) || file.filename().empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "checkpoint_%06lld.h5",
                  static_cast<long long>(zone.solver.steps()));
    file /= name;
  }
  cosim::v1::CheckpointWritten written;
  const fs::path sidecar = sidecar_of(file);
  const fs::path partial = partial_of(file), partial_sidecar = partial_of(sidecar);
  try {
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    try {
      write_checkpoint_file(partial, zone);  // closed on return: then complete
      written.set_bytes(static_cast<std::uint64_t>(fs::file_size(partial)));
      written.set_sha256(cosim::sha256_hex_of_file(partial));
      written.set_step(static_cast<std::uint64_t>(zone.solver.steps()));
      write_sidecar(partial_sidecar, written.sha256(), file);
      fs::rename(partial_sidecar, sidecar);
      fs::rename(partial, file);  // last: a checkpoint in place is complete
    } catch (...) {
      std::error_code ignored;
      fs::remove(partial, ignored);  // no partial checkpoint is left behind
      fs::remove(partial_sidecar, ignored);
      throw;
    }
  } catch (const std::exception& error) {
    refuse("Checkpoint to '" + file.string() + "' failed: " + error.what());
  }
  written.set_path(file.string());
  return written;
}

cosim::v1::Restored restore_checkpoint(ServedZone& zone, const cosim::v1::Restore& request) {
  if (request.path().empty()) refuse("Restore: no path given");
  const fs::path file = resolve(zone, request.path(), "Restore");
  if (!fs::is_regular_file(file)) refuse("Restore: '" + file.string() + "' is not a file");
  bool changed = false;  // once the solver holds the checkpoint's state
  try {
    verify_digest(file);
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
    if (changed) throw cosim::half_restored("fdm_solver", file.string(), error.what());
    refuse("Restore from '" + file.string() + "' failed: " + error.what());
  }
  cosim::v1::Restored restored;
  restored.set_step(static_cast<std::uint64_t>(zone.solver.steps()));
  restored.set_time(zone.time());
  restored.set_stable_dt(zone.solver.stable_dt());
  return restored;
}

}  // namespace mpfd::fdm
