#pragma once
// A thin RAII layer over the HDF5 C API: just what MPFD's output needs
// (float64/int64 datasets with a units attribute, scalar and string
// attributes, groups) plus reading back for tests and restarts. Every failure
// throws mpfd::Error naming the file and the object.

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace mpfd::io {

/// Owns one hid_t and closes it with the matching H5?close.
class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept;
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle();
  [[nodiscard]] hid_t get() const { return id_; }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// A dataset read back: values in C order and the shape.
struct DatasetData {
  std::vector<double> values;
  std::vector<std::size_t> shape;
};

class Hdf5File {
 public:
  enum class Mode { create, read };
  Hdf5File(const std::filesystem::path& path, Mode mode);

  /// Creates every missing group on the path ("/cells" or "/gauges/g1").
  void create_group(const std::string& path);
  void write_dataset(const std::string& path, std::span<const double> values,
                     const std::vector<std::size_t>& shape, const std::string& units);
  void write_dataset(const std::string& path, std::span<const std::int64_t> values,
                     const std::vector<std::size_t>& shape);
  void write_attribute(const std::string& object, const std::string& name, double value);
  void write_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void write_attribute(const std::string& object, const std::string& name,
                       std::span<const double> values);
  void write_attribute(const std::string& object, const std::string& name,
                       const std::string& value);

  /// A text of any length as a scalar string dataset (an attribute holds at most 64 KiB).
  void write_text(const std::string& path, const std::string& text);

  [[nodiscard]] bool exists(const std::string& path) const;
  [[nodiscard]] DatasetData read_dataset(const std::string& path) const;
  [[nodiscard]] double read_attribute(const std::string& object, const std::string& name) const;
  [[nodiscard]] std::string read_string_attribute(const std::string& object,
                                                  const std::string& name) const;
  /// The text of write_text().
  [[nodiscard]] std::string read_text(const std::string& path) const;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(const std::string& what, const std::string& object) const;
  void write_attribute_raw(const std::string& object, const std::string& name, hid_t file_type,
                           hid_t memory_type, const void* data, hsize_t count);

  std::filesystem::path path_;
  Hdf5Handle file_;
};

}  // namespace mpfd::io
