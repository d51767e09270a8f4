#pragma once
// Reading a checkpoint's arrays with every check a restore needs: a size or a
// value that does not fit the running zone becomes a non-fatal
// ProtocolError{IO} naming the file, the array and both the expected and
// the found value, before anything is restored.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/io/hdf5_file.hpp"

namespace mpfd::cosim {

class CheckpointReader {
 public:
  explicit CheckpointReader(const std::filesystem::path& path);

  [[nodiscard]] const io::Hdf5File& file() const { return h5_; }
  /// Throws ProtocolError{IO, non-fatal}: "Restore: '<file>' <what>".
  [[noreturn]] void mismatch(const std::string& what) const;

  /// The float64 array `name`; it must have `count` values (`of`: what they are per).
  [[nodiscard]] std::vector<double> values(const std::string& name, std::size_t count,
                                           const std::string& of) const;
  /// The int64 array `name` as indices: `count` whole numbers in [0, limit)
  /// or equal to `special` (when given; `meaning` names the range).
  [[nodiscard]] std::vector<int> indices(const std::string& name, std::size_t count,
                                         const std::string& of, int limit,
                                         std::optional<int> special,
                                         const std::string& meaning) const;

 private:
  io::Hdf5File h5_;
};

}  // namespace mpfd::cosim
