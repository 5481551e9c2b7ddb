// cambrian: per-joint sine oscillators.
#include "brain/sine_oscillators.hpp"

#include "cambrian/error.hpp"
#include "cambrian/math.hpp"

#include <cmath>
#include <string>

namespace cambrian {

std::unique_ptr<Controller> SineOscillatorsPlan::build(double time_step, std::size_t,
                                                       std::size_t effectors) const {
  if (effectors != oscillators.size()) {
    throw Error(ExitCode::failure, "sine oscillators: " + std::to_string(oscillators.size()) +
                                       " oscillators for " + std::to_string(effectors) +
                                       " effectors");
  }
  return std::make_unique<SineOscillators>(oscillators, time_step);
}

SineOscillators::SineOscillators(std::vector<SineOscillator> oscillators, double time_step)
    : oscillators_(std::move(oscillators)), time_step_(time_step) {
  if (!(time_step > 0) || !std::isfinite(time_step)) {
    throw ConfigError("sine oscillators: time_step = " + std::to_string(time_step) +
                      " must be positive and finite");
  }
}

void SineOscillators::step(std::span<const double>, std::span<double> drives) {
  constexpr double kTwoPi = 2 * kPi;
  const double t = time_;
  for (std::size_t e = 0; e < oscillators_.size() && e < drives.size(); ++e) {
    const SineOscillator& o = oscillators_[e];
    drives[e] =
        o.enabled ? o.amplitude * std::sin(kTwoPi * o.frequency * t + o.phase) + o.offset : 0.0;
  }
  ++steps_;
  time_ = static_cast<double>(steps_) * time_step_;
}

void SineOscillators::reset() {
  steps_ = 0;
  time_ = 0;
}

}  // namespace cambrian
