#pragma once
// The particle fields of an MPM snapshot (docs/output.md): views of the
// particle arrays, plus the few derived ones (Cauchy stress components,
// indices and burn fraction as numbers) held in scratch owned here.

#include <vector>

#include "common/io/field_view.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {

class SnapshotParticles {
 public:
  /// The fields of the solver's particles now; valid until the next call or step.
  std::vector<io::FieldView> views(const MpmSolver& solver);

 private:
  std::array<std::vector<double>, 6> stress_;
  std::vector<double> material_, body_, burn_;
};

}  // namespace mpfd::mpm
