#include "cosim/arrays.hpp"

#include <algorithm>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::cosim {

std::size_t dtype_size(v1::DType dtype) {
  switch (dtype) {
    case v1::DTYPE_F64:
    case v1::DTYPE_I64:
    case v1::DTYPE_U64:
      return 8;
    case v1::DTYPE_F32:
    case v1::DTYPE_I32:
    case v1::DTYPE_U32:
      return 4;
    case v1::DTYPE_U8:
      return 1;
    default:
      return 0;
  }
}

ArrayShape::ArrayShape(std::span<const std::uint64_t> extents) : axes_(extents.size()) {
  if (axes_ > kMaxAxes)
    throw Error("array shape of " + std::to_string(axes_) + " axes; at most " +
                std::to_string(kMaxAxes) + " are supported");
  std::copy(extents.begin(), extents.end(), extents_.begin());
}

void append_frame(Message& message, const ArraySpec& spec, v1::DType dtype, std::size_t count,
                  zmq::message_t frame) {
  auto* descriptor = message.header.add_arrays();
  descriptor->set_group(std::string(spec.group));
  descriptor->set_name(std::string(spec.name));
  descriptor->set_dtype(dtype);
  if (spec.shape.empty()) {
    descriptor->add_shape(count);
  } else {
    for (const auto extent : spec.shape) descriptor->add_shape(extent);
  }
  descriptor->set_frame_index(static_cast<std::uint32_t>(message.frames.size()));
  descriptor->set_units(std::string(spec.units));
  message.frames.push_back(std::move(frame));
}

const v1::ArrayDescriptor& find_descriptor(const Message& message, std::string_view group,
                                           std::string_view name) {
  for (const auto& descriptor : message.header.arrays()) {
    if (descriptor.group() == group && descriptor.name() == name) return descriptor;
  }
  throw Error("message '" + std::string(body_name(message.header)) + "' from '" +
              message.header.envelope().sender() + "' has no array '" + std::string(name) +
              "' in group '" + std::string(group) + "'");
}

void check_dtype(const v1::ArrayDescriptor& descriptor, v1::DType expected) {
  if (descriptor.dtype() == expected) return;
  throw Error("array '" + descriptor.group() + "/" + descriptor.name() + "' has dtype " +
              v1::DType_Name(descriptor.dtype()) + ", expected " + v1::DType_Name(expected));
}

}  // namespace mpfd::cosim
