#include "cosim/serving/checkpoint_files.hpp"

#include <cstdio>
#include <fstream>

#include "cosim/serving/sha256.hpp"

namespace mpfd::cosim {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& text) {
  throw ProtocolError(v1::ERROR_CODE_IO, text, false);
}

fs::path resolve(const fs::path& output_dir, const std::string& requested) {
  const fs::path path(requested);
  return path.is_relative() && !output_dir.empty() ? output_dir / path : path;
}

fs::path with_suffix(const fs::path& file, const char* suffix) {
  fs::path named = file;
  named += suffix;
  return named;
}

/// `file`'s digest, as `sha256sum -c` reads it.
void write_sidecar(const fs::path& sidecar, const std::string& digest, const fs::path& file) {
  std::ofstream out(sidecar, std::ios::trunc);
  out << digest << "  " << file.filename().string() << '\n';
  out.close();
  if (!out) throw Error("cannot write '" + sidecar.string() + "'");
}

}  // namespace

fs::path checkpoint_target(const fs::path& output_dir, const std::string& requested,
                           std::int64_t steps) {
  if (requested.empty() && output_dir.empty())
    refuse("Checkpoint: no path given and Setup gave no output_dir");
  fs::path file = requested.empty() ? output_dir / "checkpoints" : resolve(output_dir, requested);
  if (requested.empty() || fs::is_directory(file) || file.filename().empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "checkpoint_%06lld.h5", static_cast<long long>(steps));
    file /= name;
  }
  return file;
}

v1::CheckpointWritten write_checkpoint_atomically(
    const fs::path& file, std::int64_t steps, const std::function<void(const fs::path&)>& write) {
  v1::CheckpointWritten written;
  const fs::path sidecar = with_suffix(file, ".sha256");
  const fs::path partial = with_suffix(file, ".partial");
  const fs::path partial_sidecar = with_suffix(sidecar, ".partial");
  try {
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    try {
      write(partial);
      written.set_bytes(static_cast<std::uint64_t>(fs::file_size(partial)));
      written.set_sha256(sha256_hex_of_file(partial));
      written.set_step(static_cast<std::uint64_t>(steps));
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

fs::path verified_restore_file(const fs::path& output_dir, const std::string& requested) {
  if (requested.empty()) refuse("Restore: no path given");
  const fs::path file = resolve(output_dir, requested);
  if (!fs::is_regular_file(file)) refuse("Restore: '" + file.string() + "' is not a file");
  const fs::path sidecar = with_suffix(file, ".sha256");
  std::ifstream in(sidecar);
  std::string recorded;
  if (!(in >> recorded))
    refuse("Restore: '" + file.string() + "' has no readable '" + sidecar.string() +
           "' beside it (Checkpoint writes one) to check it against");
  std::string actual;
  try {
    actual = sha256_hex_of_file(file);
  } catch (const std::exception& error) {
    refuse("Restore from '" + file.string() + "' failed: " + error.what());
  }
  std::error_code unread;
  if (actual != recorded)
    refuse("Restore: '" + file.string() + "' (" + std::to_string(fs::file_size(file, unread)) +
           " bytes) has SHA-256 " + actual + "; '" + sidecar.string() + "' records " + recorded +
           ": the file is truncated or corrupt, or not the one Checkpoint wrote");
  return file;
}

ProtocolError half_restored(const std::string& program, const fs::path& file,
                            const std::string& what) {
  return {v1::ERROR_CODE_IO,
          "Restore from '" + file.string() + "' failed after the state was replaced: " + what +
              "; the zone is neither its Setup's nor the checkpoint's, so " + program + " stops",
          true};
}

}  // namespace mpfd::cosim
