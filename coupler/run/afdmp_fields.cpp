#include "coupler/run/afdmp_fields.hpp"

#include <algorithm>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "coupler/handoff/sub_grid.hpp"

namespace mpfd::coupler {
namespace {

/// An array of `region` holding `rows` x `width` values of T; throws naming it otherwise.
template <typename T>
cosim::ArrayView<T> view_rows(const cosim::Message& fields, std::string_view region,
                              std::string_view name, std::size_t rows, std::size_t width) {
  const auto& descriptor = cosim::find_descriptor(fields, region, name);
  std::size_t values = 1;
  for (const auto extent : descriptor.shape()) values *= extent;
  if (values != rows * width)
    throw Error("field '" + std::string(region) + "/" + std::string(name) + "' holds " +
                std::to_string(values) + " values; expected " + std::to_string(rows) + " x " +
                std::to_string(width));
  return cosim::ArrayView<T>(descriptor, fields.frames.at(descriptor.frame_index()));
}

std::size_t rows_of(const cosim::Message& fields, std::string_view region, std::string_view name) {
  const auto& descriptor = cosim::find_descriptor(fields, region, name);
  return descriptor.shape_size() == 0 ? 0 : descriptor.shape(0);
}

bool has_array(const cosim::Message& fields, std::string_view region, std::string_view name) {
  const auto& arrays = fields.header.arrays();
  return std::any_of(arrays.begin(), arrays.end(),
                     [&](const auto& a) { return a.group() == region && a.name() == name; });
}

std::vector<int> materials_from_wire(std::span<const std::uint32_t> wire) {
  std::vector<int> out(wire.size());
  std::transform(wire.begin(), wire.end(), out.begin(),
                 [](std::uint32_t m) { return static_cast<int>(m); });
  return out;
}

void add_materials(std::span<const int> materials, std::string_view region, cosim::Message& out) {
  std::vector<std::uint32_t> wire(materials.size());
  std::transform(materials.begin(), materials.end(), wire.begin(),
                 [](int m) { return static_cast<std::uint32_t>(m); });
  cosim::add_array(out, {region, "material", {}, "1"}, std::move(wire));
}

std::vector<double> interleave(const std::array<std::span<const double>, 3>& components) {
  const std::size_t n = components[0].size();
  std::vector<double> out(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < 3; ++a) out[3 * i + a] = components[a][i];
  return out;
}

template <typename Vector>
std::array<std::span<const double>, 3> spans(const std::array<Vector, 3>& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<std::string> field_names(std::string_view region,
                                     std::initializer_list<const char*> quantities) {
  std::vector<std::string> names;
  for (const char* q : quantities) names.push_back(std::string(region) + "/" + q);
  return names;
}

handoff::ParticleSet particles_from_wire(const cosim::Message& fields, std::string_view region) {
  const std::size_t n = rows_of(fields, region, "mass");
  handoff::ParticleSet particles;
  particles.resize(n);
  const auto position = view_rows<double>(fields, region, "position", n, 3);
  const auto velocity = view_rows<double>(fields, region, "velocity", n, 3);
  const auto mass = view_rows<double>(fields, region, "mass", n, 1);
  const auto energy = view_rows<double>(fields, region, "internal_energy", n, 1);
  const auto material = view_rows<std::uint32_t>(fields, region, "material", n, 1);
  if (has_array(fields, region, "volume")) {
    const auto volume = view_rows<double>(fields, region, "volume", n, 1);
    std::copy(volume.values().begin(), volume.values().end(), particles.volume.begin());
  }
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t a = 0; a < 3; ++a) {
      particles.position[a][p] = position.values()[3 * p + a];
      particles.velocity[a][p] = velocity.values()[3 * p + a];
    }
    particles.mass[p] = mass.values()[p];
    particles.internal_energy[p] = energy.values()[p];
    particles.material[p] = static_cast<int>(material.values()[p]);
  }
  return particles;
}

void add_cells_to_wire(const grid::UniformGrid& grid, const handoff::ConservedView& cells,
                       std::string_view region, cosim::Message& out) {
  const std::size_t n = grid.cell_count();
  handoff::check_sizes(cells, n);
  std::vector<double> rho(n), momentum(3 * n), energy(n);
  handoff::grid_to_wire_order(grid.cells(), cells.density, rho);
  handoff::grid_to_wire_vectors(grid.cells(), cells.momentum, momentum);
  handoff::grid_to_wire_order(grid.cells(), cells.total_energy, energy);
  cosim::add_array(out, {region, "rho", {}, "kg/m^3"}, std::move(rho));
  cosim::add_array(out, {region, "momentum", {n, 3}, "kg/(m^2*s)"}, std::move(momentum));
  cosim::add_array(out, {region, "E", {}, "J/m^3"}, std::move(energy));
}

void add_material_start_to_wire(const grid::UniformGrid& grid, const handoff::MaterialStart& start,
                                std::string_view region, cosim::Message& out) {
  const std::size_t n = grid.cell_count();
  const auto width = static_cast<std::size_t>(start.material_count);
  struct Field {
    const std::vector<double>* values;
    const char* name;
    const char* unit;
  };
  const Field fields[] = {{&start.volume_fraction, "volume_fraction", "1"},
                          {&start.density, "material_density", "kg/m^3"},
                          {&start.energy, "material_energy", "J/kg"}};
  for (const auto& [values, name, unit] : fields) {
    if (values->size() != n * width)
      throw Error("material start '" + std::string(name) + "' has " +
                  std::to_string(values->size()) + " values; expected " + std::to_string(n) +
                  " cells x " + std::to_string(width) + " materials");
    std::vector<double> wire(n * width);
    handoff::grid_to_wire_order(grid.cells(), *values, wire, start.material_count);
    cosim::add_array(out, {region, name, {n, width}, unit}, std::move(wire));
  }
}

void add_tracers_to_wire(const handoff::TracerView& tracers, std::string_view region,
                         cosim::Message& out) {
  handoff::check_sizes(tracers);
  const std::size_t n = tracers.size();
  cosim::add_array(out, {region, "position", {n, 3}, "m"}, interleave(tracers.position));
  add_materials(tracers.material, region, out);
}

void add_particles_to_wire(const handoff::ParticleSet& particles, std::uint64_t first_id,
                           std::string_view region, cosim::Message& out) {
  const std::size_t n = particles.size();
  std::vector<std::uint64_t> id(n);
  for (std::size_t p = 0; p < n; ++p) id[p] = first_id + p;
  std::vector<double> stress(6 * n, 0.0);  // Voigt xx, yy, zz, yz, xz, xy: -p I, T (3-17)
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t c = 0; c < 3; ++c) stress[6 * p + c] = -particles.pressure[p];
  cosim::add_array(out, {region, "id", {}, "1"}, std::move(id));
  cosim::add_array(out, {region, "position", {n, 3}, "m"}, interleave(spans(particles.position)));
  cosim::add_array(out, {region, "velocity", {n, 3}, "m/s"}, interleave(spans(particles.velocity)));
  cosim::add_array(out, {region, "mass", {}, "kg"}, std::span<const double>(particles.mass));
  cosim::add_array(out, {region, "volume", {}, "m^3"}, std::span<const double>(particles.volume));
  cosim::add_array(out, {region, "internal_energy", {}, "J"},
                   std::span<const double>(particles.internal_energy));
  add_materials(particles.material, region, out);
  cosim::add_array(out, {region, "stress", {n, 6}, "Pa"}, std::move(stress));
}

FdmEndFields::FdmEndFields(const grid::UniformGrid& grid, const cosim::Message& fields,
                           std::string_view cell_region, std::string_view tracer_region) {
  const std::size_t n = grid.cell_count();
  const grid::Index3& cells = grid.cells();
  cells_.assign(n);
  handoff::wire_to_grid_order(cells, view_rows<double>(fields, cell_region, "rho", n, 1).values(),
                              cells_.density);
  handoff::wire_to_grid_vectors(cells,
                                view_rows<double>(fields, cell_region, "momentum", n, 3).values(),
                                {cells_.momentum[0], cells_.momentum[1], cells_.momentum[2]});
  handoff::wire_to_grid_order(cells, view_rows<double>(fields, cell_region, "E", n, 1).values(),
                              cells_.total_energy);
  pressure_.resize(n);
  handoff::wire_to_grid_order(
      cells, view_rows<double>(fields, cell_region, "pressure", n, 1).values(), pressure_);
  cell_material_.resize(n);
  handoff::wire_to_grid_order(
      cells, view_rows<std::int32_t>(fields, cell_region, "cell_material", n, 1).values(),
      cell_material_);
  const auto& fractions = cosim::find_descriptor(fields, cell_region, "volume_fraction");
  material_count_ = fractions.shape_size() == 2 ? static_cast<int>(fractions.shape(1)) : 0;
  const auto m = static_cast<std::size_t>(material_count_);
  const auto per_material = [&](const char* name, std::vector<double>& out) {
    out.resize(n * m);
    handoff::wire_to_grid_order(cells, view_rows<double>(fields, cell_region, name, n, m).values(),
                                out, material_count_);
  };
  per_material("volume_fraction", volume_fraction_);
  per_material("material_density", material_density_);
  per_material("material_energy", material_energy_);

  const std::size_t t = rows_of(fields, tracer_region, "material");
  const auto position = view_rows<double>(fields, tracer_region, "position", t, 3);
  for (std::size_t a = 0; a < 3; ++a) tracers_.position[a].resize(t);
  for (std::size_t i = 0; i < t; ++i)
    for (std::size_t a = 0; a < 3; ++a) tracers_.position[a][i] = position.values()[3 * i + a];
  tracers_.material = materials_from_wire(
      view_rows<std::uint32_t>(fields, tracer_region, "material", t, 1).values());
}

handoff::FdmEnd FdmEndFields::view() const {
  return {.cells = cells_.view(),
          .pressure = pressure_,
          .cell_material = cell_material_,
          .material_count = material_count_,
          .volume_fraction = volume_fraction_,
          .material_density = material_density_,
          .material_energy = material_energy_,
          .tracers = tracers_.view()};
}

}  // namespace mpfd::coupler
