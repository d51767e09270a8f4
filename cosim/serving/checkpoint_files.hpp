#pragma once
// Where a solver's Checkpoint writes and its Restore reads (proto/README.md §8),
// the same for every solver: the path resolved against Setup.output_dir, the
// file written as `<file>.partial` and renamed into place after its
// `<file>.sha256`, and the digest a Restore checks before it reads anything.
// What goes into the file is each solver's own (its checkpoint_file.hpp).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "cosim/message.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::cosim {

/// The file a Checkpoint{path} writes for a solver at step `steps`: an empty path
/// is `<output_dir>/checkpoints/`, a folder gets `checkpoint_NNNNNN.h5` (NNNNNN the
/// step) in it, a relative path lies under output_dir (without one, the working
/// folder). Throws a non-fatal ProtocolError{IO} for an empty path without output_dir.
[[nodiscard]] std::filesystem::path checkpoint_target(const std::filesystem::path& output_dir,
                                                      const std::string& requested,
                                                      std::int64_t steps);

/// Writes `file` through `write(partial)`, which must close what it writes, and
/// `<file>.sha256` (sha256sum's format) beside it; both under temporary names,
/// renamed into place, the checkpoint last, so a checkpoint in place is complete.
/// Returns CheckpointWritten{path, bytes, sha256, step = steps}. Any failure is a
/// non-fatal ProtocolError{IO} naming the file, and no partial file is left.
[[nodiscard]] v1::CheckpointWritten write_checkpoint_atomically(
    const std::filesystem::path& file, std::int64_t steps,
    const std::function<void(const std::filesystem::path& partial)>& write);

/// The checkpoint a Restore{path} names (a relative path under output_dir),
/// checked against the `<file>.sha256` beside it. Throws a non-fatal
/// ProtocolError{IO} for an empty path, a path that is not a file, a missing
/// sidecar or bytes whose digest is not the recorded one.
[[nodiscard]] std::filesystem::path verified_restore_file(const std::filesystem::path& output_dir,
                                                          const std::string& requested);

/// A Restore that failed after the solver's state was replaced: the zone holds
/// neither its Setup's state nor the checkpoint's, so the error is fatal and
/// `program` stops rather than serve a mixture.
[[nodiscard]] ProtocolError half_restored(const std::string& program,
                                          const std::filesystem::path& file,
                                          const std::string& what);

}  // namespace mpfd::cosim
