#pragma once
// What a solver hands to the writers: a named field, its units, and one
// contiguous array per component (structure of arrays, as the solvers store
// them). Scalars have one component, vectors three.

#include <span>
#include <string>
#include <vector>

namespace mpfd::io {

struct FieldView {
  std::string name;
  std::string units;
  std::vector<std::span<const double>> components;
};

}  // namespace mpfd::io
