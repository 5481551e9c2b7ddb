// cambrian: lengths that follow sinusoids as a controller.
#include "brain/length_sinusoids.hpp"

#include "cambrian/error.hpp"

#include <cmath>
#include <string>

namespace cambrian {

std::unique_ptr<Controller> LengthSinusoidsPlan::build(double time_step, std::size_t,
                                                       std::size_t effectors) const {
  if (effectors != sinusoids.size())
    throw Error(ExitCode::failure, "a length controller of " + std::to_string(sinusoids.size()) +
                                       " sinusoids cannot drive " + std::to_string(effectors) +
                                       " effectors");
  return std::make_unique<LengthSinusoids>(sinusoids, time_step);
}

LengthSinusoids::LengthSinusoids(std::vector<LengthSinusoid> sinusoids, double time_step)
    : sinusoids_(std::move(sinusoids)), time_step_(time_step) {}

void LengthSinusoids::step(std::span<const double>, std::span<double> drives) {
  ++steps_;
  const double t = static_cast<double>(steps_) * time_step_;
  for (std::size_t e = 0; e < sinusoids_.size(); ++e) {
    const LengthSinusoid& s = sinusoids_[e];
    const double length = s.middle + s.amplitude * std::sin(s.angular_frequency * t + s.phase);
    drives[e] = s.scale > 0 ? (length - s.zero) / s.scale : 0.0;
  }
}

}  // namespace cambrian
