#pragma once
// Building and reading the operations of an Exchange (proto/README.md §6):
// one function per operation, and the conversions between the wire's 3-axis
// boxes and [n, 3] vectors and the handshake kernels' Dim-axis ones.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/message.hpp"
#include "coupler/handshake/index_box.hpp"
#include "coupler/run/zone_layout.hpp"

namespace mpfd::coupler {

namespace v1 = cosim::v1;

v1::Exchange& exchange_of(cosim::Message& message);
/// Empties an Exchange request for the next step's add_* and keeps its memory
/// (descriptors, operations and their bodies, strings): once a step of the same
/// kinds of operations has been built, building it again allocates nothing.
void clear_for_reuse(cosim::Message& message);
/// The next operation of an Exchange, for the add_* below and any new kind: a
/// parked one of `kind` if there is one (its body kept and emptied), else a new one.
v1::Operation& next_operation(cosim::Message& message, v1::Operation::OpCase kind);
void add_apply(cosim::Message& message, std::string_view region, v1::ApplyRegion::Mode mode);
void add_export(cosim::Message& message, std::string_view region,
                std::initializer_list<const char*> quantities = {});
void add_advance(cosim::Message& message, double dt, double time);
void add_propose_dt(cosim::Message& message);
void add_inject(cosim::Message& message, std::string_view group);
void add_remove(cosim::Message& message, std::string_view group, std::string_view left_region);

/// A Region of Setup: `kind`, `box`, and `quantities`.
v1::Region make_region(std::string_view name, v1::RegionKind kind, const WireBox& box,
                       std::initializer_list<const char*> quantities);

/// The Dim-axis box of a wire box (its active axes, in order).
template <int Dim>
handshake::IndexBox<Dim> to_kernel_box(const WireBox& box, const ZoneLayout& layout) {
  handshake::IndexBox<Dim> out;
  for (int d = 0; d < Dim; ++d) {
    out.lo[d] = box.lo[layout.active[d]];
    out.hi[d] = box.hi[layout.active[d]];
  }
  return out;
}

/// Vectors [n, 3] of the wire -> Dim-axis vectors (inactive components dropped).
template <int Dim>
void from_wire_vectors(std::span<const double> wire, const ZoneLayout& layout,
                       std::vector<handshake::Vec<Dim>>& out) {
  out.resize(wire.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int d = 0; d < Dim; ++d) out[i](d) = wire[3 * i + layout.active[d]];
}

/// Dim-axis vectors -> [n, 3] in `wire` (inactive components set to `fill[axis]`);
/// returns it. `wire` is the caller's scratch: once large enough it is not reallocated.
template <int Dim>
std::span<const double> to_wire_vectors(std::span<const handshake::Vec<Dim>> vectors,
                                        const ZoneLayout& layout, const std::array<double, 3>& fill,
                                        std::vector<double>& wire) {
  wire.resize(3 * vectors.size());
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    for (int a = 0; a < 3; ++a) wire[3 * i + a] = fill[a];
    for (int d = 0; d < Dim; ++d) wire[3 * i + layout.active[d]] = vectors[i](d);
  }
  return wire;
}

/// Throws mpfd::Error naming the peer, step and array unless `got` == `expected` values.
void check_value_count(const cosim::Message& reply, std::string_view peer, std::string_view group,
                       std::string_view name, std::size_t got, std::size_t expected);

/// Array `group`/`name` of a reply (F64), checked to hold `values` entries,
/// copied into `out` (reusing its memory).
void read_doubles(const cosim::Message& reply, std::string_view peer, std::string_view group,
                  std::string_view name, std::size_t values, std::vector<double>& out);

/// Array `group`/`name` of a reply (F64, [count, 3]) as Dim-axis vectors in `out`.
template <int Dim>
void read_wire_vectors(const cosim::Message& reply, std::string_view peer, std::string_view group,
                       std::string_view name, std::size_t count, const ZoneLayout& layout,
                       std::vector<handshake::Vec<Dim>>& out) {
  const auto view = cosim::view_array<double>(reply, group, name);
  check_value_count(reply, peer, group, name, view.values().size(), 3 * count);
  from_wire_vectors<Dim>(view.values(), layout, out);
}

/// The result of operation `index` of an ExchangeResult; throws mpfd::Error
/// naming the peer if the reply has fewer results or is no ExchangeResult.
const v1::OperationResult& result_of(const cosim::Message& reply, std::string_view peer, int index);

}  // namespace mpfd::coupler
