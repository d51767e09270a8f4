#pragma once
// Internal: reading one YAML value with its key path, and the value types of
// the schema (number, integer, name, enum, fixed-length and open lists). Each
// value type has: Value (the C++ type), read() (reports its own errors and
// returns nullopt on failure), describe() (what was expected, for errors and
// the reference), unit() and format() (a default, for the reference).

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/config/diagnostics.hpp"

namespace mpfd::config::schema {

struct TableDoc;

/// A YAML node being read: the node, its key path, where it is, and where errors go.
struct Cursor {
  YAML::Node node;
  std::string path;
  Mark mark;
  Diagnostics* diagnostics;

  /// The cursor of value `value` under key `key` (of a map) or item `key` (e.g. "[2]").
  Cursor child(const std::string& key, const YAML::Node& value, Mark fallback) const;
  void error(const std::string& message) const { diagnostics->error(mark, path, message); }
  /// An error at key `key` of this map (at the map itself if the key is absent).
  void error_at(const std::string& key, const std::string& message) const;
  /// "expected <expected>, got <what the node holds><suffix>".
  void expected(const std::string& expected, const std::string& suffix = "") const;
};

Mark mark_of(const YAML::Node& node);
/// What a node holds, for messages: `0.9`, `"2" (a quoted string)`, `a map`, `a list of 2 items`,
/// `nothing`.
std::string found(const YAML::Node& node);
/// The shortest text that reads back as `value`.
std::string format_number(double value);

/// An interval of allowed values; unbounded by default.
struct Range {
  std::optional<double> lower, upper;
  bool lower_open = false, upper_open = false;

  static Range above(double x) { return {x, std::nullopt, true, false}; }
  static Range at_least(double x) { return {x, std::nullopt, false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  bool contains(double x) const;
  std::string text() const;    ///< "> 1", ">= 0", "in (0, 1]" or ""
  std::string suffix() const;  ///< " " + text(), or "" if unbounded
};

class Number {
 public:
  using Value = double;
  explicit Number(std::string unit = "-", Range range = {})
      : unit_(std::move(unit)), range_(range) {}
  std::optional<double> read(const Cursor& c) const;
  std::string describe() const { return "a number" + rule(); }
  std::string plural() const { return "numbers" + rule(); }
  std::string unit() const { return unit_; }
  std::string format(double v) const { return format_number(v); }

 private:
  std::string rule() const { return range_.suffix(); }
  std::string unit_;
  Range range_;
};

class Integer {
 public:
  using Value = int;
  explicit Integer(Range range = {}) : range_(range) {}
  std::optional<int> read(const Cursor& c) const;
  std::string describe() const { return "an integer" + rule(); }
  std::string plural() const { return "integers" + rule(); }
  std::string unit() const { return "-"; }
  std::string format(int v) const { return std::to_string(v); }

 private:
  std::string rule() const { return range_.suffix(); }
  Range range_;
};

/// A name: a letter, then letters, digits, '_' or '-'.
class Name {
 public:
  using Value = std::string;
  std::optional<std::string> read(const Cursor& c) const;
  std::string describe() const { return "a name (a letter, then letters, digits, _ or -)"; }
  std::string plural() const { return "names"; }
  std::string unit() const { return ""; }
};

/// true or false.
class Boolean {
 public:
  using Value = bool;
  std::optional<bool> read(const Cursor& c) const;
  std::string describe() const { return "true or false"; }
  std::string plural() const { return "booleans"; }
  std::string unit() const { return ""; }
  std::string format(bool v) const { return v ? "true" : "false"; }
};

/// One of a fixed set of words, each standing for a C++ enumerator.
template <class E>
class Enum {
 public:
  using Value = E;
  explicit Enum(std::vector<std::pair<std::string, E>> choices) : choices_(std::move(choices)) {}
  std::optional<E> read(const Cursor& c) const;
  std::string describe() const { return "one of: " + join(words()); }
  std::string plural() const { return "words from: " + join(words()); }
  std::string unit() const { return ""; }
  std::string format(E v) const;

 private:
  std::vector<std::string> words() const;
  std::vector<std::pair<std::string, E>> choices_;
};

/// Exactly N items, e.g. a point [x, y, z].
template <class Item, std::size_t N>
class Fixed {
 public:
  using Value = std::array<typename Item::Value, N>;
  explicit Fixed(Item item) : item_(std::move(item)) {}
  std::optional<Value> read(const Cursor& c) const;
  std::string describe() const { return "a list of " + std::to_string(N) + " " + item_.plural(); }
  std::string unit() const { return item_.unit(); }
  std::string format(const Value& v) const;

 private:
  Item item_;
};

/// At least `min_size` items.
template <class Item>
class ListOf {
 public:
  using Value = std::vector<typename Item::Value>;
  explicit ListOf(Item item, std::size_t min_size = 0) : item_(std::move(item)), min_(min_size) {}
  std::optional<Value> read(const Cursor& c) const;
  std::string describe() const;
  std::string unit() const { return item_.unit(); }
  std::string format(const Value& v) const requires
      requires(const Item& i, const typename Item::Value& x) {
    i.format(x);
  };
  void children(std::vector<const TableDoc*>& out) const;

 private:
  Item item_;
  std::size_t min_;
};

// ---- template definitions ---------------------------------------------------

template <class E>
std::vector<std::string> Enum<E>::words() const {
  std::vector<std::string> out;
  for (const auto& [word, value] : choices_) out.push_back(word);
  return out;
}

template <class E>
std::optional<E> Enum<E>::read(const Cursor& c) const {
  if (c.node.IsScalar()) {
    for (const auto& [word, value] : choices_) {
      if (c.node.Scalar() == word) return value;
    }
    c.expected(describe(), did_you_mean(c.node.Scalar(), words()));
  } else {
    c.expected(describe());
  }
  return std::nullopt;
}

template <class E>
std::string Enum<E>::format(E v) const {
  for (const auto& [word, value] : choices_) {
    if (value == v) return word;
  }
  return "?";
}

template <class Item, std::size_t N>
auto Fixed<Item, N>::read(const Cursor& c) const -> std::optional<Value> {
  if (!c.node.IsSequence() || c.node.size() != N) {
    c.expected(describe());
    return std::nullopt;
  }
  Value out{};
  bool ok = true;
  for (std::size_t i = 0; i < N; ++i) {
    const auto item = item_.read(c.child("[" + std::to_string(i) + "]", c.node[i], c.mark));
    if (item) out[i] = *item;
    ok = ok && item.has_value();
  }
  return ok ? std::optional<Value>(out) : std::nullopt;
}

template <class Item, std::size_t N>
std::string Fixed<Item, N>::format(const Value& v) const {
  std::string out = "[";
  for (std::size_t i = 0; i < N; ++i) out += (i ? ", " : "") + item_.format(v[i]);
  return out + "]";
}

template <class Item>
auto ListOf<Item>::read(const Cursor& c) const -> std::optional<Value> {
  if (!c.node.IsSequence() || c.node.size() < min_) {
    c.expected(describe());
    return std::nullopt;
  }
  Value out;
  bool ok = true;
  for (std::size_t i = 0; i < c.node.size(); ++i) {
    auto item = item_.read(c.child("[" + std::to_string(i) + "]", c.node[i], c.mark));
    if (item) out.push_back(std::move(*item));
    ok = ok && item.has_value();
  }
  return ok ? std::optional<Value>(std::move(out)) : std::nullopt;
}

template <class Item>
std::string ListOf<Item>::describe() const {
  const std::string size = min_ > 0 ? std::to_string(min_) + " or more " : "";
  return "a list of " + size + item_.plural();
}

template <class Item>
std::string ListOf<Item>::format(const Value& v) const requires
    requires(const Item& i, const typename Item::Value& x) {
  i.format(x);
}
{
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + item_.format(v[i]);
  return out + "]";
}

template <class Item>
void ListOf<Item>::children(std::vector<const TableDoc*>& out) const {
  if constexpr (requires { item_.children(out); }) item_.children(out);
}

}  // namespace mpfd::config::schema
