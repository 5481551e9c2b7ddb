// cambrian: lengths that follow sinusoids as a controller (the springy organisms' muscles): each
// effector is commanded to the length middle + amplitude sin(angular_frequency t + phase), given
// to a position effector as (length - zero) / scale.
#pragma once

#include "cambrian/controller.hpp"

#include <cstdint>
#include <vector>

namespace cambrian {

/// One effector's sinusoid and how its length becomes a command.
struct LengthSinusoid {
  double middle = 0;             ///< m
  double amplitude = 0;          ///< m
  double angular_frequency = 0;  ///< rad / s
  double phase = 0;              ///< rad
  double zero = 0;               ///< the length commanded by 0, m
  double scale = 1;              ///< the change of length commanded by 1, m (0: always 0)
  friend bool operator==(const LengthSinusoid&, const LengthSinusoid&) = default;
};

/// One sinusoid per effector (BodyPlan effector order).
class LengthSinusoidsPlan : public ControllerPlan {
 public:
  std::vector<LengthSinusoid> sinusoids;

  std::string kind() const override { return "lengths"; }
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
};

/// The running sinusoids; reads no sensors. Step n (counted from 0) commands the length of time
/// (n + 1) x the time step: where a position effector is to be at the end of the step.
class LengthSinusoids : public Controller {
 public:
  LengthSinusoids(std::vector<LengthSinusoid> sinusoids, double time_step);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override { steps_ = 0; }

 private:
  std::vector<LengthSinusoid> sinusoids_;
  double time_step_ = 0;
  std::uint64_t steps_ = 0;
};

}  // namespace cambrian
