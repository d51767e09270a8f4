#include "common/io/snapshot_writer.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/xdmf.hpp"

namespace mpfd::io {
namespace {

void check_field(const FieldView& f, std::size_t count, const char* kind) {
  if (f.components.size() != 1 && f.components.size() != 3)
    throw Error(std::string(kind) + " field '" + f.name + "' has " +
                std::to_string(f.components.size()) + " components; expected 1 or 3");
  for (const auto& c : f.components)
    if (c.size() != count)
      throw Error(std::string(kind) + " field '" + f.name + "' has " + std::to_string(c.size()) +
                  " values per component; expected " + std::to_string(count));
}

/// Writes one field, interleaving vector components into `scratch`.
void write_field(Hdf5File& file, const std::string& group, const FieldView& f,
                 std::vector<std::size_t> shape, std::vector<double>& scratch) {
  const std::string path = group + "/" + f.name;
  if (f.components.size() == 1) {
    file.write_dataset(path, f.components[0], shape, f.units);
    return;
  }
  const std::size_t n = f.components[0].size();
  scratch.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) scratch[3 * i + c] = f.components[c][i];
  shape.push_back(3);
  file.write_dataset(path, scratch, shape, f.units);
}

std::vector<XdmfStep> steps_of(const auto& entries, bool particles) {
  std::vector<XdmfStep> steps;
  for (const auto& e : entries) {
    if (particles && e.particle_fields.empty()) continue;
    steps.push_back(
        {e.file, e.time, particles ? e.particle_fields : e.cell_fields, e.particle_count});
  }
  return steps;
}

/// The file of snapshot number `index`, relative to the output folder.
std::string snapshot_name(int index) {
  char name[40];
  std::snprintf(name, sizeof name, "snapshots/snapshot_%06d.h5", index);
  return name;
}

using FieldList = std::vector<std::pair<std::string, int>>;

nlohmann::json fields_json(const FieldList& fields) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, components] : fields) list.push_back({name, components});
  return list;
}

FieldList fields_of(const nlohmann::json& list) {
  FieldList fields;
  for (const auto& field : list) {
    const int components = field.at(1).get<int>();
    if (components != 1 && components != 3)
      throw Error("field '" + field.at(0).get<std::string>() + "' with " +
                  std::to_string(components) + " components; expected 1 or 3");
    fields.emplace_back(field.at(0).get<std::string>(), components);
  }
  return fields;
}

}  // namespace

SnapshotWriter::SnapshotWriter(std::filesystem::path out_dir, const grid::UniformGrid& grid)
    : out_dir_(std::move(out_dir)), grid_(grid) {
  std::filesystem::create_directories(out_dir_ / "snapshots");
}

std::filesystem::path SnapshotWriter::write(std::int64_t step, double time,
                                            const std::vector<FieldView>& cells,
                                            const std::vector<FieldView>& particles) {
  const std::size_t cell_count = grid_.cell_count();
  for (const auto& f : cells) check_field(f, cell_count, "cell");
  std::size_t particle_count = 0;
  if (!particles.empty()) {
    const FieldView* position = nullptr;
    for (const auto& f : particles)
      if (f.name == "position") position = &f;
    if (position == nullptr || position->components.size() != 3)
      throw Error("particle fields must include 'position' with 3 components");
    particle_count = position->components[0].size();
    for (const auto& f : particles) check_field(f, particle_count, "particle");
  }

  const std::string name = snapshot_name(index());
  const std::filesystem::path file = out_dir_ / name;
  const auto& n = grid_.cells();
  const std::vector<std::size_t> cell_shape{static_cast<std::size_t>(n[2]),
                                            static_cast<std::size_t>(n[1]),
                                            static_cast<std::size_t>(n[0])};
  write_path_atomically(file, [&](const std::filesystem::path& partial) {
    Hdf5File h5(partial, Hdf5File::Mode::create);
    h5.write_attribute("/", "format", std::string("mpfd-snapshot"));
    h5.write_attribute("/", "format_version", std::int64_t{kOutputFormatVersion});
    h5.write_attribute("/", "time", time);
    h5.write_attribute("/", "step", std::int64_t{step});
    h5.create_group("/grid");
    h5.write_attribute("/grid", "origin", grid_.origin());
    h5.write_attribute("/grid", "spacing", grid_.spacing());
    const std::array<double, 3> counts{double(n[0]), double(n[1]), double(n[2])};
    h5.write_attribute("/grid", "cells", counts);
    if (!cells.empty()) h5.create_group("/cells");
    for (const auto& f : cells) write_field(h5, "/cells", f, cell_shape, interleaved_);
    if (!particles.empty()) h5.create_group("/particles");
    for (const auto& f : particles)
      write_field(h5, "/particles", f, {particle_count}, interleaved_);
  });

  Entry entry{name, time, {}, {}, particle_count};
  for (const auto& f : cells) entry.cell_fields.emplace_back(f.name, int(f.components.size()));
  for (const auto& f : particles)
    entry.particle_fields.emplace_back(f.name, int(f.components.size()));
  entries_.push_back(std::move(entry));
  write_sidecars();
  return file;
}

std::string SnapshotWriter::history() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& e : entries_)
    list.push_back({{"file", e.file},
                    {"time", e.time},
                    {"cell_fields", fields_json(e.cell_fields)},
                    {"particle_fields", fields_json(e.particle_fields)},
                    {"particle_count", e.particle_count}});
  return list.dump();
}

std::vector<SnapshotWriter::Entry> SnapshotWriter::parse_history(const std::string& history) {
  std::vector<Entry> entries;
  try {
    const nlohmann::json list = nlohmann::json::parse(history);
    if (!list.is_array()) throw Error("not a list");
    for (const auto& e : list) {
      const std::string name = snapshot_name(static_cast<int>(entries.size()));
      if (e.at("file").get<std::string>() != name)
        throw Error("entry " + std::to_string(entries.size()) + " names '" +
                    e.at("file").get<std::string>() + "', expected '" + name + "'");
      entries.push_back({name, e.at("time").get<double>(), fields_of(e.at("cell_fields")),
                         fields_of(e.at("particle_fields")),
                         e.at("particle_count").get<std::size_t>()});
    }
  } catch (const std::exception& error) {
    throw Error("snapshot series to resume: " + std::string(error.what()));
  }
  return entries;
}

void SnapshotWriter::check_history(const std::string& history) {
  (void)parse_history(history);
}

bool SnapshotWriter::empty_history(const std::string& history) {
  return history == "[]";
}

void SnapshotWriter::resume(const std::string& history) {
  entries_ = parse_history(history);
  if (!entries_.empty()) write_sidecars();
}

void SnapshotWriter::write_sidecars() const {
  const auto cell_steps = steps_of(entries_, false);
  write_file_atomically(out_dir_ / "cells.xmf",
                        [&](std::ostream& out) { out << cells_xdmf(grid_, cell_steps); });
  const auto particle_steps = steps_of(entries_, true);
  if (!particle_steps.empty())
    write_file_atomically(out_dir_ / "particles.xmf",
                          [&](std::ostream& out) { out << particles_xdmf(particle_steps); });
}

}  // namespace mpfd::io
