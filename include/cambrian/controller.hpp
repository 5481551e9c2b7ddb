// cambrian: controllers — what drives a creature's joints. A ControllerPlan is the immutable
// description an encoding develops (MuJoCo's model); a Controller is the running state one
// evaluation steps (its data). Physics writes sensor values, the controller writes one drive per
// effector, physics clamps each drive to [-1, 1] and applies it.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

namespace cambrian {

/// A running controller. Deterministic; no heap allocation in step().
class Controller {
 public:
  virtual ~Controller() = default;
  /// Advances by one time step: reads `sensors` (BodyPlan sensor order) and writes one drive per
  /// effector into `drives` (BodyPlan effector order; any finite value, clamped by physics).
  virtual void step(std::span<const double> sensors, std::span<double> drives) = 0;
  /// Back to the state at construction (clock, memories).
  virtual void reset() = 0;
  /// Internal signals for tracing (a network: sensors then neurons); may be empty.
  virtual std::span<const double> signals() const { return {}; }
};

/// The immutable description of a controller, made by development.
class ControllerPlan {
 public:
  virtual ~ControllerPlan() = default;
  /// What kind of controller it is ("network", "sine", "sum").
  virtual std::string kind() const = 0;
  /// A fresh controller stepping every `time_step` seconds, for `sensors` sensors and `effectors`
  /// effectors. Throws Error(failure) naming the inconsistency when the plan does not fit them.
  virtual std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                            std::size_t effectors) const = 0;
  /// Units of the controller's own (neurons), for the outcome's body statistics.
  virtual int neuronCount() const { return 0; }
};

}  // namespace cambrian
