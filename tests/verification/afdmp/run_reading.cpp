#include "tests/verification/afdmp/run_reading.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"

namespace mpfd::verification {
namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

}  // namespace

std::filesystem::path snapshot_nearest(const std::filesystem::path& snapshots, double time,
                                       double tolerance) {
  std::filesystem::path best;
  double best_gap = std::numeric_limits<double>::infinity();
  for (const auto& entry : std::filesystem::directory_iterator(snapshots)) {
    if (entry.path().extension() != ".h5") continue;
    const io::Hdf5File file(entry.path(), io::Hdf5File::Mode::read);
    const double gap = std::abs(file.read_attribute("/", "time") - time);
    if (gap < best_gap) {
      best_gap = gap;
      best = entry.path();
    }
  }
  if (best.empty() || best_gap > tolerance)
    throw Error("snapshot_nearest: no snapshot in " + snapshots.string() + " within " +
                std::to_string(tolerance) + " s of t = " + std::to_string(time) +
                " s (nearest is " + std::to_string(best_gap) + " s away)");
  return best;
}

PointSet particle_points(const std::filesystem::path& snapshot, int products_material) {
  const io::Hdf5File file(snapshot, io::Hdf5File::Mode::read);
  if (!file.exists("/particles/position"))
    throw Error("particle_points: " + snapshot.string() + " holds no /particles/position");
  const auto position = file.read_dataset("/particles/position").values;
  const auto material = file.read_dataset("/particles/material").values;
  const auto mass = file.read_dataset("/particles/mass").values;
  const auto density = file.read_dataset("/particles/density").values;
  PointSet points;
  for (std::size_t p = 0; p < material.size(); ++p) {
    const bool products = static_cast<int>(material[p]) == products_material;
    points.x.push_back(position[3 * p]);
    points.y.push_back(position[3 * p + 1]);
    const double volume = mass[p] / density[p];
    points.products.push_back(products ? volume : 0.0);
    points.air.push_back(products ? 0.0 : volume);
  }
  return points;
}

PointSet cell_points(const std::filesystem::path& snapshot, const std::string& products_fraction,
                     const std::string& air_fraction, const PlaneGrid& grid) {
  const io::Hdf5File file(snapshot, io::Hdf5File::Mode::read);
  const auto read = [&](const std::string& field) {
    const std::string path = "/cells/" + field;
    if (!file.exists(path)) throw Error("cell_points: " + snapshot.string() + " holds no " + path);
    return file.read_dataset(path);
  };
  const auto products = read(products_fraction);
  const auto air = read(air_fraction).values;
  const std::size_t nx = products.shape.back(), ny = products.shape[products.shape.size() - 2];
  if (products.values.size() != nx * ny || air.size() != nx * ny)
    throw Error("cell_points: " + products_fraction + " and " + air_fraction + " in " +
                snapshot.string() + " are not one layer of " + std::to_string(nx) + " x " +
                std::to_string(ny) + " cells");
  const double volume = grid.spacing[0] * grid.spacing[1];  // per unit thickness
  PointSet points;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = j * nx + i;  // x fastest (docs/output.md)
      points.x.push_back(grid.origin[0] + (static_cast<double>(i) + 0.5) * grid.spacing[0]);
      points.y.push_back(grid.origin[1] + (static_cast<double>(j) + 0.5) * grid.spacing[1]);
      points.products.push_back(products.values[c] * volume);
      points.air.push_back(air[c] * volume);
    }
  return points;
}

HandoffErrors handoff_errors(const std::filesystem::path& summary_json) {
  std::ifstream in(summary_json);
  const auto summary = nlohmann::json::parse(in);
  const auto& handoffs = summary.at("details").at("afdmp").at("handoffs");
  if (handoffs.empty())
    throw Error("handoff_errors: " + summary_json.string() + " lists no handoff");
  HandoffErrors out;
  double terms = 0;
  for (const auto& handoff : handoffs) {
    for (const auto& [comparison, errors] : handoff.at("relative_error").items())
      for (const auto& [quantity, error] : errors.items())
        out.worst = std::max(out.worst, error.get<double>());
    for (const char* count : {"cells", "particles", "tracers"})
      if (handoff.contains(count)) terms = std::max(terms, handoff.at(count).get<double>());
  }
  out.roundoff = 2.0 * std::max(terms - 1.0, 0.0) * std::ldexp(1.0, -53);
  return out;
}

GaugeColumn read_gauge_column(const std::filesystem::path& csv, const std::string& header) {
  std::ifstream in(csv);
  std::string line;
  if (!in || !std::getline(in, line)) throw Error("read_gauge_column: cannot read " + csv.string());
  const auto headers = split_csv(line);
  std::size_t column = headers.size();
  for (std::size_t c = 0; c < headers.size(); ++c)
    if (headers[c] == header) column = c;
  if (column == headers.size())
    throw Error("read_gauge_column: " + csv.string() + " has no column '" + header + "'");
  GaugeColumn out;
  while (std::getline(in, line)) {
    const auto cells = split_csv(line);
    out.time.push_back(std::stod(cells.at(0)));
    out.value.push_back(column < cells.size() && !cells[column].empty()
                            ? std::stod(cells[column])
                            : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

}  // namespace mpfd::verification
