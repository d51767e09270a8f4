#pragma once
// <out>/summary.json: what ran, how long it took, how fast it went and how
// well it conserved mass, momentum and energy. Written at every output (status
// "running"), and at the end ("completed" or "failed" with the error), so a
// run that dies still says how far it got. Layout: docs/output.md.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mpfd::io {

/// One conserved quantity: inside the domain now and at the start, and what
/// left through open boundaries (net outflow, positive out).
struct ConservationEntry {
  std::string quantity;  // "mass", "momentum_x", "energy", ...
  std::string units;     // "kg", "kg m/s", "J"
  double initial = 0.0;
  double current = 0.0;
  double boundary_outflow = 0.0;
  /// (current + outflow - initial) / max(|initial|, scale): the audit's verdict.
  [[nodiscard]] double relative_error(double scale) const;
};

class RunSummary {
 public:
  RunSummary(std::string program, std::string scene_name, std::filesystem::path scene_file);

  void set_status(const std::string& status, const std::string& error = {});
  void set_progress(std::int64_t steps, double time, double end_time, double wall_seconds);
  /// e.g. ("cell_updates_per_second", 2.1e8).
  void set_rate(const std::string& name, double per_second);
  void set_conservation(const std::vector<ConservationEntry>& entries, double scale = 0.0);
  /// Anything solver-specific, under "details".
  void set_detail(const std::string& key, nlohmann::json value);

  [[nodiscard]] const nlohmann::json& json() const { return doc_; }
  void write(const std::filesystem::path& file) const;

 private:
  nlohmann::json doc_;
};

}  // namespace mpfd::io
