#pragma once
// Internal: a Table<T> reads one YAML map into one struct T, key by key, the
// way preCICE's XMLTag does: each key has a value type (schema_values.hpp), a
// doc string, and is required or optional (optional keys keep T{}'s value, so
// the defaults live in scene.hpp and the reference prints them from there).
// Unknown and duplicate keys are errors. Nested<T>, NamedMap<T> and Choice<V>
// make tables into value types, so tables nest; each table also carries the
// TableDoc that print_schema() prints.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/config/schema_values.hpp"
#include "common/core/error.hpp"

namespace mpfd::config::schema {

struct KeyDoc {
  std::string key, type, unit, presence, doc;
};

/// One section of the reference: a table's keys, its cross-key rules and the tables below it.
struct TableDoc {
  std::string title;
  std::string doc;
  std::vector<KeyDoc> keys;
  std::vector<std::string> rules;
  std::vector<const TableDoc*> children;
};

/// The reference: `root`'s section, then every table below it once, depth first.
std::string to_markdown(const TableDoc& root);

/// Reports a non-map, duplicate keys and keys not in `allowed`; false only if `c` is not a map.
bool check_keys(const Cursor& c, const std::vector<std::string>& allowed);
/// The cursor of the value under `key` in map `c`, if the key is there.
std::optional<Cursor> find_key(const Cursor& c, const std::string& key);
/// Reports "<path>.<key>: required key is missing; expected <expected>" at map `c`.
void missing_key(const Cursor& c, const std::string& key, const std::string& expected);

template <class>
inline constexpr bool is_optional = false;
template <class U>
inline constexpr bool is_optional<std::optional<U>> = true;

template <class T>
class Table {
 public:
  using Check = std::function<void(const T&, const Cursor&)>;

  Table(std::string title, std::string doc) : doc_{std::move(title), std::move(doc), {}, {}, {}} {}

  /// A key that must be present; `get` maps a T& to the member it fills (member pointer or lambda).
  template <class Type, class Get>
  Table& required(std::string key, Get get, Type type, std::string doc) {
    return add(std::move(key), get, std::move(type), std::move(doc), true);
  }
  /// A key that may be left out: its member keeps T{}'s value (a std::optional stays empty).
  template <class Type, class Get>
  Table& optional(std::string key, Get get, Type type, std::string doc) {
    return add(std::move(key), get, std::move(type), std::move(doc), false);
  }
  /// A rule across keys, run once every key read cleanly; `check` reports through the cursor.
  Table& rule(std::string doc, Check check) {
    doc_.rules.push_back(std::move(doc));
    rules_.push_back(std::move(check));
    return *this;
  }

  /// Reads map `c` into `out`; false (errors reported) if anything in it is wrong.
  bool read(const Cursor& c, T& out, const std::vector<std::string>& extra_keys = {}) const {
    std::vector<std::string> allowed = extra_keys;
    for (const Field& f : fields_) allowed.push_back(f.key);
    if (!check_keys(c, allowed)) return false;
    for (const Field& f : fields_) {
      if (const auto value = find_key(c, f.key)) {
        f.read(*value, out);
      } else if (f.required) {
        missing_key(c, f.key, f.expected);
      }
    }
    if (!c.diagnostics->clean(c.path)) return false;
    for (const Check& check : rules_) check(out, c);
    return c.diagnostics->clean(c.path);
  }

  const TableDoc& doc() const { return doc_; }

 private:
  struct Field {
    std::string key;
    bool required;
    std::string expected;
    std::function<void(const Cursor&, T&)> read;
  };

  template <class Type, class Get>
  Table& add(std::string key, Get get, Type type, std::string doc, bool required) {
    using Member = std::remove_cvref_t<std::invoke_result_t<Get, T&>>;
    T defaults{};
    std::string presence = required ? "required" : "optional";
    if constexpr (!is_optional<Member> && requires { type.format(std::invoke(get, defaults)); }) {
      if (!required) presence = "default `" + type.format(std::invoke(get, defaults)) + "`";
    }
    std::string described = type.describe();
    const std::size_t first_child = doc_.children.size();
    if constexpr (requires { type.children(doc_.children); }) type.children(doc_.children);
    for (std::size_t i = first_child; i < doc_.children.size(); ++i) {
      described += (i == first_child ? ", see " : ", ") + ("`" + doc_.children[i]->title + "`");
    }
    doc_.keys.push_back(KeyDoc{key, described, type.unit(), presence, std::move(doc)});
    fields_.push_back(Field{key, required, type.describe(), [get, type](const Cursor& c, T& out) {
                              if (auto value = type.read(c))
                                std::invoke(get, out) = std::move(*value);
                            }});
    return *this;
  }

  std::vector<Field> fields_;
  std::vector<Check> rules_;
  TableDoc doc_;
};

/// A new table titled `title` with the reference text `doc`, to be filled by the caller.
template <class T>
std::shared_ptr<Table<T>> make_table(std::string title, std::string doc) {
  return std::make_shared<Table<T>>(std::move(title), std::move(doc));
}

/// A nested map read by its own table.
template <class T>
class Nested {
 public:
  using Value = T;
  explicit Nested(std::shared_ptr<const Table<T>> table) : table_(std::move(table)) {}
  std::optional<T> read(const Cursor& c) const {
    T out{};
    return table_->read(c, out) ? std::optional<T>(std::move(out)) : std::nullopt;
  }
  std::string describe() const { return "a map"; }
  std::string plural() const { return "maps"; }
  std::string unit() const { return ""; }
  void children(std::vector<const TableDoc*>& out) const { out.push_back(&table_->doc()); }

 private:
  std::shared_ptr<const Table<T>> table_;
};

/// A map from names to entries (e.g. materials), read into a list of T whose `name` member is set.
template <class T>
class NamedMap {
 public:
  using Value = std::vector<T>;
  NamedMap(std::shared_ptr<const Table<T>> table, std::string T::*name)
      : table_(std::move(table)), name_(name) {}
  std::optional<Value> read(const Cursor& c) const {
    if (!c.node.IsMap() || c.node.size() == 0) {
      c.expected(describe());
      return std::nullopt;
    }
    Value out;
    std::map<std::string, Mark> seen;
    for (const auto& entry : c.node) {
      const Mark key_mark = mark_of(entry.first);
      const auto name = Name{}.read(c.child(entry.first.Scalar(), entry.first, key_mark));
      if (!name) continue;
      if (const auto [first, fresh] = seen.emplace(*name, key_mark); !fresh) {
        c.diagnostics->error(
            key_mark, c.path + "." + *name,
            "duplicate name (first at line " + std::to_string(first->second.line) + ")");
        continue;
      }
      T item{};
      if (table_->read(c.child(*name, entry.second, key_mark), item)) {
        item.*name_ = *name;
        out.push_back(std::move(item));
      }
    }
    return out;
  }
  std::string describe() const { return "a map from names to maps (at least one entry)"; }
  std::string unit() const { return ""; }
  void children(std::vector<const TableDoc*>& out) const { out.push_back(&table_->doc()); }

 private:
  std::shared_ptr<const Table<T>> table_;
  std::string T::*name_;
};

/// A map whose `type` key picks one alternative of variant V; the other keys are that
/// alternative's.
template <class V>
class Choice {
 public:
  using Value = V;
  Choice(std::string title, std::string doc)
      : doc_(std::make_shared<TableDoc>(TableDoc{std::move(title), std::move(doc), {}, {}, {}})) {}

  /// Alternatives are added in the order of V's types.
  template <class Alt>
  Choice& add(std::string word, std::shared_ptr<const Table<Alt>> table) {
    MPFD_ASSERT(V{Alt{}}.index() == alternatives_.size(),
                "add Choice alternatives in variant order");
    alternatives_.push_back(Alternative{word, [table](const Cursor& c) -> std::optional<V> {
                                          Alt out{};
                                          if (!table->read(c, out, {"type"})) return std::nullopt;
                                          return V{std::move(out)};
                                        }});
    doc_->children.push_back(&table->doc());
    return describe_type_key();
  }
  /// A word that names a model MPFD will have but does not yet.
  Choice& planned(std::string word) {
    planned_.push_back(std::move(word));
    return describe_type_key();
  }

  std::optional<V> read(const Cursor& c) const {
    if (!c.node.IsMap()) {
      c.expected(describe());
      return std::nullopt;
    }
    const auto type = find_key(c, "type");
    if (!type) {
      missing_key(c, "type", type_rule());
      return std::nullopt;
    }
    const std::string word = type->node.IsScalar() ? type->node.Scalar() : "";
    for (const Alternative& a : alternatives_) {
      if (a.word == word) return a.read(c);
    }
    for (const std::string& p : planned_) {
      if (p == word) type->error("'" + word + "' is not yet supported; expected " + type_rule());
    }
    if (type->diagnostics->clean(type->path))
      type->expected(type_rule(), did_you_mean(word, words()));
    return std::nullopt;
  }
  std::string describe() const { return "a map with a `type` key"; }
  std::string unit() const { return ""; }
  std::string format(const V& v) const { return "{type: " + alternatives_[v.index()].word + "}"; }
  void children(std::vector<const TableDoc*>& out) const { out.push_back(doc_.get()); }

 private:
  struct Alternative {
    std::string word;
    std::function<std::optional<V>(const Cursor&)> read;
  };

  std::vector<std::string> words() const {
    std::vector<std::string> out;
    for (const Alternative& a : alternatives_) out.push_back(a.word);
    return out;
  }
  std::string type_rule() const { return "one of: " + join(words()); }
  Choice& describe_type_key() {
    std::string doc = "the model; its other keys are those of its section below";
    if (!planned_.empty()) doc += ". Planned, not yet supported: " + join(planned_);
    doc_->keys = {KeyDoc{"type", type_rule(), "", "required", doc}};
    return *this;
  }

  std::vector<Alternative> alternatives_;
  std::vector<std::string> planned_;
  std::shared_ptr<TableDoc> doc_;
};

}  // namespace mpfd::config::schema
