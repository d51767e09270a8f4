#include "fdm_solver/snapshot_fields.hpp"

#include <algorithm>
#include <span>

#include "common/core/error.hpp"

namespace mpfd::fdm {
namespace {

constexpr const char* kWritten[] = {
    "density",     "velocity", "pressure",       "specific_internal_energy",
    "sound_speed", "material", "volume_fraction"};

}  // namespace

std::string field_name(config::Field field) {
  switch (field) {
    case config::Field::density:
      return "density";
    case config::Field::velocity:
      return "velocity";
    case config::Field::pressure:
      return "pressure";
    case config::Field::specific_internal_energy:
      return "specific_internal_energy";
    case config::Field::sound_speed:
      return "sound_speed";
    case config::Field::material:
      return "material";
    case config::Field::volume_fraction:
      return "volume_fraction";
    case config::Field::burn_fraction:
      return "burn_fraction";
  }
  return "unknown";
}

void check_field_name(const std::string& name) {
  std::string known;
  for (const char* k : kWritten) {
    if (name == k) return;
    known += (known.empty() ? "" : ", ") + std::string(k);
  }
  throw Error("fdm_solver does not write the cell field '" + name + "'; it writes " + known +
              (name == "burn_fraction" ? " (burn_fraction is an MPM particle field)" : ""));
}

SnapshotFields::SnapshotFields(const EulerSolver& solver, const std::vector<std::string>& names) {
  for (const auto& name : names) check_field_name(name);
  // A one-material scene's volume fraction is 1 everywhere: one array, only if asked for.
  if (!solver.tracker() && std::find(names.begin(), names.end(), "volume_fraction") != names.end())
    ones_.assign(solver.state().grid.cell_count(), 1.0);
}

std::vector<io::FieldView> SnapshotFields::views(const std::vector<std::string>& names,
                                                 const config::Scene& scene,
                                                 const EulerSolver& solver,
                                                 const PrimitiveFields& p) const {
  const EulerState& state = solver.state();
  std::vector<io::FieldView> out;
  for (const auto& name : names) {
    if (name == "density") out.push_back({name, "kg/m^3", {state.u[kDensity]}});
    if (name == "velocity")
      out.push_back({name, "m/s", {p.velocity_x, p.velocity_y, p.velocity_z}});
    if (name == "pressure") out.push_back({name, "Pa", {p.pressure}});
    if (name == "specific_internal_energy")
      out.push_back({name, "J/kg", {p.specific_internal_energy}});
    if (name == "sound_speed") out.push_back({name, "m/s", {p.sound_speed}});
    if (name == "material") out.push_back({name, "", {p.material}});
    if (name == "volume_fraction") {
      // theta_r of T (3-23) per material; 1 everywhere in a one-material scene.
      const std::size_t cells = state.grid.cell_count();
      for (std::size_t r = 0; r < scene.materials.size(); ++r) {
        std::span<const double> theta(ones_);
        if (const auto* tracker = solver.tracker())
          theta = std::span<const double>(tracker->materials().theta).subspan(r * cells, cells);
        out.push_back({"volume_fraction_" + scene.materials[r].name, "", {theta}});
      }
    }
  }
  return out;
}

}  // namespace mpfd::fdm
