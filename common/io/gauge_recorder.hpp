#pragma once
// Gauge time histories (the thesis's "tracking points"): a CSV file streamed
// line by line (<out>/gauges.csv) and an HDF5 copy (<out>/gauges.h5)
// rewritten on every flush(), so a crashed run keeps its histories up to the
// last output. Layout: docs/output.md.

#include <array>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace mpfd::io {

struct GaugePoint {
  std::string name;
  std::array<double, 3> position;  // m
};

struct GaugeQuantity {
  std::string name;   // e.g. "pressure"
  std::string units;  // e.g. "Pa"
};

/// A new run's recorder starts gauges.csv; a restarted run's leaves the file as the
/// stopped run left it until resume() replaces it.
enum class GaugeStart { fresh, restart };

class GaugeRecorder {
 public:
  /// Opens <out_dir>/gauges.csv and writes its header (GaugeStart::fresh).
  GaugeRecorder(std::filesystem::path out_dir, std::vector<GaugePoint> gauges,
                std::vector<GaugeQuantity> quantities, GaugeStart start = GaugeStart::fresh);

  /// One sample: values gauge-major, gauges().size() * quantities().size().
  void record(double time, std::span<const double> values);
  /// Rewrites gauges.h5 with every sample so far and flushes the CSV.
  void flush();

  [[nodiscard]] const std::vector<GaugePoint>& gauges() const { return gauges_; }
  [[nodiscard]] const std::vector<GaugeQuantity>& quantities() const { return quantities_; }
  [[nodiscard]] std::size_t sample_count() const { return times_.size(); }
  /// Pre-allocates room for `samples` samples so that record() does not allocate.
  void reserve(std::size_t samples);

  /// Every sample so far: its time [s], and its values (sample-major, as record() took them).
  [[nodiscard]] std::span<const double> times() const { return times_; }
  [[nodiscard]] std::span<const double> values() const { return values_; }
  /// Replaces the samples with `times` and `values` (those of an earlier recorder of the
  /// same gauges) and rewrites gauges.csv with them (beside it, then renamed): a restarted
  /// run goes on from its checkpoint's histories, not from the rows the run wrote after
  /// it. Throws mpfd::Error when the counts do not fit, before anything changes.
  void resume(std::span<const double> times, std::span<const double> values);

 private:
  void write_csv_header(std::ostream& csv) const;
  void write_csv_row(std::ostream& csv, double time, std::span<const double> values) const;

  std::filesystem::path out_dir_;
  std::vector<GaugePoint> gauges_;
  std::vector<GaugeQuantity> quantities_;
  std::ofstream csv_;
  std::vector<double> times_;
  std::vector<double> values_;  // sample-major, then gauge, then quantity
};

}  // namespace mpfd::io
