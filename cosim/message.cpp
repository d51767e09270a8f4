#include "cosim/message.hpp"

namespace mpfd::cosim {

const char* body_name(const v1::Header& header) {
  if (header.body_case() == v1::Header::BODY_NOT_SET) return "none";
  const auto* field = v1::Header::descriptor()->FindFieldByNumber(header.body_case());
  return field == nullptr ? "unknown" : field->name().c_str();
}

}  // namespace mpfd::cosim
