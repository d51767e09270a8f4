#pragma once
// The cell fields fdm_solver writes into a snapshot, by their names in
// docs/output.md: density, velocity, pressure, specific_internal_energy,
// sound_speed, material, and volume_fraction (one dataset
// volume_fraction_<material> per material, T (3-23)). Shared by `run` and
// `serve` so both write the same layout.

#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/io/field_view.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/primitive_fields.hpp"

namespace mpfd::fdm {

/// The docs/output.md name of a scene output field.
[[nodiscard]] std::string field_name(config::Field field);

/// Throws mpfd::Error naming `name` and the fields fdm_solver writes unless
/// it is one of them.
void check_field_name(const std::string& name);

/// Views of the named fields; `primitives` must be computed from the solver's
/// state. Valid while the solver, the primitives and this object live.
class SnapshotFields {
 public:
  /// Checks every name (check_field_name) once, up front.
  SnapshotFields(const EulerSolver& solver, const std::vector<std::string>& names);
  [[nodiscard]] std::vector<io::FieldView> views(const std::vector<std::string>& names,
                                                 const config::Scene& scene,
                                                 const EulerSolver& solver,
                                                 const PrimitiveFields& primitives) const;

 private:
  std::vector<double> ones_;  // volume fraction of a one-material scene
};

}  // namespace mpfd::fdm
