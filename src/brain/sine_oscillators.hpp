// cambrian: per-joint sine oscillators as a controller (Minemonics' joint controllers): each
// effector's drive is amplitude * sin(2 pi frequency t + phase) + offset.
#pragma once

#include "cambrian/controller.hpp"

#include <cstdint>
#include <vector>

namespace cambrian {

/// One effector's oscillator; a disabled one drives 0.
struct SineOscillator {
  bool enabled = false;
  double amplitude = 0;  ///< in effector units (-1..1)
  double frequency = 1;  ///< Hz
  double phase = 0;      ///< radians
  double offset = 0;     ///< effector units
  friend bool operator==(const SineOscillator&, const SineOscillator&) = default;
};

/// One oscillator per effector (BodyPlan effector order).
class SineOscillatorsPlan : public ControllerPlan {
 public:
  std::vector<SineOscillator> oscillators;

  std::string kind() const override { return "sine"; }
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
};

/// The running oscillators; reads no sensors. Clock as NeuralNetwork's: completed steps times
/// the time step, each step evaluated at the clock value it starts with.
class SineOscillators : public Controller {
 public:
  SineOscillators(std::vector<SineOscillator> oscillators, double time_step);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override;

 private:
  std::vector<SineOscillator> oscillators_;
  double time_step_ = 0, time_ = 0;
  std::uint64_t steps_ = 0;
};

}  // namespace cambrian
