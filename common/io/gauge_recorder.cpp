#include "common/io/gauge_recorder.hpp"

#include <cstdio>

#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"
#include "common/io/output_directory.hpp"

namespace mpfd::io {
namespace {

void write_csv_number(std::ostream& csv, double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", x);
  csv << text;
}

}  // namespace

GaugeRecorder::GaugeRecorder(std::filesystem::path out_dir, std::vector<GaugePoint> gauges,
                             std::vector<GaugeQuantity> quantities, GaugeStart start)
    : out_dir_(std::move(out_dir)), gauges_(std::move(gauges)), quantities_(std::move(quantities)) {
  if (start == GaugeStart::restart) return;
  const auto path = out_dir_ / "gauges.csv";
  csv_.open(path, std::ios::trunc);
  if (!csv_) throw Error("cannot open " + path.string() + " for writing");
  write_csv_header(csv_);
}

void GaugeRecorder::write_csv_header(std::ostream& csv) const {
  csv << "time[s]";
  for (const auto& g : gauges_)
    for (const auto& q : quantities_)
      csv << ',' << g.name << '.' << q.name << '[' << q.units << ']';
  csv << '\n';
}

void GaugeRecorder::reserve(std::size_t samples) {
  times_.reserve(samples);
  values_.reserve(samples * gauges_.size() * quantities_.size());
}

void GaugeRecorder::record(double time, std::span<const double> values) {
  if (values.size() != gauges_.size() * quantities_.size())
    throw Error("gauge sample has " + std::to_string(values.size()) + " values; expected " +
                std::to_string(gauges_.size() * quantities_.size()));
  if (!csv_.is_open())
    throw Error("gauge recorder of a restarted run: resume() must come before the first sample");
  times_.push_back(time);
  values_.insert(values_.end(), values.begin(), values.end());
  write_csv_row(csv_, time, values);
}

void GaugeRecorder::write_csv_row(std::ostream& csv, double time,
                                  std::span<const double> values) const {
  write_csv_number(csv, time);
  for (const double v : values) {
    csv << ',';
    write_csv_number(csv, v);
  }
  csv << '\n';
}

void GaugeRecorder::resume(std::span<const double> times, std::span<const double> values) {
  const std::size_t per_sample = gauges_.size() * quantities_.size();
  if (values.size() != times.size() * per_sample)
    throw Error("gauge histories to resume: " + std::to_string(values.size()) + " values for " +
                std::to_string(times.size()) + " samples of " + std::to_string(gauges_.size()) +
                " gauges x " + std::to_string(quantities_.size()) + " quantities; expected " +
                std::to_string(times.size() * per_sample));
  const auto path = out_dir_ / "gauges.csv";
  csv_.close();
  write_file_atomically(path, [&](std::ostream& csv) {
    write_csv_header(csv);
    for (std::size_t s = 0; s < times.size(); ++s)
      write_csv_row(csv, times[s], values.subspan(s * per_sample, per_sample));
  });
  times_.assign(times.begin(), times.end());
  values_.assign(values.begin(), values.end());
  csv_.clear();
  csv_.open(path, std::ios::app);
  if (!csv_) throw Error("cannot open " + path.string() + " for appending");
}

void GaugeRecorder::flush() {
  csv_.flush();
  if (!csv_) throw Error("cannot write " + (out_dir_ / "gauges.csv").string() + " (disk full?)");
  const std::size_t samples = times_.size();
  const std::size_t per_sample = gauges_.size() * quantities_.size();
  std::vector<double> history(samples);
  write_path_atomically(out_dir_ / "gauges.h5", [&](const std::filesystem::path& partial) {
    Hdf5File h5(partial, Hdf5File::Mode::create);
    h5.write_attribute("/", "format", std::string("mpfd-gauges"));
    h5.write_attribute("/", "format_version", std::int64_t{kOutputFormatVersion});
    h5.write_dataset("/time", times_, {samples}, "s");
    for (std::size_t g = 0; g < gauges_.size(); ++g) {
      const std::string group = "/gauges/" + gauges_[g].name;
      h5.create_group(group);
      h5.write_attribute(group, "position", gauges_[g].position);
      for (std::size_t q = 0; q < quantities_.size(); ++q) {
        for (std::size_t s = 0; s < samples; ++s)
          history[s] = values_[s * per_sample + g * quantities_.size() + q];
        h5.write_dataset(group + "/" + quantities_[q].name, history, {samples},
                         quantities_[q].units);
      }
    }
  });
}

}  // namespace mpfd::io
