// cambrian: Sims' nested network compiled into flat arrays and updated synchronously, without
// allocating. See docs/development-and-brain.md.
#include "brain/neural_network.hpp"

#include "cambrian/error.hpp"
#include "cambrian/math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cambrian {
namespace {

// every neuron output and state stays inside this range
constexpr double kSignalLimit = 1000;
// divisors smaller than this make divide output 0
constexpr double kDivideEpsilon = 1e-6;
// log reads at least this magnitude
constexpr double kLogFloor = 1e-6;
// expt never exponentiates more than this
constexpr double kExpCap = 10;
// oscillator neurons run at most this many hertz
constexpr double kMaxOscillatorHz = 4;
constexpr double kTwoPi = 2 * kPi;

// the longest delay of a delay neuron, steps (a genome's are at most 10: its parameter bound;
// a catapult's release mechanism waits its release_delay)
constexpr int kMaxDelay = 255;

// non-finite values become 0, finite ones are clamped to +-limit
double bounded(double value, double limit = kSignalLimit) {
  if (!std::isfinite(value))
    return 0;
  return std::clamp(value, -limit, limit);
}

// a delay neuron's delay in steps
int delaySteps(double parameter) {
  const double steps = std::round(std::fabs(parameter));
  return steps >= kMaxDelay ? kMaxDelay : std::max(1, static_cast<int>(steps));
}

// sawtooth in [-1, 1] rising through 0 where sin(theta) does
double sawtooth(double theta) {
  const double u = theta / kTwoPi + 0.5;
  return 2 * (u - std::floor(u)) - 1;
}

// checks that a wire reads a signal of the plan
void checkWire(const Wire& wire, int signal_count, const std::string& where) {
  if (wire.signal >= signal_count) {
    throw Error(ExitCode::failure, "network: " + where + " reads signal " +
                                       std::to_string(wire.signal) + " but the plan has " +
                                       std::to_string(signal_count) + " signals");
  }
}

}  // namespace

int neuronArity(NeuronFunction function) {
  switch (function) {
    case NeuronFunction::constant:
      return 0;
    case NeuronFunction::sign_of:
    case NeuronFunction::abs:
    case NeuronFunction::sin:
    case NeuronFunction::cos:
    case NeuronFunction::atan:
    case NeuronFunction::log:
    case NeuronFunction::expt:
    case NeuronFunction::sigmoid:
    case NeuronFunction::integrate:
    case NeuronFunction::differentiate:
    case NeuronFunction::smooth:
    case NeuronFunction::memory:
    case NeuronFunction::oscillate_wave:
    case NeuronFunction::oscillate_saw:
    case NeuronFunction::delay:
      return 1;
    case NeuronFunction::sum:
    case NeuronFunction::product:
    case NeuronFunction::divide:
    case NeuronFunction::sum_threshold:
    case NeuronFunction::greater_than:
    case NeuronFunction::min:
    case NeuronFunction::max:
    case NeuronFunction::sum_above:
    case NeuronFunction::divide_or_one:
      return 2;
    case NeuronFunction::if_positive:
    case NeuronFunction::interpolate:
    case NeuronFunction::wave:
      return 3;
    case NeuronFunction::count_:
      break;
  }
  return 0;
}

const char* neuronFunctionName(NeuronFunction function) {
  static constexpr const char* kNames[] = {"constant",
                                           "sum",
                                           "product",
                                           "divide",
                                           "sum_threshold",
                                           "greater_than",
                                           "sign_of",
                                           "min",
                                           "max",
                                           "abs",
                                           "if",
                                           "interpolate",
                                           "sin",
                                           "cos",
                                           "atan",
                                           "log",
                                           "expt",
                                           "sigmoid",
                                           "integrate",
                                           "differentiate",
                                           "smooth",
                                           "memory",
                                           "oscillate_wave",
                                           "oscillate_saw",
                                           "sum_above",
                                           "divide_or_one",
                                           "delay",
                                           "wave"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) ==
                static_cast<std::size_t>(NeuronFunction::count_));
  auto i = static_cast<std::size_t>(function);
  return i < static_cast<std::size_t>(NeuronFunction::count_) ? kNames[i] : "unknown";
}

std::unique_ptr<Controller> NeuralNetworkPlan::build(double time_step, std::size_t sensors,
                                                     std::size_t effectors) const {
  if (sensors != sensor_count || effectors != effector_inputs.size()) {
    throw Error(ExitCode::failure, "network: made for " + std::to_string(sensor_count) +
                                       " sensors and " + std::to_string(effector_inputs.size()) +
                                       " effectors, the body has " + std::to_string(sensors) +
                                       " and " + std::to_string(effectors));
  }
  return std::make_unique<NeuralNetwork>(*this, time_step);
}

NeuralNetwork::NeuralNetwork(const NeuralNetworkPlan& plan, double time_step)
    : time_step_(time_step) {
  // the clock needs a positive, finite step
  if (!(time_step > 0) || !std::isfinite(time_step)) {
    throw ConfigError("network: time_step = " + std::to_string(time_step) +
                      " must be positive and finite");
  }
  sensor_count_ = static_cast<int>(plan.sensor_count);
  neuron_count_ = static_cast<int>(plan.neurons.size());
  const int signal_count = sensor_count_ + neuron_count_;

  // neurons: function, parameter and three wires each
  signals_.assign(signal_count, 0.0);
  next_signals_.assign(neuron_count_, 0.0);
  state_.assign(neuron_count_, 0.0);
  function_.resize(neuron_count_);
  parameter_.resize(neuron_count_);
  input_signal_.resize(3 * static_cast<std::size_t>(neuron_count_));
  input_weight_.resize(3 * static_cast<std::size_t>(neuron_count_));
  for (int n = 0; n < neuron_count_; ++n) {
    const NeuronPlan& neuron = plan.neurons[n];
    if (neuron.function >= NeuronFunction::count_) {
      throw Error(ExitCode::failure, "network: neuron " + std::to_string(n) +
                                         " has unknown function " +
                                         std::to_string(static_cast<int>(neuron.function)));
    }
    function_[n] = static_cast<std::uint8_t>(neuron.function);
    parameter_[n] = neuron.parameter;
    for (int i = 0; i < 3; ++i) {
      const Wire& wire = neuron.inputs[i];
      checkWire(wire, signal_count, "neuron " + std::to_string(n) + " input " + std::to_string(i));
      input_signal_[3 * n + i] = wire.signal < 0 ? -1 : wire.signal;
      input_weight_[3 * n + i] = wire.weight;
    }
  }

  // the bound, and a ring of past inputs per delay neuron
  if (!(plan.signal_bound > 0) || !(plan.signal_bound <= kSignalLimit)) {
    throw Error(ExitCode::failure, "network: signal_bound = " + std::to_string(plan.signal_bound) +
                                       " must be in (0, 1000]");
  }
  bound_ = plan.signal_bound;
  bound_inputs_ = bound_ < kSignalLimit;
  ring_.assign(neuron_count_, 0);
  length_.assign(neuron_count_, 0);
  for (int n = 0; n < neuron_count_; ++n) {
    if (plan.neurons[n].function != NeuronFunction::delay)
      continue;
    ring_[n] = static_cast<std::uint32_t>(delayed_.size());
    length_[n] = static_cast<std::uint8_t>(delaySteps(plan.neurons[n].parameter));
    delayed_.resize(delayed_.size() + length_[n], 0.0);
  }

  // effectors: one wire each
  const std::size_t effectors = plan.effector_inputs.size();
  effector_signal_.resize(effectors);
  effector_weight_.resize(effectors);
  for (std::size_t e = 0; e < effectors; ++e) {
    const Wire& wire = plan.effector_inputs[e];
    checkWire(wire, signal_count, "effector " + std::to_string(e));
    effector_signal_[e] = wire.signal < 0 ? -1 : wire.signal;
    effector_weight_[e] = wire.weight;
  }
}

void NeuralNetwork::reset() {
  std::fill(signals_.begin(), signals_.end(), 0.0);
  std::fill(next_signals_.begin(), next_signals_.end(), 0.0);
  std::fill(state_.begin(), state_.end(), 0.0);
  std::fill(delayed_.begin(), delayed_.end(), 0.0);
  steps_ = 0;
  time_ = 0;
}

void NeuralNetwork::step(std::span<const double> sensors, std::span<double> drives) {
  const double t = time_;
  const double dt = time_step_;
  std::copy_n(sensors.begin(), std::min<std::size_t>(sensors.size(), sensor_count_),
              signals_.begin());
  const double* signals = signals_.data();

  // a weighted wire: the weight itself for a constant, non-finite readings count as 0
  auto wire = [signals](int signal, double weight) {
    if (signal < 0)
      return weight;
    const double value = weight * signals[signal];
    return std::isfinite(value) ? value : 0.0;
  };

  // every neuron reads the previous step's signals and writes next_signals_ (under a bound
  // below the default, its inputs are bounded too)
  const double limit = bound_inputs_ ? bound_ : std::numeric_limits<double>::infinity();
  for (int n = 0; n < neuron_count_; ++n) {
    const double a = std::clamp(wire(input_signal_[3 * n], input_weight_[3 * n]), -limit, limit);
    const double b =
        std::clamp(wire(input_signal_[3 * n + 1], input_weight_[3 * n + 1]), -limit, limit);
    const double c =
        std::clamp(wire(input_signal_[3 * n + 2], input_weight_[3 * n + 2]), -limit, limit);
    const double p = parameter_[n];
    double& state = state_[n];
    double out = 0;
    switch (static_cast<NeuronFunction>(function_[n])) {
      case NeuronFunction::constant:
        out = p;
        break;
      case NeuronFunction::sum:
        out = a + b;
        break;
      case NeuronFunction::product:
        out = a * b;
        break;
      case NeuronFunction::divide:
        out = std::fabs(b) < kDivideEpsilon ? 0.0 : a / b;
        break;
      case NeuronFunction::sum_threshold:
        out = a + b > p ? 1.0 : 0.0;
        break;
      case NeuronFunction::greater_than:
        out = a > b ? 1.0 : 0.0;
        break;
      case NeuronFunction::sign_of:
        out = a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
        break;
      case NeuronFunction::min:
        out = std::min(a, b);
        break;
      case NeuronFunction::max:
        out = std::max(a, b);
        break;
      case NeuronFunction::abs:
        out = std::fabs(a);
        break;
      case NeuronFunction::if_positive:
        out = a > 0 ? b : c;
        break;
      case NeuronFunction::interpolate:
        out = b + (c - b) * std::clamp(a, 0.0, 1.0);
        break;
      case NeuronFunction::sin:
        out = std::sin(a);
        break;
      case NeuronFunction::cos:
        out = std::cos(a);
        break;
      case NeuronFunction::atan:
        out = std::atan(a);
        break;
      case NeuronFunction::log:
        out = std::log(std::max(std::fabs(a), kLogFloor));
        break;
      case NeuronFunction::expt:
        out = std::exp(std::min(a, kExpCap));
        break;
      case NeuronFunction::sigmoid:
        out = 1.0 / (1.0 + std::exp(-a));
        break;
      case NeuronFunction::integrate:
        state = bounded(state + a * dt);
        out = state;
        break;
      case NeuronFunction::differentiate:
        out = (a - state) / dt;
        state = a;
        break;
      case NeuronFunction::smooth:
        state = bounded(state + (a - state) * std::min(1.0, std::fabs(p) * dt));
        out = state;
        break;
      case NeuronFunction::memory:
        if (std::fabs(a) > std::fabs(p))
          state = a;
        out = state;
        break;
      case NeuronFunction::oscillate_wave:
        out = std::sin(kTwoPi * std::min(std::fabs(p), kMaxOscillatorHz) * t + a);
        break;
      case NeuronFunction::oscillate_saw:
        out = sawtooth(kTwoPi * std::min(std::fabs(p), kMaxOscillatorHz) * t + a);
        break;
      case NeuronFunction::sum_above:
        out = a + b >= p ? a + b : 0.0;
        break;
      case NeuronFunction::divide_or_one:
        out = b <= kDivideEpsilon ? 1.0 : a / b;
        break;
      case NeuronFunction::delay: {
        double& slot = delayed_[ring_[n] + steps_ % length_[n]];
        out = slot;
        slot = a;
        break;
      }
      case NeuronFunction::wave:
        out = b * std::sin(a * static_cast<double>(steps_) + c);
        break;
      case NeuronFunction::count_:
        break;
    }
    next_signals_[n] = bounded(out, bound_);
  }

  // the new neuron outputs become visible all at once
  std::copy(next_signals_.begin(), next_signals_.end(), signals_.begin() + sensor_count_);

  // each effector's drive is its wire
  for (std::size_t e = 0; e < effector_signal_.size() && e < drives.size(); ++e)
    drives[e] = wire(effector_signal_[e], effector_weight_[e]);

  // the clock counts steps, so it does not drift with repeated addition
  ++steps_;
  time_ = static_cast<double>(steps_) * time_step_;
}

}  // namespace cambrian
