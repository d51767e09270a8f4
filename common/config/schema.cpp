#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <system_error>

#include "common/config/schema_table.hpp"
#include "common/config/schema_values.hpp"

namespace mpfd::config::schema {
namespace {

// A quoted scalar ("1.0") is text even if it looks like a number.
bool is_plain(const YAML::Node& node) {
  return node.IsScalar() && node.Tag() != "!";
}

std::optional<double> parse_double(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string child_path(const std::string& path, const std::string& key) {
  if (key.starts_with('[') || path.empty()) return path + key;
  return path + "." + key;
}

}  // namespace

Mark mark_of(const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return Mark{};
  return Mark{m.line + 1, m.column + 1};
}

Cursor Cursor::child(const std::string& key, const YAML::Node& value, Mark fallback) const {
  const Mark m = value.IsNull() || mark_of(value).line == 0 ? fallback : mark_of(value);
  Cursor c{value, child_path(path, key), m, diagnostics};
  diagnostics->remember(c.path, m);
  return c;
}

void Cursor::error_at(const std::string& key, const std::string& message) const {
  diagnostics->error(child_path(path, key), message);
}

void Cursor::expected(const std::string& what, const std::string& suffix) const {
  error("expected " + what + ", got " + found(node) + suffix);
}

std::string found(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) {
    return "a list of " + std::to_string(node.size()) + (node.size() == 1 ? " item" : " items");
  }
  std::string text = node.Scalar();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return is_plain(node) ? text : "\"" + text + "\" (a quoted string)";
}

std::string format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

bool Range::contains(double x) const {
  if (lower && (lower_open ? x <= *lower : x < *lower)) return false;
  if (upper && (upper_open ? x >= *upper : x > *upper)) return false;
  return true;
}

std::string Range::text() const {
  std::string out;
  if (lower && upper) {
    out = lower_open ? "in (" : "in [";
    out += format_number(*lower);
    out += ", ";
    out += format_number(*upper);
    out += upper_open ? ")" : "]";
  } else if (lower) {
    out = lower_open ? "> " : ">= ";
    out += format_number(*lower);
  } else if (upper) {
    out = upper_open ? "< " : "<= ";
    out += format_number(*upper);
  }
  return out;
}

std::string Range::suffix() const {
  std::string out = text();
  if (!out.empty()) out.insert(out.begin(), ' ');
  return out;
}

std::optional<double> Number::read(const Cursor& c) const {
  const auto value = is_plain(c.node) ? parse_double(c.node.Scalar()) : std::nullopt;
  if (!value || !range_.contains(*value)) {
    c.expected(describe());
    return std::nullopt;
  }
  return value;
}

// Accepts 100000 and also 1e5: any number with an integral value in range.
std::optional<int> Integer::read(const Cursor& c) const {
  const auto value = is_plain(c.node) ? parse_double(c.node.Scalar()) : std::nullopt;
  if (!value || *value != std::floor(*value) || !range_.contains(*value) ||
      std::abs(*value) > std::numeric_limits<int>::max()) {
    c.expected(describe());
    return std::nullopt;
  }
  return static_cast<int>(*value);
}

std::optional<std::string> Name::read(const Cursor& c) const {
  const std::string text = c.node.IsScalar() ? c.node.Scalar() : "";
  bool ok = !text.empty() && std::isalpha(static_cast<unsigned char>(text[0]));
  for (const char ch : text) {
    ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-');
  }
  if (!ok) {
    c.expected(describe());
    return std::nullopt;
  }
  return text;
}

std::optional<bool> Boolean::read(const Cursor& c) const {
  const std::string text = c.node.IsScalar() ? c.node.Scalar() : "";
  if (text == "true") return true;
  if (text == "false") return false;
  c.expected(describe());
  return std::nullopt;
}

bool check_keys(const Cursor& c, const std::vector<std::string>& allowed) {
  if (!c.node.IsMap()) {
    c.expected("a map with keys: " + join(allowed));
    return false;
  }
  std::map<std::string, Mark> seen;
  for (const auto& entry : c.node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    const Mark at = mark_of(entry.first);
    const std::string path = child_path(c.path, key);
    if (const auto [first, fresh] = seen.emplace(key, at); !fresh) {
      c.diagnostics->error(
          at, path, "duplicate key (first at line " + std::to_string(first->second.line) + ")");
    } else if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      c.diagnostics->error(
          at, path,
          "unknown key" + did_you_mean(key, allowed) + " (allowed here: " + join(allowed) + ")");
    }
  }
  return true;
}

std::optional<Cursor> find_key(const Cursor& c, const std::string& key) {
  for (const auto& entry : c.node) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) {
      return c.child(key, entry.second, mark_of(entry.first));
    }
  }
  return std::nullopt;
}

void missing_key(const Cursor& c, const std::string& key, const std::string& expected) {
  c.diagnostics->error(c.mark, child_path(c.path, key),
                       "required key is missing; expected " + expected);
}

}  // namespace mpfd::config::schema
