#pragma once
// SHA-256 (FIPS 180-4) of a file, for CheckpointWritten.sha256
// (proto/README.md §8). Self-contained: no crypto library is a dependency.

#include <filesystem>
#include <string>
#include <string_view>

namespace mpfd::cosim {

/// Lower-case hex digest of `bytes`.
[[nodiscard]] std::string sha256_hex(std::string_view bytes);
/// Lower-case hex digest of the file's contents; throws mpfd::Error naming the file.
[[nodiscard]] std::string sha256_hex_of_file(const std::filesystem::path& path);

}  // namespace mpfd::cosim
