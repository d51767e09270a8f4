#pragma once
// The arrays a handshake kernel reads or writes, one span per quantity (the
// protocol's standard names, proto/README.md §3): FDM cells carry rho (kg/m^3),
// momentum ρv (kg/(m^2 s)) and E (J/m^3); MPM nodes mass (kg), momentum (kg m/s)
// and internal_force (N). All spans of one struct have the same length.

#include <cstddef>
#include <span>

#include "coupler/handshake/index_box.hpp"

namespace mpfd::coupler::handshake {

/// Throws mpfd::Error "<what>: <quantity> must have <expected> entries, got <got>".
void require_length(std::size_t got, std::size_t expected, const char* what, const char* quantity);

template <int Dim>
struct CellStates {
  std::span<const double> rho;
  std::span<const Vec<Dim>> momentum;
  std::span<const double> energy;

  [[nodiscard]] std::size_t size() const { return rho.size(); }
};

template <int Dim>
struct CellOutputs {
  std::span<double> rho;
  std::span<Vec<Dim>> momentum;
  std::span<double> energy;

  [[nodiscard]] std::size_t size() const { return rho.size(); }
};

template <int Dim>
struct NodeOutputs {
  std::span<double> mass;
  std::span<Vec<Dim>> momentum;
  std::span<Vec<Dim>> internal_force;

  [[nodiscard]] std::size_t size() const { return mass.size(); }
};

template <int Dim>
void require_node_lengths(const NodeOutputs<Dim>& nodes, std::size_t n, const char* what) {
  require_length(nodes.mass.size(), n, what, "mass");
  require_length(nodes.momentum.size(), n, what, "momentum");
  require_length(nodes.internal_force.size(), n, what, "internal_force");
}

/// Throws mpfd::Error naming `what` unless every span of `fields` has `n` entries.
template <class Fields>
void require_lengths(const Fields& fields, std::size_t n, const char* what) {
  require_length(fields.rho.size(), n, what, "rho");
  require_length(fields.momentum.size(), n, what, "momentum");
  require_length(fields.energy.size(), n, what, "E");
}

}  // namespace mpfd::coupler::handshake
