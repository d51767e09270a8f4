// libFuzzer target for the decoder (built when MPFD_FUZZ=ON with clang).
// Input layout: byte 0 = number of parts (mod 5); the rest is cut into parts
// at positions taken from the following bytes.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/core/error.hpp"
#include "cosim/codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t parts = data[0] % 5;
  std::span<const std::byte> rest(reinterpret_cast<const std::byte*>(data + 1), size - 1);
  std::vector<std::span<const std::byte>> views;
  for (std::size_t i = 0; i < parts && !rest.empty(); ++i) {
    const std::size_t cut = std::to_integer<std::size_t>(rest[0]) % rest.size() + 1;
    views.push_back(rest.subspan(1, cut - 1));
    rest = rest.subspan(cut);
  }
  if (!rest.empty()) views.push_back(rest);
  try {
    mpfd::cosim::decode_bytes(views);
  } catch (const mpfd::Error&) {
  }
  return 0;
}
