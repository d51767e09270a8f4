// The MpmSolver members a coupler uses (mpm_solver.hpp, "Coupling"):
// particle injection and removal, nodal state and contributions, restore.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "mpm_solver/material/shear_modulus.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

/// Throws naming `which()` unless x is finite and, on an active axis a, on the
/// grid [origin, upper): a particle off it has no nodes to map to.
template <class Which>
void require_on_grid(const grid::UniformGrid& g, double x, int a, const Which& which) {
  const double upper = g.upper()[a];
  if (!std::isfinite(x) || (g.is_active(a) && (x < g.origin()[a] || x >= upper)))
    throw Error(which() + ": position " + std::to_string(x) + " m on axis " + std::to_string(a) +
                " is off the grid [" + std::to_string(g.origin()[a]) + ", " +
                std::to_string(upper) + ")");
}

}  // namespace

ConstitutiveModel& MpmSolver::model_for(std::size_t material) {
  if (!models_[material]) {
    auto model = make_constitutive_model(materials_[material]);
    const auto stride = static_cast<std::size_t>(model->history_count());
    if (stride > particles_.history_stride) {  // re-lay the history at the wider stride
      const std::size_t old = particles_.history_stride;
      std::vector<double> wider(particles_.size() * stride, 0.0);
      for (std::size_t p = 0; p < particles_.size(); ++p)
        std::copy_n(particles_.history.begin() + static_cast<std::ptrdiff_t>(p * old), old,
                    wider.begin() + static_cast<std::ptrdiff_t>(p * stride));
      particles_.history = std::move(wider);
      particles_.history_stride = stride;
    }
    models_[material] = std::move(model);
  }
  return *models_[material];
}

void MpmSolver::refuse_unsupported_coupling(const char* what) const {
  // Contact keeps per-body nodal fields, and a coupler's loads act on the summed
  // field only: that would be wrong.
  if (contact_)
    throw Error(std::string("mpm: ") + what +
                " from a coupler in a zone with contact between bodies is not supported yet; "
                "remove solver.mpm.contact from the MPM zone's scene");
}

std::uint16_t MpmSolver::injected_body(std::size_t material) {
  for (std::size_t b = scene_bodies_; b < bodies_.size(); ++b)
    if (bodies_[b].material == material) return static_cast<std::uint16_t>(b);
  constexpr int per_axis = 2;  // T §4.3: 2 x 2 x 2 particles per injected cell (4-15)
  BodyInfo body;
  body.name = "injected " + materials_[material].name;
  body.material = material;
  body.particles_per_axis = per_axis;
  for (int a = 0; a < 3; ++a) body.half_width[a] = grid().is_active(a) ? 0.5 / per_axis : 0.5;
  body.characteristic_length = min_spacing_ / per_axis;
  body.burn_rate = 0.0;  // inert: lighting time -inf, F = 1
  bodies_.push_back(body);
  // Every per-body array grows with bodies_ (the passes index them by body).
  body_fixed_.push_back(0);
  body_shear_modulus_.push_back(shear_modulus(materials_[material].strength));
  return static_cast<std::uint16_t>(bodies_.size() - 1);
}

void MpmSolver::inject_particles(const ParticleBatch& batch) {
  refuse_unsupported_coupling("particle injection");
  const std::size_t n = batch.size();
  const bool with_stress = !batch.stress.empty();
  const auto& g = grid();
  for (std::size_t i = 0; i < n; ++i) {
    // Named only when refused: a string per particle was most of an injection's cost.
    const auto which = [&] {
      return "injected particle " + std::to_string(i) + " (id " + std::to_string(batch.id[i]) + ")";
    };
    if (!(batch.mass[i] > 0.0) || !std::isfinite(batch.mass[i]) || !(batch.volume[i] > 0.0) ||
        !std::isfinite(batch.volume[i]))
      throw Error(which() + ": mass and volume must be positive and finite, got " +
                  std::to_string(batch.mass[i]) + " kg, " + std::to_string(batch.volume[i]) +
                  " m^3");
    if (batch.material[i] >= materials_.size())
      throw Error(which() + ": material " + std::to_string(batch.material[i]) +
                  " is not one of the scene's " + std::to_string(materials_.size()));
    for (int a = 0; a < 3; ++a)
      require_on_grid(g, batch.position[3 * i + static_cast<std::size_t>(a)], a, which);
  }
  for (std::size_t i = 0; i < n; ++i) model_for(batch.material[i]);  // may throw: before growing
  const std::size_t first = particles_.size();
  particles_.grow(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = first + i;
    const std::size_t m = batch.material[i];
    const ConstitutiveModel& model = *models_[m];
    particles_.id[p] = batch.id[i];
    particles_.material[p] = static_cast<std::uint16_t>(m);
    particles_.body[p] = injected_body(m);
    for (std::size_t a = 0; a < 3; ++a) {
      particles_.position[a][p] = batch.position[3 * i + a];
      particles_.velocity[a][p] = batch.velocity[3 * i + a];
    }
    particles_.mass[p] = batch.mass[i];
    particles_.density[p] = batch.mass[i] / batch.volume[i];
    particles_.specific_internal_energy[p] = batch.internal_energy[i] / batch.mass[i];
    Tensor3 s = Tensor3::Zero();
    MaterialPoint point = particles_.material_point(p, s);
    model.initialise(particles_.density[p], point);
    particles_.set_deviator(p, s);
    if (with_stress) {
      const double* sigma = &batch.stress[kVoigt * i];
      const double pressure = -(sigma[0] + sigma[1] + sigma[2]) / 3.0;
      particles_.pressure[p] = pressure;
      for (std::size_t c = 0; c < kVoigt; ++c)
        particles_.deviatoric_stress[kFromVoigt[c]][p] = sigma[c] + (c < 3 ? pressure : 0.0);
    }
  }
  reserve_particle_scratch();
  add_to_next_step_map(first);  // before a throw below could leave the map without them
  compute_stable_dt(first);     // the others have not changed since the last full pass
}

ParticleBatch MpmSolver::remove_particles(std::span<const std::uint8_t> flags) {
  auto& ps = particles_;
  ParticleBatch out;
  out.resize(static_cast<std::size_t>(
      std::count_if(flags.begin(), flags.end(), [](std::uint8_t f) { return f != 0; })));
  std::size_t i = 0;
  double fastest_removed = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    if (flags[p] == 0) continue;
    fastest_removed = std::max(fastest_removed, signal_speed(p));
    out.id[i] = ps.id[p];
    for (std::size_t a = 0; a < 3; ++a) {
      out.position[3 * i + a] = ps.position[a][p];
      out.velocity[3 * i + a] = ps.velocity[a][p];
    }
    out.mass[i] = ps.mass[p];
    out.volume[i] = ps.mass[p] / ps.density[p];
    out.internal_energy[i] = ps.mass[p] * ps.specific_internal_energy[p];
    out.material[i] = ps.material[p];
    const double pq = ps.pressure[p] + ps.bulk_viscosity[p];  // sigma = s - (p + q) I
    for (std::size_t c = 0; c < kVoigt; ++c)
      out.stress[kVoigt * i + c] = ps.deviatoric_stress[kFromVoigt[c]][p] - (c < 3 ? pq : 0.0);
    ++i;
  }
  if (i > 0) {
    ps.remove_flagged(flags);
    next_map_.valid = false;  // a map cannot take particles back to the bit
    // The step changes only if the fastest particle left (a full pass per
    // removal and per injection was 1 % of V6's CPU time at h = 2 mm).
    if (!(fastest_removed < fastest_speed_)) compute_stable_dt();
  }
  return out;
}

void MpmSolver::map_particles_to_nodes() {
  next_map_.valid = false;
  rebuild_grid();
  particles_to_grid();
}

NodeState MpmSolver::node_state(const grid::Index3& node) const {
  grid::Index3 storage{};
  for (int a = 0; a < 3; ++a) storage[a] = node[a] + grid_.offset()[a];
  const std::ptrdiff_t n = grid_.find_node(storage);
  if (n < 0) return {};
  const auto i = static_cast<std::size_t>(n);
  return {grid_.mass[i], {grid_.momentum[0][i], grid_.momentum[1][i], grid_.momentum[2][i]}};
}

void MpmSolver::map_particles_to_node_box(const grid::Index3& lo, const grid::Index3& hi,
                                          NodeBoxMap& out) const {
  out.reset(lo, hi);
  const auto& ps = particles_;
  dispatch_stencil(
      settings_.shape_function != config::ShapeFunction::linear, axis_mask_,
      [&](auto width, auto mask) {
        constexpr int kWidth = decltype(width)::value;
        constexpr int kMask = decltype(mask)::value;
        constexpr int kExtent[3] = {(kMask & 1) ? kWidth : 1, (kMask & 2) ? kWidth : 1,
                                    (kMask & 4) ? kWidth : 1};
        // Pass 1, positions only: the particles whose stencil (as rebuild_grid
        // places it) reaches the box, and the colour of their home block.
        std::array<std::int32_t, SparseGrid::kColours + 1> begin{};
        // A stencil starts at most kWidth nodes below its particle: farther ones
        // cannot reach the box, and this test needs no floor (a libm call).
        double near_lo[3], near_hi[3];
        for (int a = 0; a < 3; ++a) {
          near_lo[a] = geometry_.origin[a] + (lo[a] - kWidth - 1) / geometry_.inverse_spacing[a];
          near_hi[a] = geometry_.origin[a] + (hi[a] + 1) / geometry_.inverse_spacing[a];
        }
        for (std::size_t p = 0; p < ps.size(); ++p) {
          bool near = true;
          for (int a = 0; a < 3; ++a)
            if ((kMask >> a) & 1)
              near = near && ps.position[a][p] > near_lo[a] && ps.position[a][p] < near_hi[a];
          if (!near) continue;
          bool reaches = true;
          int colour = 0;
          for (int a = 0; a < 3 && reaches; ++a) {
            const bool active = ((kMask >> a) & 1) != 0;
            const int first =
                first_node<kWidth>(ps.position[a][p], a, active, geometry_) - grid_.offset()[a];
            reaches = first + kExtent[a] > lo[a] && first < hi[a];
            if (active) colour |= ((first + grid_.offset()[a]) >> SparseGrid::kBlockShift & 1) << a;
          }
          if (!reaches) continue;
          out.reaching.push_back(static_cast<std::int32_t>(p));
          ++begin[static_cast<std::size_t>(colour) + 1];
        }
        // P2G adds to a node colour by colour, and within a colour from one home
        // block, whose particles it takes in index order: the same order here
        // gives the same sums to the last bit.
        for (int c = 0; c < SparseGrid::kColours; ++c) begin[c + 1] += begin[c];
        out.by_colour.resize(out.reaching.size());
        for (const std::int32_t p : out.reaching) {
          int colour = 0;
          for (int a = 0; a < 3; ++a)
            if ((kMask >> a) & 1)
              colour |= (first_node<kWidth>(ps.position[a][static_cast<std::size_t>(p)], a, true,
                                            geometry_) >>
                             SparseGrid::kBlockShift &
                         1)
                        << a;
          out.by_colour[static_cast<std::size_t>(begin[static_cast<std::size_t>(colour)]++)] = p;
        }
        // Pass 2: (2-12) and (2-9) on the box's nodes, as particles_to_grid computes them.
        for (const std::int32_t index : out.by_colour) {
          const auto p = static_cast<std::size_t>(index);
          double half_width[3];
          particle_half_width(p, half_width);
          AxisWeights<kWidth> ax[3];
          for (int a = 0; a < 3; ++a)
            axis_weights<kWidth>(ps.position[a][p], a, ((kMask >> a) & 1) != 0, geometry_,
                                 half_width[a], ax[a]);
          const double m = ps.mass[p];
          const double e = ps.specific_internal_energy[p];
          const double v[3] = {ps.velocity[0][p], ps.velocity[1][p], ps.velocity[2][p]};
          for (int k = 0; k < kExtent[2]; ++k) {
            const int nk = ax[2].first + k - lo[2];
            if (nk < 0 || nk >= hi[2] - lo[2]) continue;
            for (int j = 0; j < kExtent[1]; ++j) {
              const int nj = ax[1].first + j - lo[1];
              if (nj < 0 || nj >= hi[1] - lo[1]) continue;
              const double wyz = ax[1].weight[j] * ax[2].weight[k];
              for (int i = 0; i < kExtent[0]; ++i) {
                const int ni = ax[0].first + i - lo[0];
                if (ni < 0 || ni >= hi[0] - lo[0]) continue;
                const auto n =
                    static_cast<std::size_t>((ni * (hi[1] - lo[1]) + nj) * (hi[2] - lo[2]) + nk);
                const double wm = ax[0].weight[i] * wyz * m;
                out.mass[n] += wm;
                out.internal_energy[n] += wm * e;
                for (int a = 0; a < 3; ++a) out.momentum[3 * n + a] += wm * v[a];
              }
            }
          }
        }
      });
}

void MpmSolver::queue_node_load(const NodeLoad& load) {
  refuse_unsupported_coupling("a node load");
  const auto& g = grid();
  for (int a = 0; a < 3; ++a) {
    const int last = g.is_active(a) ? g.cells()[a] : 0;
    if (load.node[a] < 0 || load.node[a] > last)
      throw Error("node load at node (" + std::to_string(load.node[0]) + ", " +
                  std::to_string(load.node[1]) + ", " + std::to_string(load.node[2]) + "): axis " +
                  std::to_string(a) + " needs 0 <= index <= " + std::to_string(last));
  }
  node_loads_.push_back(load);
}

void MpmSolver::record_added_node_state() {
  added_node_state_.clear();  // only this step's loads enter the remap
  if (node_loads_.empty()) return;
  // node -> entry of added_node_state_ (-1: none), so n loads cost O(n), not O(n^2).
  if (added_slot_.size() < grid_.node_count()) added_slot_.resize(grid_.node_count(), -1);
  for (const NodeLoad& load : node_loads_) {
    if (load.overwrite || load.quantity == NodeLoad::Quantity::force) continue;
    const auto n = static_cast<std::size_t>(grid_.node(load.node[0] + grid_.offset()[0],
                                                       load.node[1] + grid_.offset()[1],
                                                       load.node[2] + grid_.offset()[2]));
    if (added_slot_[n] < 0) {
      added_slot_[n] = static_cast<std::int32_t>(added_node_state_.size());
      added_node_state_.push_back(AddedNodeState{n, 0.0, {0.0, 0.0, 0.0}});
    }
    auto& added = added_node_state_[static_cast<std::size_t>(added_slot_[n])];
    if (load.quantity == NodeLoad::Quantity::mass)
      added.mass += load.value[0];
    else
      for (int a = 0; a < 3; ++a) added.momentum[a] += load.value[a];
  }
  for (const auto& entry : added_node_state_) added_slot_[entry.node] = -1;
}

void MpmSolver::apply_node_loads(NodeLoadPass pass) {
  for (const NodeLoad& load : node_loads_) {
    const bool is_force = load.quantity == NodeLoad::Quantity::force;
    if ((pass == NodeLoadPass::force && !is_force) ||
        (pass == NodeLoadPass::mass_and_momentum && is_force))
      continue;
    const auto n = static_cast<std::size_t>(grid_.node(load.node[0] + grid_.offset()[0],
                                                       load.node[1] + grid_.offset()[1],
                                                       load.node[2] + grid_.offset()[2]));
    if (load.quantity == NodeLoad::Quantity::mass) {
      grid_.mass[n] = load.overwrite ? load.value[0] : grid_.mass[n] + load.value[0];
      continue;
    }
    auto& field = load.quantity == NodeLoad::Quantity::momentum ? grid_.momentum : grid_.force;
    for (int a = 0; a < 3; ++a)
      field[a][n] = load.overwrite ? load.value[a] : field[a][n] + load.value[a];
  }
}

void MpmSolver::restore(ParticleSet particles, std::span<const std::size_t> injected_body_materials,
                        double time, std::int64_t steps, const BoundaryLedger& ledger,
                        double particle_updates) {
  for (const std::size_t m : injected_body_materials)
    if (m >= materials_.size())
      throw Error("restore: an injected body has material " + std::to_string(m) +
                  "; the scene has " + std::to_string(materials_.size()));
  const std::size_t bodies = scene_bodies_ + injected_body_materials.size();
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (particles.body[p] >= bodies || particles.material[p] >= materials_.size())
      throw Error("restore: particle " + std::to_string(p) + " has body " +
                  std::to_string(particles.body[p]) + " and material " +
                  std::to_string(particles.material[p]) + "; there are " + std::to_string(bodies) +
                  " bodies and " + std::to_string(materials_.size()) + " materials");
  for (std::size_t p = 0; p < particles.size(); ++p)
    for (int a = 0; a < 3; ++a)
      require_on_grid(grid(), particles.position[a][p], a,
                      [p] { return "restore: particle " + std::to_string(p); });
  // Models only widen the running particles' history (same values): the state is unchanged.
  for (std::size_t p = 0; p < particles.size(); ++p) model_for(particles.material[p]);
  if (particles.history_stride != particles_.history_stride)
    throw Error("restore: the particles keep " + std::to_string(particles.history_stride) +
                " history values each; this scene's models keep " +
                std::to_string(particles_.history_stride));
  bodies_.resize(scene_bodies_);
  body_fixed_.resize(scene_bodies_);
  body_shear_modulus_.resize(scene_bodies_);
  for (const std::size_t m : injected_body_materials) injected_body(m);  // one per material
  particles_ = std::move(particles);
  reserve_particle_scratch();
  time_ = time;
  steps_ = steps;
  ledger_ = ledger;
  particle_updates_ = particle_updates;
  node_loads_.clear();
  next_map_.valid = false;
  compute_stable_dt();
}

}  // namespace mpfd::mpm
