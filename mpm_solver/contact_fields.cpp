#include "mpm_solver/contact_fields.hpp"

namespace mpfd::mpm {

void ContactFields::compact() {
  node_of.clear();
  for (std::size_t n = 0; n < shared.size(); ++n) {
    if (shared[n] == bodies) {
      shared[n] = static_cast<std::int32_t>(node_of.size());
      node_of.push_back(n);
    } else {
      shared[n] = -1;
    }
  }
  const std::size_t entries = node_of.size() * static_cast<std::size_t>(bodies);
  mass.assign(entries, 0.0);
  for (auto* field : {&momentum, &gradient, &force, &remapped})
    for (auto& a : *field) a.assign(entries, 0.0);
}

}  // namespace mpfd::mpm
