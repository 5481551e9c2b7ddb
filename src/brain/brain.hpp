// cambrian: the creature's controller compiled from a BodyPlan into flat arrays.
#pragma once

#include "cambrian/body_plan.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace cambrian {

/// A compiled neural controller. The signal array holds sensors then neurons (BodyPlan layout).
/// step() updates every neuron synchronously from the previous step's signals, then computes
/// effector commands in [-1, 1]. No heap allocation after construction; outputs stay finite.
class Brain {
 public:
  Brain(const BodyPlan& plan, double time_step);

  /// Sensor slots, written by physics before each step.
  std::span<double> sensors();
  /// Advances the controller by one time step.
  void step();
  /// Effector commands in [-1, 1], one per BodyPlan effector, valid after step().
  std::span<const double> effectors() const;
  /// Zeros neuron state, outputs and the controller clock.
  void reset();
  /// All signals (sensors then neurons), for tests and tracing.
  std::span<const double> signals() const;
  /// Controller clock t in seconds: the number of completed step() calls times the time step.
  /// step() evaluates oscillators at the clock value it starts with.
  double time() const { return time_; }

 private:
  // compiled from the plan: see brain.cpp
  std::vector<double> signals_, next_signals_, state_, effector_out_;
  std::vector<std::uint8_t> function_;
  std::vector<double> parameter_;
  std::vector<int> input_signal_;     // 3 per neuron, -1 = constant
  std::vector<double> input_weight_;  // 3 per neuron
  std::vector<int> effector_signal_;
  std::vector<double> effector_weight_;
  std::vector<JointControllerGene> effector_oscillator_;
  int sensor_count_ = 0, neuron_count_ = 0;
  double time_step_ = 0, time_ = 0;
  std::uint64_t steps_ = 0;  // step() calls since construction or reset(); time_ = steps_ * dt
};

}  // namespace cambrian
