// CfdmpStep's part of a coupled checkpoint (coupler_checkpoint.hpp): what the coupler
// carries from one step to the next, written after an output's exchange.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "coupler/run/cfdmp_step.hpp"

namespace mpfd::coupler {
namespace {

constexpr const char* kStepOwner = "step";

template <int Dim>
std::vector<double> flat_vectors(const std::vector<handshake::Vec<Dim>>& vectors) {
  std::vector<double> values(Dim * vectors.size());
  for (std::size_t i = 0; i < vectors.size(); ++i)
    for (int k = 0; k < Dim; ++k) values[Dim * i + static_cast<std::size_t>(k)] = vectors[i](k);
  return values;
}

template <int Dim>
std::vector<handshake::Vec<Dim>> vectors_of(const std::vector<double>& values) {
  std::vector<handshake::Vec<Dim>> out(values.size() / Dim);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < Dim; ++k) out[i](k) = values[Dim * i + static_cast<std::size_t>(k)];
  return out;
}

/// A face cell's share of a deposit as "/step/<name>": face cell, share, density,
/// taken back, particle mass (the face-drain watch's last two deposits).
void save_drain(RestartWriter& out, const std::string& name, const FaceDrain& drain) {
  out.array(kStepOwner, name,
            std::array<double, 5>{static_cast<double>(drain.face_cell), drain.share, drain.density,
                                  drain.taken_back, drain.particle_mass});
}

FaceDrain restored_drain(const RestartReader& in, const std::string& name) {
  const auto v = in.array(kStepOwner, name, 5);
  if (!(v[0] >= 0 && v[0] < 0x1p53 && v[0] == std::floor(v[0])))
    in.refuse("holds face cell " + std::to_string(v[0]) + " in /step/" + name +
              "; expected a whole number >= 0");
  return {.face_cell = static_cast<std::size_t>(v[0]),
          .share = v[1],
          .density = v[2],
          .taken_back = v[3],
          .particle_mass = v[4]};
}

}  // namespace

void save_totals(RestartWriter& out, const std::string& owner, const std::string& name,
                 const Totals& totals) {
  out.array(owner, name,
            std::array<double, 5>{totals.mass, totals.momentum[0], totals.momentum[1],
                                  totals.momentum[2], totals.energy});
}

Totals restored_totals(const RestartReader& in, const std::string& owner, const std::string& name) {
  const auto v = in.array(owner, name, 5);
  return {.mass = v[0], .momentum = {v[1], v[2], v[3]}, .energy = v[4]};
}

template <int Dim>
void CfdmpStep<Dim>::save(RestartWriter& out) const {
  if (!removed_mass_.empty() || flux_due_)
    throw Error("coupler checkpoint: taken between a step's advance and its deposit (" +
                std::to_string(removed_mass_.size()) +
                " removed particles wait); it belongs after an output's exchange");
  // How the parcels are booked depends on these: a restart must find the same.
  out.feature(kStepOwner, "fdm_face_crossing", features_.fdm_face_crossing);
  out.feature(kStepOwner, "fdm_outflow", features_.fdm_outflow);
  out.feature(kStepOwner, "mpm_outflow", features_.mpm_outflow);
  out.array(kStepOwner, "parcel_mass", parcels_.mass);
  out.array(kStepOwner, "parcel_momentum", flat_vectors<Dim>(parcels_.momentum));
  out.array(kStepOwner, "parcel_energy", parcels_.energy);
  out.array(kStepOwner, "parcel_volume", parcels_.volume);
  out.array(kStepOwner, "parcel_travel", parcels_.travel);
  out.number(kStepOwner, "next_id", static_cast<double>(next_id_));  // < 2^53: exact
  out.number(kStepOwner, "reference_mass", rule_.reference_mass);
  out.number(kStepOwner, "min_particle_mass", rule_.min_particle_mass);
  out.number(kStepOwner, "min_particle_volume", rule_.min_particle_volume);
  out.number(kStepOwner, "have_ghost_source", have_ghost_source_ ? 1 : 0);
  out.array(kStepOwner, "ghost_node_mass", ghost_node_mass_);
  out.array(kStepOwner, "ghost_node_momentum", flat_vectors<Dim>(ghost_node_momentum_));
  out.array(kStepOwner, "ghost_cell_energy", ghost_cell_energy_);
  save_totals(out, kStepOwner, "dormant_outflow", dormant_outflow_);
  out.number(kStepOwner, "max_face_drain_share", drain_.run_max_share());
  save_drain(out, "face_drain_last", drain_.last());
  save_drain(out, "face_drain_previous", drain_.previous());
}

template <int Dim>
void CfdmpStep<Dim>::restore(const RestartReader& in) {
  in.expect_feature(kStepOwner, "fdm_face_crossing", features_.fdm_face_crossing);
  in.expect_feature(kStepOwner, "fdm_outflow", features_.fdm_outflow);
  in.expect_feature(kStepOwner, "mpm_outflow", features_.mpm_outflow);
  const std::size_t faces = parcels_.size();
  handshake::Parcels<Dim> parcels(faces);
  parcels.mass = in.array(kStepOwner, "parcel_mass", faces);
  parcels.momentum = vectors_of<Dim>(in.array(kStepOwner, "parcel_momentum", Dim * faces));
  parcels.energy = in.array(kStepOwner, "parcel_energy", faces);
  parcels.volume = in.array(kStepOwner, "parcel_volume", faces);
  parcels.travel = in.array(kStepOwner, "parcel_travel", faces);
  const bool ghost_source = in.number(kStepOwner, "have_ghost_source") != 0;
  const std::size_t nodes = ghost_source ? ghost_nodes_.count() : 0;
  auto ghost_mass = in.array(kStepOwner, "ghost_node_mass", nodes);
  auto ghost_momentum = in.array(kStepOwner, "ghost_node_momentum", Dim * nodes);
  auto ghost_energy =
      in.array(kStepOwner, "ghost_cell_energy", ghost_source ? ghost_cells_.count() : 0);
  handshake::InjectionRule rule{
      .reference_mass = in.number(kStepOwner, "reference_mass"),
      .min_particle_mass = in.number(kStepOwner, "min_particle_mass"),
      .min_particle_volume = in.number(kStepOwner, "min_particle_volume")};
  if (rule.reference_mass != 0.0) rule.check();
  const Totals dormant_outflow = restored_totals(in, kStepOwner, "dormant_outflow");
  const double drain_share = in.number(kStepOwner, "max_face_drain_share");
  const FaceDrain drain_last = restored_drain(in, "face_drain_last");
  const FaceDrain drain_previous = restored_drain(in, "face_drain_previous");
  const double next_id = in.number(kStepOwner, "next_id");
  if (!(next_id >= 0 && next_id < 0x1p53))
    in.refuse("holds next_id " + std::to_string(next_id) +
              "; expected a whole number in [0, 2^53)");
  // Read whole before anything changes.
  parcels_ = std::move(parcels);
  rule_ = rule;
  next_id_ = static_cast<std::uint64_t>(next_id);
  have_ghost_source_ = ghost_source;
  ghost_node_mass_ = std::move(ghost_mass);
  ghost_node_momentum_ = vectors_of<Dim>(ghost_momentum);
  ghost_cell_energy_ = std::move(ghost_energy);
  dormant_outflow_ = dormant_outflow;
  drain_.resume(drain_last, drain_previous, drain_share);
}

template void CfdmpStep<1>::save(RestartWriter&) const;
template void CfdmpStep<2>::save(RestartWriter&) const;
template void CfdmpStep<3>::save(RestartWriter&) const;
template void CfdmpStep<1>::restore(const RestartReader&);
template void CfdmpStep<2>::restore(const RestartReader&);
template void CfdmpStep<3>::restore(const RestartReader&);

}  // namespace mpfd::coupler
