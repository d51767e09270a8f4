#include "common/io/run_summary.hpp"

#include <algorithm>
#include <cmath>

#include "common/io/output_directory.hpp"

namespace mpfd::io {

double ConservationEntry::relative_error(double scale) const {
  const double reference = std::max(std::abs(initial), scale);
  const double drift = current + boundary_outflow - initial;
  return reference > 0.0 ? drift / reference : drift;
}

RunSummary::RunSummary(std::string program, std::string scene_name,
                       std::filesystem::path scene_file) {
  doc_["format"] = "mpfd-summary";
  doc_["format_version"] = kOutputFormatVersion;
  doc_["program"] = std::move(program);
  doc_["scene"] = {{"name", std::move(scene_name)}, {"file", scene_file.string()}};
  doc_["status"] = "running";
}

void RunSummary::set_status(const std::string& status, const std::string& error) {
  doc_["status"] = status;
  if (error.empty())
    doc_.erase("error");
  else
    doc_["error"] = error;
}

void RunSummary::set_progress(std::int64_t steps, double time, double end_time,
                              double wall_seconds) {
  doc_["steps"] = steps;
  doc_["time_s"] = time;
  doc_["end_time_s"] = end_time;
  doc_["wall_time_s"] = wall_seconds;
}

void RunSummary::set_rate(const std::string& name, double per_second) {
  doc_["rates"][name] = per_second;
}

void RunSummary::set_conservation(const std::vector<ConservationEntry>& entries, double scale) {
  nlohmann::json audit = nlohmann::json::object();
  for (const auto& e : entries)
    audit[e.quantity] = {{"units", e.units},
                         {"initial", e.initial},
                         {"current", e.current},
                         {"boundary_outflow", e.boundary_outflow},
                         {"relative_error", e.relative_error(scale)}};
  doc_["conservation"] = std::move(audit);
}

void RunSummary::set_detail(const std::string& key, nlohmann::json value) {
  doc_["details"][key] = std::move(value);
}

void RunSummary::write(const std::filesystem::path& file) const {
  write_file_atomically(file, [&](std::ostream& out) { out << doc_.dump(2) << '\n'; });
}

}  // namespace mpfd::io
