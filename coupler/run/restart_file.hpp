#pragma once
// The coupler's own part of a coupled checkpoint (coupler/run/coupler_checkpoint.hpp):
// named numbers, arrays and texts in an HDF5 file, "/<owner>/<name>" (a number
// is an attribute of the owner's group, an array or a text a dataset in it: the
// records grow with the run), read back with errors that name the file and the entry.

#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/io/hdf5_file.hpp"

namespace mpfd::coupler {

class RestartWriter {
 public:
  explicit RestartWriter(io::Hdf5File& file) : file_(file) {}

  /// Writes `value` as "/<owner>/<name>".
  void number(const std::string& owner, const std::string& name, double value);
  /// An empty optional as NaN.
  void optional_number(const std::string& owner, const std::string& name,
                       std::optional<double> value);
  void array(const std::string& owner, const std::string& name, std::span<const double> values);
  void text(const std::string& owner, const std::string& name, const std::string& value);
  /// Whether the solvers offered protocol feature `name` (RestartReader::expect_feature).
  void feature(const std::string& owner, const std::string& name, bool offered);

 private:
  void make_group(const std::string& owner);
  io::Hdf5File& file_;
};

class RestartReader {
 public:
  static constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

  explicit RestartReader(const io::Hdf5File& file) : file_(file) {}

  [[nodiscard]] double number(const std::string& owner, const std::string& name) const;
  /// NaN as an empty optional.
  [[nodiscard]] std::optional<double> optional_number(const std::string& owner,
                                                      const std::string& name) const;
  /// The array "/<owner>/<name>"; it must hold `count` values unless kAnyCount.
  [[nodiscard]] std::vector<double> array(const std::string& owner, const std::string& name,
                                          std::size_t count = kAnyCount) const;
  [[nodiscard]] std::string text(const std::string& owner, const std::string& name) const;
  /// The text "/<owner>/<name>" parsed as JSON.
  [[nodiscard]] nlohmann::json json(const std::string& owner, const std::string& name) const;
  /// Refuses unless the solvers that wrote it offered feature `name` as these do (`offered`):
  /// it decides how the run books what it carries.
  void expect_feature(const std::string& owner, const std::string& name, bool offered) const;
  /// Throws mpfd::Error "restart: '<file>' <what>".
  [[noreturn]] void refuse(const std::string& what) const;

 private:
  const io::Hdf5File& file_;
};

}  // namespace mpfd::coupler
