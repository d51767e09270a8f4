#include "tests/verification/support/scene_text.hpp"

#include <fstream>
#include <sstream>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

std::size_t find_or_throw(const std::string& text, const std::string& from) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos)
    throw Error("scene text lacks '" + from + "', which the test replaces");
  return at;
}

}  // namespace

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read '" + file.string() + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(find_or_throw(text, from), from.size(), to);
  return text;
}

std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = find_or_throw(text, from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace mpfd::verification
