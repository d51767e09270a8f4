#include "common/config/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace mpfd::config {
namespace {

// The parent of `a.b[2]` is `a.b`, of `a.b` is `a`, of `a` is "".
std::string_view parent(std::string_view path) {
  const std::size_t cut = path.find_last_of(".[");
  return cut == std::string_view::npos ? std::string_view{} : path.substr(0, cut);
}

bool is_under(std::string_view path, std::string_view prefix) {
  if (prefix.empty()) return true;
  if (!path.starts_with(prefix)) return false;
  return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}

// Levenshtein distance, ignoring case.
std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string to_string(const Diagnostic& d) {
  std::string out = d.file;
  if (d.line > 0) {
    out += ':';
    out += std::to_string(d.line);
    out += ':';
    out += std::to_string(d.column);
  }
  out += ": ";
  if (!d.path.empty()) out += d.path + ": ";
  return out + d.message;
}

SceneError::SceneError(std::vector<Diagnostic> diagnostics)
    : Error([&] {
        std::string text;
        for (const Diagnostic& d : diagnostics) {
          if (!text.empty()) text += '\n';
          text += to_string(d);
        }
        return text;
      }()),
      diagnostics_(std::move(diagnostics)) {}

Mark Diagnostics::locate(std::string_view path) const {
  for (;;) {
    if (const auto it = marks_.find(path); it != marks_.end()) return it->second;
    if (path.empty()) return Mark{};
    path = parent(path);
  }
}

void Diagnostics::error(Mark mark, std::string path, std::string message) {
  errors_.push_back(Diagnostic{file_, mark.line, mark.column, std::move(path), std::move(message)});
}

bool Diagnostics::clean(std::string_view path) const {
  return std::none_of(errors_.begin(), errors_.end(),
                      [&](const Diagnostic& d) { return is_under(d.path, path); });
}

void Diagnostics::throw_if_any() const {
  if (errors_.empty()) return;
  std::vector<Diagnostic> sorted = errors_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  throw SceneError(std::move(sorted));
}

std::string did_you_mean(std::string_view got, const std::vector<std::string>& allowed) {
  const std::string* best = nullptr;
  std::size_t best_distance = std::max<std::size_t>(2, got.size() / 3) + 1;
  for (const std::string& candidate : allowed) {
    const bool extends = got.size() >= 3 && std::string_view(candidate).starts_with(got);
    const std::size_t d = extends ? 1 : distance(got, candidate);
    if (d < best_distance) {
      best = &candidate;
      best_distance = d;
    }
  }
  return best ? "; did you mean '" + *best + "'?" : "";
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (const std::string& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

}  // namespace mpfd::config
