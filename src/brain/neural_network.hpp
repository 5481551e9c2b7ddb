// cambrian: Sims' nested neural network as a controller — neurons of the parts and of the brain,
// wired to sensors, to each other and to the effectors, updated synchronously every step.
#pragma once

#include "cambrian/controller.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cambrian {

/// Neuron functions: Sims (1994) set plus constant. Arity is neuronArity().
enum class NeuronFunction : std::uint8_t {
  constant = 0,
  sum,
  product,
  divide,
  sum_threshold,
  greater_than,
  sign_of,
  min,
  max,
  abs,
  if_positive,  ///< Sims' "if": input 0 > 0 ? input 1 : input 2
  interpolate,
  sin,
  cos,
  atan,
  log,
  expt,
  sigmoid,
  integrate,
  differentiate,
  smooth,
  memory,
  oscillate_wave,
  oscillate_saw,
  // Chaumont et al.'s own (2007, Table I), where they differ from the above
  sum_above,      ///< sumT: a + b if a + b >= parameter, else 0
  divide_or_one,  ///< div: 1 if b <= 1e-6, else a / b
  delay,          ///< mem: a as it was n = round(|parameter|) steps ago (1..255; 0 before)
  wave,           ///< wav: b sin(a k + c), k the step count
  count_          ///< number of functions; not a function
};

/// Number of inputs a neuron function reads (0..3).
int neuronArity(NeuronFunction function);
/// Lower-case name used by text forms ("sum_threshold", "oscillate_wave", ...).
const char* neuronFunctionName(NeuronFunction function);

/// One weighted wire into a neuron or effector: value = weight * signal[signal], or the weight
/// itself when signal < 0 (a constant). Signals are the sensors, then the neurons.
struct Wire {
  int signal = -1;
  double weight = 0;
  friend bool operator==(const Wire&, const Wire&) = default;
};

/// A neuron: function, parameter and up to three input wires.
struct NeuronPlan {
  NeuronFunction function = NeuronFunction::sum;
  double parameter = 0;
  int part = -1;  ///< owning part, -1 for a brain neuron
  std::array<Wire, 3> inputs{};
  friend bool operator==(const NeuronPlan&, const NeuronPlan&) = default;
};

/// The network: neurons and one wire per effector. Signal i < sensors is sensor i; signal
/// sensors + n is neuron n.
class NeuralNetworkPlan : public ControllerPlan {
 public:
  std::vector<NeuronPlan> neurons;
  std::vector<Wire> effector_inputs;  ///< one per BodyPlan effector
  std::size_t sensor_count = 0;       ///< sensors the wires were made for
  /// Every neuron output (and, when below the default, every neuron input) is kept within
  /// +-signal_bound: 1000 for Sims' network, 1 for Chaumont et al.'s ("every input value lies in
  /// the interval [-1, 1], every output value is also restricted to the same interval").
  double signal_bound = 1000;

  std::string kind() const override { return "network"; }
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
  int neuronCount() const override { return static_cast<int>(neurons.size()); }
  /// The signal index of neuron n.
  int neuronSignal(int n) const { return static_cast<int>(sensor_count) + n; }
};

/// The running network. step() updates every neuron synchronously from the previous step's
/// signals (sensors just written), then sets each drive to its wire. Outputs stay finite.
class NeuralNetwork : public Controller {
 public:
  /// Throws ConfigError for a bad time step, Error(failure) for a wire past the signals.
  NeuralNetwork(const NeuralNetworkPlan& plan, double time_step);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override;
  std::span<const double> signals() const override { return signals_; }
  /// Controller clock t in seconds: completed step() calls times the time step; step()
  /// evaluates oscillators at the clock value it starts with.
  double time() const { return time_; }

 private:
  // compiled from the plan: see neural_network.cpp
  std::vector<double> signals_, next_signals_, state_;
  std::vector<double> delayed_;       // the delay neurons' past inputs, each its own ring
  std::vector<std::uint32_t> ring_;   // per neuron: where its ring starts in delayed_
  std::vector<std::uint8_t> length_;  // per neuron: its ring's length (delay neurons)
  double bound_ = 1000;               // NeuralNetworkPlan::signal_bound
  bool bound_inputs_ = false;         // the bound is below the default: inputs clamped too
  std::vector<std::uint8_t> function_;
  std::vector<double> parameter_;
  std::vector<int> input_signal_;     // 3 per neuron, -1 = constant
  std::vector<double> input_weight_;  // 3 per neuron
  std::vector<int> effector_signal_;
  std::vector<double> effector_weight_;
  int sensor_count_ = 0, neuron_count_ = 0;
  double time_step_ = 0, time_ = 0;
  std::uint64_t steps_ = 0;  // step() calls since construction or reset(); time_ = steps_ * dt
};

}  // namespace cambrian
