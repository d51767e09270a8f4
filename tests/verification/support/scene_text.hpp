#pragma once
// Scene text for verification runs: a scene file read whole, and variants of
// it made by replacing a key's text (a grid size, a method, an end time).

#include <filesystem>
#include <string>

namespace mpfd::verification {

/// The whole of `file`; throws mpfd::Error naming it when it cannot be read.
[[nodiscard]] std::string read_text(const std::filesystem::path& file);

/// `text` with its first `from` replaced by `to`; throws mpfd::Error naming
/// `from` when `text` lacks it (the scene changed under the test).
[[nodiscard]] std::string replaced(std::string text, const std::string& from,
                                   const std::string& to);

/// `text` with every `from` replaced by `to`; throws like replaced() when
/// there is none.
[[nodiscard]] std::string replaced_all(std::string text, const std::string& from,
                                       const std::string& to);

}  // namespace mpfd::verification
