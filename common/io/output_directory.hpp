#pragma once
// The run's output folder, and writing files so that a crash never leaves a
// half-written one in it: every file is written beside its final name and
// renamed into place.

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

namespace mpfd::io {

/// Version of the layout documented in docs/output.md. Bump it on any change
/// that a reader of the files would notice.
inline constexpr int kOutputFormatVersion = 1;

/// Creates `dir` (and its parents). Refuses, with an error naming the folder,
/// to reuse a folder that already holds a run (a summary.json) unless
/// `overwrite` is set, so an earlier run's results are never lost by mistake.
void prepare_output_directory(const std::filesystem::path& dir, bool overwrite);

/// `path` relative to the run folder `dir` when it lies in it (a relative `path`
/// counts from the working folder), else `path` as given: what a record names stays
/// valid when the folder moves.
[[nodiscard]] std::string path_in_run(const std::string& path, const std::filesystem::path& dir);

/// Writes `file` through `write` into `file`.tmp, then renames it into place.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

/// Same, for writers that need a path (HDF5).
void write_path_atomically(const std::filesystem::path& file,
                           const std::function<void(const std::filesystem::path&)>& write);

}  // namespace mpfd::io
