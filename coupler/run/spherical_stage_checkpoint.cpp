// SphericalStage's part of a coupled checkpoint (coupler_checkpoint.hpp): the 1D
// particles whole, and the stage's clock. Its grid is rebuilt from the particles
// in every step, so the particles are the whole state.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "coupler/run/spherical_stage.hpp"

namespace mpfd::coupler {
namespace {

constexpr const char* kStageOwner = "stage";
constexpr std::size_t kTensorValues = 9;

}  // namespace

void SphericalStage::save(RestartWriter& out) const {
  const auto& particles = mpm_.particles();
  out.number(kStageOwner, "time", mpm_.time());
  out.number(kStageOwner, "particles", static_cast<double>(particles.size()));
  for (const auto& [name, field] : particles.scalar_fields()) out.array(kStageOwner, name, *field);
  std::vector<double> stress;
  stress.reserve(kTensorValues * particles.size());
  for (const auto& s : particles.deviatoric_stress)
    stress.insert(stress.end(), s.data(), s.data() + kTensorValues);
  out.array(kStageOwner, "deviatoric_stress", stress);
  out.array(kStageOwner, "history", particles.history);
  out.array(kStageOwner, "material",
            std::vector<double>(particles.material.begin(), particles.material.end()));
}

void SphericalStage::restore(const RestartReader& in) {
  mpm::spherical::SphericalParticles particles = mpm_.particles();
  const std::size_t n = particles.size();
  const double count = in.number(kStageOwner, "particles");
  if (count != static_cast<double>(n))
    in.refuse("holds " + shortest_text(count) + " 1D particles (/stage, attribute particles); " +
              "this scene's 1D stage seeds " + std::to_string(n));
  for (const auto& [name, field] : particles.scalar_fields())
    *field = in.array(kStageOwner, name, n);
  const auto stress = in.array(kStageOwner, "deviatoric_stress", kTensorValues * n);
  for (std::size_t p = 0; p < n; ++p)
    std::copy_n(stress.begin() + static_cast<std::ptrdiff_t>(kTensorValues * p), kTensorValues,
                particles.deviatoric_stress[p].data());
  particles.history = in.array(kStageOwner, "history", particles.history.size());
  const auto material = in.array(kStageOwner, "material", n);
  if (!std::equal(material.begin(), material.end(), particles.material.begin()))
    in.refuse("holds 1D particles of other layers (/stage/material) than this scene's stage seeds");
  try {
    mpm_.restore(particles, in.number(kStageOwner, "time"));
  } catch (const Error& e) {
    in.refuse(std::string("/stage: ") + e.what());
  }
}

}  // namespace mpfd::coupler
