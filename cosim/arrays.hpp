#pragma once
// Typed access to the raw frames of a Message: append arrays (copying or
// zero-copy) and view received arrays as spans (copied only when misaligned).

#include <array>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string_view>
#include <vector>

#include "cosim/message.hpp"

namespace mpfd::cosim {

template <typename T>
struct DTypeOf;
template <>
struct DTypeOf<double> {
  static constexpr v1::DType value = v1::DTYPE_F64;
};
template <>
struct DTypeOf<float> {
  static constexpr v1::DType value = v1::DTYPE_F32;
};
template <>
struct DTypeOf<std::int64_t> {
  static constexpr v1::DType value = v1::DTYPE_I64;
};
template <>
struct DTypeOf<std::int32_t> {
  static constexpr v1::DType value = v1::DTYPE_I32;
};
template <>
struct DTypeOf<std::uint64_t> {
  static constexpr v1::DType value = v1::DTYPE_U64;
};
template <>
struct DTypeOf<std::uint32_t> {
  static constexpr v1::DType value = v1::DTYPE_U32;
};
template <>
struct DTypeOf<std::uint8_t> {
  static constexpr v1::DType value = v1::DTYPE_U8;
};

/// Bytes per value of a dtype; 0 for DTYPE_UNSPECIFIED or an unknown value.
std::size_t dtype_size(v1::DType dtype);

/// The extents of an array, up to four axes, from a braced list ({n, 3}) without
/// allocating (a coupler builds several arrays every step).
class ArrayShape {
 public:
  static constexpr std::size_t kMaxAxes = 4;
  ArrayShape() = default;
  ArrayShape(std::initializer_list<std::uint64_t> extents)  // throws mpfd::Error past kMaxAxes
      : ArrayShape(std::span<const std::uint64_t>(extents.begin(), extents.size())) {}
  /// From extents held elsewhere (a std::vector, a descriptor's shape); throws past kMaxAxes.
  ArrayShape(std::span<const std::uint64_t> extents);
  ArrayShape(const std::vector<std::uint64_t>& extents)
      : ArrayShape(std::span<const std::uint64_t>(extents)) {}
  [[nodiscard]] bool empty() const { return axes_ == 0; }
  [[nodiscard]] const std::uint64_t* begin() const { return extents_.data(); }
  [[nodiscard]] const std::uint64_t* end() const { return extents_.data() + axes_; }

 private:
  std::array<std::uint64_t, kMaxAxes> extents_{};
  std::size_t axes_ = 0;
};

struct ArraySpec {
  std::string_view group;
  std::string_view name;
  ArrayShape shape;  // empty: one axis of the data's length
  std::string_view units;
};

/// Appends a descriptor for `frame` (raw bytes of `dtype`) and the frame itself.
void append_frame(Message& message, const ArraySpec& spec, v1::DType dtype, std::size_t count,
                  zmq::message_t frame);

/// Appends an array by copying `values` once into a new frame.
template <typename T>
void add_array(Message& message, const ArraySpec& spec, std::span<const T> values) {
  zmq::message_t frame(values.size_bytes());
  if (!values.empty()) std::memcpy(frame.data(), values.data(), values.size_bytes());
  append_frame(message, spec, DTypeOf<T>::value, values.size(), std::move(frame));
}

/// Appends an array without copying: the frame takes ownership of `values`.
template <typename T>
void add_array(Message& message, const ArraySpec& spec, std::vector<T>&& values) {
  auto* owner = new std::vector<T>(std::move(values));
  const std::size_t count = owner->size();
  zmq::message_t frame(
      owner->data(), owner->size() * sizeof(T),
      [](void*, void* hint) { delete static_cast<std::vector<T>*>(hint); }, owner);
  append_frame(message, spec, DTypeOf<T>::value, count, std::move(frame));
}

/// The descriptor of array `name` in `group`; throws mpfd::Error naming both if absent.
const v1::ArrayDescriptor& find_descriptor(const Message& message, std::string_view group,
                                           std::string_view name);

/// Throws mpfd::Error unless `descriptor` has dtype `expected`.
void check_dtype(const v1::ArrayDescriptor& descriptor, v1::DType expected);

/// A read-only view of a received array: points into the frame when it is
/// aligned for T, else into an aligned copy it owns.
template <typename T>
class ArrayView {
 public:
  ArrayView(const v1::ArrayDescriptor& descriptor, const zmq::message_t& frame)
      : descriptor_(&descriptor) {
    check_dtype(descriptor, DTypeOf<T>::value);
    const std::size_t count = frame.size() / sizeof(T);
    const auto address = reinterpret_cast<std::uintptr_t>(frame.data());
    if (address % alignof(T) == 0) {
      values_ = std::span<const T>(static_cast<const T*>(frame.data()), count);
    } else {
      copy_.resize(count);
      std::memcpy(copy_.data(), frame.data(), count * sizeof(T));
      values_ = copy_;
    }
  }
  ArrayView(const ArrayView&) = delete;
  ArrayView& operator=(const ArrayView&) = delete;

  std::span<const T> values() const { return values_; }
  const v1::ArrayDescriptor& descriptor() const { return *descriptor_; }
  bool copied() const { return !copy_.empty(); }

 private:
  const v1::ArrayDescriptor* descriptor_;
  std::vector<T> copy_;
  std::span<const T> values_;
};

/// Views array `name` of `group`; throws mpfd::Error if absent or of another dtype.
template <typename T>
ArrayView<T> view_array(const Message& message, std::string_view group, std::string_view name) {
  const auto& descriptor = find_descriptor(message, group, name);
  return ArrayView<T>(descriptor, message.frames.at(descriptor.frame_index()));
}

}  // namespace mpfd::cosim
