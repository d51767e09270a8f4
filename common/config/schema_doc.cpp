#include <set>
#include <string>

#include "common/config/schema_table.hpp"

namespace mpfd::config::schema {
namespace {

void print(const TableDoc& table, std::set<const TableDoc*>& done, std::string& out) {
  if (!done.insert(&table).second) return;
  out += "\n## `" + table.title + "`\n\n" + table.doc + "\n";
  if (!table.keys.empty()) {
    out += "\n| key | type | unit | default | description |\n|---|---|---|---|---|\n";
    for (const KeyDoc& k : table.keys) {
      out += "| `" + k.key + "` | " + k.type + " | " + k.unit + " | " + k.presence + " | " + k.doc +
             " |\n";
    }
  }
  if (!table.rules.empty()) {
    out += "\nRules:\n";
    for (const std::string& rule : table.rules) out += "- " + rule + "\n";
  }
  for (const TableDoc* child : table.children) print(*child, done, out);
}

}  // namespace

std::string to_markdown(const TableDoc& root) {
  std::set<const TableDoc*> done;
  std::string out;
  print(root, done, out);
  return out;
}

}  // namespace mpfd::config::schema
