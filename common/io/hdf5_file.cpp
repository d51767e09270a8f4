#include "common/io/hdf5_file.hpp"

#include <utility>

#include "common/core/error.hpp"

namespace mpfd::io {
namespace {

/// HDF5 prints its own error stack to stderr by default; our exceptions say
/// enough, so switch that off once.
void silence_hdf5_error_stack() {
  static const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

std::vector<hsize_t> to_hsize(const std::vector<std::size_t>& shape) {
  return {shape.begin(), shape.end()};
}

std::size_t element_count(const std::vector<std::size_t>& shape) {
  std::size_t n = 1;
  for (const std::size_t s : shape) n *= s;
  return n;
}

}  // namespace

Hdf5Handle::Hdf5Handle(Hdf5Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0 && closer_ != nullptr) closer_(id_);
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

Hdf5Handle::~Hdf5Handle() {
  if (id_ >= 0 && closer_ != nullptr) closer_(id_);
}

Hdf5File::Hdf5File(const std::filesystem::path& path, Mode mode) : path_(path) {
  silence_hdf5_error_stack();
  const hid_t id = mode == Mode::create
                       ? H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
                       : H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) fail(mode == Mode::create ? "cannot create" : "cannot open", "/");
  file_ = Hdf5Handle(id, H5Fclose);
}

void Hdf5File::fail(const std::string& what, const std::string& object) const {
  throw Error("HDF5 file " + path_.string() + ": " + what + " '" + object + "'");
}

void Hdf5File::create_group(const std::string& path) {
  std::size_t pos = 0;
  while (pos != std::string::npos) {
    pos = path.find('/', pos + 1);
    const std::string prefix = path.substr(0, pos);
    if (prefix.empty() || prefix == "/" || exists(prefix)) continue;
    const hid_t g = H5Gcreate2(file_.get(), prefix.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (g < 0) fail("cannot create group", prefix);
    H5Gclose(g);
  }
}

void Hdf5File::write_dataset(const std::string& path, std::span<const double> values,
                             const std::vector<std::size_t>& shape, const std::string& units) {
  MPFD_ASSERT(element_count(shape) == values.size(), "dataset shape does not match its data");
  const auto dims = to_hsize(shape);
  const Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                         H5Sclose);
  const Hdf5Handle set(H5Dcreate2(file_.get(), path.c_str(), H5T_IEEE_F64LE, space.get(),
                                  H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Dclose);
  if (set.get() < 0) fail("cannot create dataset", path);
  if (H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail("cannot write dataset", path);
  write_attribute(path, "units", units);
}

void Hdf5File::write_dataset(const std::string& path, std::span<const std::int64_t> values,
                             const std::vector<std::size_t>& shape) {
  MPFD_ASSERT(element_count(shape) == values.size(), "dataset shape does not match its data");
  const auto dims = to_hsize(shape);
  const Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                         H5Sclose);
  const Hdf5Handle set(H5Dcreate2(file_.get(), path.c_str(), H5T_STD_I64LE, space.get(),
                                  H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Dclose);
  if (set.get() < 0) fail("cannot create dataset", path);
  if (H5Dwrite(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail("cannot write dataset", path);
}

void Hdf5File::write_attribute_raw(const std::string& object, const std::string& name,
                                   hid_t file_type, hid_t memory_type, const void* data,
                                   hsize_t count) {
  const Hdf5Handle space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr),
                         H5Sclose);
  const Hdf5Handle attr(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), file_type,
                                          space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        H5Aclose);
  if (attr.get() < 0) fail("cannot create attribute " + name + " on", object);
  if (H5Awrite(attr.get(), memory_type, data) < 0)
    fail("cannot write attribute " + name + " on", object);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name, double value) {
  write_attribute_raw(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, 0);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               std::int64_t value) {
  write_attribute_raw(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value, 0);
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               std::span<const double> values) {
  write_attribute_raw(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(),
                      values.size());
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               const std::string& value) {
  const Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.empty() ? 1 : value.size());
  write_attribute_raw(object, name, type.get(), type.get(), value.empty() ? "" : value.c_str(), 0);
}

void Hdf5File::write_text(const std::string& path, const std::string& text) {
  const Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), text.empty() ? 1 : text.size());
  const Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Hdf5Handle set(H5Dcreate2(file_.get(), path.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                  H5P_DEFAULT, H5P_DEFAULT),
                       H5Dclose);
  if (set.get() < 0) fail("cannot create text dataset", path);
  if (H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
               text.empty() ? "" : text.c_str()) < 0)
    fail("cannot write text dataset", path);
}

std::string Hdf5File::read_text(const std::string& path) const {
  if (!exists(path)) fail("no text dataset", path);
  const Hdf5Handle set(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail("cannot open text dataset", path);
  const Hdf5Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) fail("not a text dataset:", path);
  std::string text(H5Tget_size(type.get()), '\0');
  if (H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
    fail("cannot read text dataset", path);
  text.erase(text.find_last_not_of('\0') + 1);
  return text;
}

bool Hdf5File::exists(const std::string& path) const {
  return H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) > 0;
}

DatasetData Hdf5File::read_dataset(const std::string& path) const {
  if (!exists(path)) fail("no dataset", path);
  const Hdf5Handle set(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail("cannot open dataset", path);
  const Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  DatasetData data;
  data.shape.assign(dims.begin(), dims.end());
  data.values.resize(element_count(data.shape));
  if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.values.data()) < 0)
    fail("cannot read dataset", path);
  return data;
}

double Hdf5File::read_attribute(const std::string& object, const std::string& name) const {
  const Hdf5Handle attr(
      H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (attr.get() < 0) fail("no attribute " + name + " on", object);
  double value = 0.0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail("cannot read attribute " + name + " on", object);
  return value;
}

std::string Hdf5File::read_string_attribute(const std::string& object,
                                            const std::string& name) const {
  const Hdf5Handle attr(
      H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (attr.get() < 0) fail("no attribute " + name + " on", object);
  const Hdf5Handle type(H5Aget_type(attr.get()), H5Tclose);
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(attr.get(), type.get(), value.data()) < 0)
    fail("cannot read attribute " + name + " on", object);
  value.erase(value.find_last_not_of('\0') + 1);
  return value;
}

}  // namespace mpfd::io
