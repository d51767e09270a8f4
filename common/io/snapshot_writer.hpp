#pragma once
// Field snapshots: one HDF5 file per output time under <out>/snapshots/, and
// XDMF sidecars (<out>/cells.xmf, <out>/particles.xmf) listing every snapshot
// as a time series so that ParaView opens cells and particles directly.
// Layout and units: docs/output.md.

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "common/io/field_view.hpp"

namespace mpfd::io {

class SnapshotWriter {
 public:
  /// `grid` describes the cell fields; `out_dir` must exist.
  SnapshotWriter(std::filesystem::path out_dir, const grid::UniformGrid& grid);

  /// Writes snapshot number `index()` at `time` and refreshes the sidecars.
  /// Cell fields have grid.cell_count() values per component. Particle
  /// fields, if any, must include "position" (3 components, m) and all have
  /// the same length. Returns the file written.
  std::filesystem::path write(std::int64_t step, double time, const std::vector<FieldView>& cells,
                              const std::vector<FieldView>& particles = {});

  [[nodiscard]] int index() const { return static_cast<int>(entries_.size()); }

  /// The series written so far, as text (JSON) that a restart state keeps.
  [[nodiscard]] std::string history() const;
  /// Continues the series `history` (history() of an earlier writer over the same
  /// folder): the next write() is snapshot number N, and the sidecars list the N
  /// before it. A restart must not number its snapshots from 0 over the earlier
  /// ones. Throws mpfd::Error naming what is malformed (check_history first, to
  /// refuse before anything changes).
  void resume(const std::string& history);
  /// Throws what resume(history) would for a malformed `history`; changes nothing.
  static void check_history(const std::string& history);
  /// True for the history of a writer that wrote nothing.
  [[nodiscard]] static bool empty_history(const std::string& history);

 private:
  struct Entry {
    std::string file;  // relative to out_dir_
    double time;
    std::vector<std::pair<std::string, int>> cell_fields;      // name, components
    std::vector<std::pair<std::string, int>> particle_fields;  // name, components
    std::size_t particle_count;
  };
  void write_sidecars() const;
  [[nodiscard]] static std::vector<Entry> parse_history(const std::string& history);

  std::filesystem::path out_dir_;
  grid::UniformGrid grid_;
  std::vector<Entry> entries_;
  std::vector<double> interleaved_;  // scratch for vector fields, reused
};

}  // namespace mpfd::io
