#include "coupler/run/activation.hpp"

#include <algorithm>
#include <sstream>

namespace mpfd::coupler {
namespace {

constexpr const char* kActivationOwner = "activation";

}  // namespace

ActivationWatch::ActivationWatch(std::optional<double> threshold)
    : threshold_(threshold), dormant_(threshold.has_value()) {}

void ActivationWatch::observe(const std::vector<double>& strip_pressure, double time) {
  if (!dormant_ || trigger_time_) return;
  // The largest cell-centre pressure on either side of the face: the wave reaches
  // the outer strip cell first from the FDM side (T §4.3, Fig. 4.1).
  double peak = 0;
  for (const double p : strip_pressure) peak = std::max(peak, p);
  peak_pressure_ = std::max(peak_pressure_, peak);
  if (peak > *threshold_) {
    trigger_time_ = time;
    trigger_pressure_ = peak;
  }
}

void ActivationWatch::activated(double time, std::int64_t step) {
  dormant_ = false;
  activation_time_ = time;
  activation_step_ = step;
}

nlohmann::json ActivationWatch::summary() const {
  if (!threshold_) return {{"threshold_pa", nullptr}, {"activated", true}, {"time_s", 0.0}};
  nlohmann::json out = {{"threshold_pa", *threshold_},
                        {"activated", activation_time_.has_value()},
                        {"peak_strip_pressure_pa", peak_pressure_}};
  if (activation_time_) {
    out["time_s"] = *activation_time_;
    out["after_step"] = activation_step_;
    out["trigger_pressure_pa"] = trigger_pressure_;
  } else {
    out["time_s"] = nullptr;
  }
  return out;
}

std::string ActivationWatch::activation_text() const {
  std::ostringstream text;
  text << "FSI zone activated at t = " << activation_time_.value_or(0.0) << " s (after step "
       << activation_step_ << "): strip pressure " << trigger_pressure_ << " Pa > threshold "
       << threshold_.value_or(0.0) << " Pa";
  return text.str();
}

void ActivationWatch::save(RestartWriter& out) const {
  out.number(kActivationOwner, "dormant", dormant_ ? 1 : 0);
  out.optional_number(kActivationOwner, "trigger_time", trigger_time_);
  out.number(kActivationOwner, "trigger_pressure", trigger_pressure_);
  out.number(kActivationOwner, "peak_pressure", peak_pressure_);
  out.optional_number(kActivationOwner, "activation_time", activation_time_);
  out.number(kActivationOwner, "activation_step", static_cast<double>(activation_step_));
}

void ActivationWatch::restore(const RestartReader& in) {
  const bool dormant = in.number(kActivationOwner, "dormant") != 0;
  if (dormant && !threshold_)
    in.refuse("holds a sleeping MPM zone; this scene has no zones.mpm.activation_pressure");
  dormant_ = dormant;
  trigger_time_ = in.optional_number(kActivationOwner, "trigger_time");
  trigger_pressure_ = in.number(kActivationOwner, "trigger_pressure");
  peak_pressure_ = in.number(kActivationOwner, "peak_pressure");
  activation_time_ = in.optional_number(kActivationOwner, "activation_time");
  activation_step_ = static_cast<std::int64_t>(in.number(kActivationOwner, "activation_step"));
}

}  // namespace mpfd::coupler
