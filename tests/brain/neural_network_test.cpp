// Tests of the controllers: Sims' network (every neuron function, synchronous update, finiteness
// under hostile inputs, reset, networks of developed genomes), the joint sine oscillators and
// their sum with the network, and the drive clamping physics applies.
#include "brain/neural_network.hpp"

#include "cambrian/error.hpp"

#include "brain/allocation_counter.hpp"
#include "brain/controller_sum.hpp"
#include "brain/sine_oscillators.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace cambrian {
namespace {

constexpr double kTol = 1e-12;

// a test plan: sensor slots, neurons, and effectors each with a wire and an oscillator
struct TestPlan {
  int sensors = 0;
  std::vector<NeuronPlan> neurons;
  std::vector<std::pair<Wire, SineOscillator>> effectors;
  int neuronSignal(int n) const { return sensors + n; }
  int signalCount() const { return sensors + static_cast<int>(neurons.size()); }
};

// the controller plan of a test plan: the network, plus the oscillators when any is on (as the
// directed-graph development makes it)
std::shared_ptr<const ControllerPlan> controllerPlanOf(const TestPlan& plan) {
  auto network = std::make_shared<NeuralNetworkPlan>();
  network->sensor_count = static_cast<std::size_t>(plan.sensors);
  network->neurons = plan.neurons;
  auto sine = std::make_shared<SineOscillatorsPlan>();
  bool any = false;
  for (const auto& [wire, oscillator] : plan.effectors) {
    network->effector_inputs.push_back(wire);
    sine->oscillators.push_back(oscillator);
    any = any || oscillator.enabled;
  }
  if (!any)
    return network;
  auto sum = std::make_shared<ControllerSumPlan>();
  sum->parts = {network, sine};
  return sum;
}

// a controller stepped as physics steps it: sensors written, step, drives clamped to [-1, 1]
class Brain {
 public:
  Brain(const TestPlan& plan, double time_step)
      : plan_(controllerPlanOf(plan)),
        controller_(
            plan_->build(time_step, static_cast<std::size_t>(plan.sensors), plan.effectors.size())),
        sensors_(static_cast<std::size_t>(plan.sensors), 0.0),
        drives_(plan.effectors.size(), 0.0),
        commands_(plan.effectors.size(), 0.0),
        time_step_(time_step) {}
  std::span<double> sensors() { return sensors_; }
  void step() {
    controller_->step(sensors_, drives_);
    for (std::size_t e = 0; e < drives_.size(); ++e)
      commands_[e] = std::isfinite(drives_[e]) ? std::clamp(drives_[e], -1.0, 1.0) : 0.0;
    ++steps_;
  }
  std::span<const double> effectors() const { return commands_; }
  std::span<const double> signals() const { return controller_->signals(); }
  void reset() {
    controller_->reset();
    steps_ = 0;
  }
  double time() const { return static_cast<double>(steps_) * time_step_; }

 private:
  std::shared_ptr<const ControllerPlan> plan_;
  std::unique_ptr<Controller> controller_;
  std::vector<double> sensors_, drives_, commands_;
  double time_step_;
  std::uint64_t steps_ = 0;
};

// a plan with `sensors` sensor slots
TestPlan planWithSensors(int sensors) {
  TestPlan plan;
  plan.sensors = sensors;
  return plan;
}

// a neuron reading the given wires
NeuronPlan neuronOf(NeuronFunction function, std::array<Wire, 3> inputs, double parameter = 0) {
  NeuronPlan neuron;
  neuron.function = function;
  neuron.parameter = parameter;
  neuron.inputs = inputs;
  return neuron;
}

// one neuron with inputs a, b, c on sensors 0, 1, 2: its output after one step
double evaluate(NeuronFunction function, double a, double b, double c, double parameter = 0,
                double time_step = 0.1) {
  TestPlan plan = planWithSensors(3);
  plan.neurons.push_back(neuronOf(function, {Wire{0, 1}, Wire{1, 1}, Wire{2, 1}}, parameter));
  Brain brain(plan, time_step);
  brain.sensors()[0] = a;
  brain.sensors()[1] = b;
  brain.sensors()[2] = c;
  brain.step();
  return brain.signals()[3];
}

// arities follow Sims' function set
TEST(NeuronFunctions, Arity) {
  EXPECT_EQ(neuronArity(NeuronFunction::constant), 0);
  EXPECT_EQ(neuronArity(NeuronFunction::sin), 1);
  EXPECT_EQ(neuronArity(NeuronFunction::oscillate_wave), 1);
  EXPECT_EQ(neuronArity(NeuronFunction::sum), 2);
  EXPECT_EQ(neuronArity(NeuronFunction::greater_than), 2);
  EXPECT_EQ(neuronArity(NeuronFunction::if_positive), 3);
  EXPECT_EQ(neuronArity(NeuronFunction::interpolate), 3);
  for (int i = 0; i < static_cast<int>(NeuronFunction::count_); ++i) {
    int arity = neuronArity(static_cast<NeuronFunction>(i));
    EXPECT_GE(arity, 0);
    EXPECT_LE(arity, 3);
  }
}

// every function has a distinct lower-case name; out-of-range values are "unknown"
TEST(NeuronFunctions, NamesAreDistinct) {
  std::set<std::string> names;
  for (int i = 0; i < static_cast<int>(NeuronFunction::count_); ++i) {
    std::string name = neuronFunctionName(static_cast<NeuronFunction>(i));
    EXPECT_FALSE(name.empty());
    EXPECT_NE(name, "unknown");
    names.insert(name);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(NeuronFunction::count_));
  EXPECT_STREQ(neuronFunctionName(NeuronFunction::oscillate_wave), "oscillate_wave");
  EXPECT_STREQ(neuronFunctionName(static_cast<NeuronFunction>(200)), "unknown");
}

TEST(Brain, StatelessFunctionsOnKnownInputs) {
  using F = NeuronFunction;
  EXPECT_EQ(evaluate(F::constant, 5, 6, 7, 0.25), 0.25);
  EXPECT_EQ(evaluate(F::sum, 1.5, 2.25, 9), 3.75);
  EXPECT_EQ(evaluate(F::product, 1.5, -2, 9), -3.0);
  EXPECT_EQ(evaluate(F::divide, 3, 2, 9), 1.5);
  EXPECT_EQ(evaluate(F::divide, 3, 1e-7, 9), 0.0);
  EXPECT_EQ(evaluate(F::sum_threshold, 0.4, 0.3, 0, 0.5), 1.0);
  EXPECT_EQ(evaluate(F::sum_threshold, 0.1, 0.3, 0, 0.5), 0.0);
  EXPECT_EQ(evaluate(F::greater_than, 2, 1, 0), 1.0);
  EXPECT_EQ(evaluate(F::greater_than, 1, 1, 0), 0.0);
  EXPECT_EQ(evaluate(F::sign_of, -3, 0, 0), -1.0);
  EXPECT_EQ(evaluate(F::sign_of, 0, 5, 0), 0.0);
  EXPECT_EQ(evaluate(F::sign_of, 0.1, 0, 0), 1.0);
  EXPECT_EQ(evaluate(F::min, 2, -1, 0), -1.0);
  EXPECT_EQ(evaluate(F::max, 2, -1, 0), 2.0);
  EXPECT_EQ(evaluate(F::abs, -2.5, 0, 0), 2.5);
  EXPECT_EQ(evaluate(F::if_positive, 1, 2, 3), 2.0);
  EXPECT_EQ(evaluate(F::if_positive, 0, 2, 3), 3.0);
  EXPECT_NEAR(evaluate(F::interpolate, 0.25, 2, 4), 2.5, kTol);
  EXPECT_EQ(evaluate(F::interpolate, -1, 2, 4), 2.0);
  EXPECT_EQ(evaluate(F::interpolate, 7, 2, 4), 4.0);
  EXPECT_NEAR(evaluate(F::sin, 0.5, 0, 0), std::sin(0.5), kTol);
  EXPECT_NEAR(evaluate(F::cos, 0.5, 0, 0), std::cos(0.5), kTol);
  EXPECT_NEAR(evaluate(F::atan, 2, 0, 0), std::atan(2.0), kTol);
  EXPECT_NEAR(evaluate(F::log, -2, 0, 0), std::log(2.0), kTol);
  EXPECT_NEAR(evaluate(F::log, 0, 0, 0), std::log(1e-6), kTol);
  EXPECT_NEAR(evaluate(F::expt, 1, 0, 0), std::exp(1.0), kTol);
  EXPECT_NEAR(evaluate(F::expt, 5, 0, 0), std::exp(5.0), 1e-9);
  EXPECT_EQ(evaluate(F::expt, 50, 0, 0), 1000.0);  // exp(10) then the output clamp
  EXPECT_NEAR(evaluate(F::sigmoid, 0.3, 0, 0), 1 / (1 + std::exp(-0.3)), kTol);
  // outputs are clamped to [-1000, 1000]
  EXPECT_EQ(evaluate(F::product, 100, 100, 0), 1000.0);
  EXPECT_EQ(evaluate(F::sum, -900, -900, 0), -1000.0);
}

// runs one neuron on a sequence of input values a and returns its outputs
std::vector<double> run(NeuronFunction function, const std::vector<double>& a, double parameter,
                        double time_step) {
  TestPlan plan = planWithSensors(1);
  plan.neurons.push_back(neuronOf(function, {Wire{0, 1}, Wire{}, Wire{}}, parameter));
  Brain brain(plan, time_step);
  std::vector<double> out;
  for (double value : a) {
    brain.sensors()[0] = value;
    brain.step();
    out.push_back(brain.signals()[1]);
  }
  return out;
}

// Chaumont et al.'s functions (Table I) on known inputs: sumT passes a + b from the threshold
// up, div gives 1 for b <= epsilon (negative b too), wav is b sin(a k + c) at step k
TEST(Brain, ChaumontFunctionsOnKnownInputs) {
  using F = NeuronFunction;
  EXPECT_NEAR(evaluate(F::sum_above, 0.3, 0.4, 0, 0.7), 0.7, kTol);
  EXPECT_EQ(evaluate(F::sum_above, 0.3, 0.39, 0, 0.7), 0.0);
  EXPECT_NEAR(evaluate(F::sum_above, -2, 0.5, 0, -3), -1.5, kTol);
  EXPECT_NEAR(evaluate(F::divide_or_one, 0.6, 0.3, 0), 2.0, kTol);
  EXPECT_EQ(evaluate(F::divide_or_one, 0.6, 0, 0), 1.0);
  EXPECT_EQ(evaluate(F::divide_or_one, 0.6, -0.5, 0), 1.0);
  EXPECT_NEAR(evaluate(F::wave, 0.5, 0.8, 0.3), 0.8 * std::sin(0.3), kTol);  // step 0

  TestPlan plan = planWithSensors(3);
  plan.neurons.push_back(neuronOf(F::wave, {Wire{0, 1}, Wire{1, 1}, Wire{2, 1}}));
  Brain brain(plan, 1.0 / 60);
  brain.sensors()[0] = 0.5;
  brain.sensors()[1] = 0.8;
  brain.sensors()[2] = 0.3;
  for (int k = 0; k < 7; ++k)
    brain.step();
  EXPECT_NEAR(brain.signals()[3], 0.8 * std::sin(0.5 * 6 + 0.3), kTol);  // the 7th step: k = 6
  EXPECT_EQ(neuronArity(F::sum_above), 2);
  EXPECT_EQ(neuronArity(F::divide_or_one), 2);
  EXPECT_EQ(neuronArity(F::delay), 1);
  EXPECT_EQ(neuronArity(F::wave), 3);
}

// mem: the input as it was n = round(|parameter|) steps ago (0 before), n in 1..255
TEST(Brain, DelayGivesTheInputOfNStepsAgo) {
  using F = NeuronFunction;
  EXPECT_EQ(run(F::delay, {1, 2, 3, 4, 5, 6}, 3, 0.1), (std::vector<double>{0, 0, 0, 1, 2, 3}));
  EXPECT_EQ(run(F::delay, {1, 2, 3}, -0.2, 0.1), (std::vector<double>{0, 1, 2}));  // at least 1
  std::vector<double> ramp(300);
  for (int k = 0; k < 300; ++k)
    ramp[k] = k + 1;
  EXPECT_EQ(run(F::delay, ramp, 100, 0.1)[101], 2.0);
  EXPECT_EQ(run(F::delay, ramp, 1000, 0.1)[256], 2.0);  // at most 255 steps

  // two delay neurons keep rings of their own, and reset empties them
  TestPlan plan = planWithSensors(1);
  plan.neurons.push_back(neuronOf(F::delay, {Wire{0, 1}, Wire{}, Wire{}}, 2));
  plan.neurons.push_back(neuronOf(F::delay, {Wire{0, -1}, Wire{}, Wire{}}, 1));
  Brain brain(plan, 0.1);
  for (double value : {1.0, 2.0, 3.0}) {
    brain.sensors()[0] = value;
    brain.step();
  }
  EXPECT_EQ(brain.signals()[1], 1.0);
  EXPECT_EQ(brain.signals()[2], -2.0);
  brain.reset();
  brain.step();
  EXPECT_EQ(brain.signals()[1], 0.0);
  EXPECT_EQ(brain.signals()[2], 0.0);
}

// Chaumont's network keeps every input and output within +-1 (signal_bound 1)
TEST(Brain, ChaumontBoundKeepsSignalsWithinOne) {
  auto network = std::make_shared<NeuralNetworkPlan>();
  network->sensor_count = 2;
  network->signal_bound = 1;
  network->neurons.push_back(neuronOf(NeuronFunction::sum, {Wire{0, 1}, Wire{1, 1}, Wire{}}));
  network->neurons.push_back(neuronOf(NeuronFunction::product, {Wire{0, 5}, Wire{1, 1}, Wire{}}));
  std::unique_ptr<Controller> brain = network->build(0.1, 2, 0);
  std::vector<double> sensors{0.8, 0.7}, drives;
  brain->step(sensors, drives);
  EXPECT_EQ(brain->signals()[2], 1.0);          // 1.5, bounded
  EXPECT_NEAR(brain->signals()[3], 0.7, kTol);  // 5 x 0.8 read as 1, times 0.7
  network->signal_bound = 0;
  EXPECT_THROW(network->build(0.1, 2, 0), Error);
}

TEST(Brain, StatefulFunctionsKeepTheirState) {
  using F = NeuronFunction;
  const auto integrate = run(F::integrate, {2, 2, 2, -1}, 0, 0.1);
  EXPECT_NEAR(integrate[0], 0.2, kTol);
  EXPECT_NEAR(integrate[2], 0.6, kTol);
  EXPECT_NEAR(integrate[3], 0.5, kTol);
  EXPECT_EQ(run(F::integrate, {1e6, 1e6}, 0, 1).back(), 1000.0);

  const auto differentiate = run(F::differentiate, {1, 3, 3}, 0, 0.1);
  EXPECT_NEAR(differentiate[0], 10, 1e-9);  // from the initial 0
  EXPECT_NEAR(differentiate[1], 20, 1e-9);
  EXPECT_NEAR(differentiate[2], 0, 1e-9);

  const auto smooth = run(F::smooth, {1, 1, 1}, 5, 0.1);  // rate min(1, 5 * 0.1) = 0.5
  EXPECT_NEAR(smooth[0], 0.5, kTol);
  EXPECT_NEAR(smooth[1], 0.75, kTol);
  EXPECT_NEAR(smooth[2], 0.875, kTol);
  EXPECT_NEAR(run(F::smooth, {1, 1}, 100, 0.1)[0], 1.0, kTol);  // rate capped at 1

  const auto memory = run(F::memory, {0.3, 0.8, 0.1, -0.9}, 0.5, 0.1);
  EXPECT_EQ(memory, (std::vector<double>{0, 0.8, 0.8, -0.9}));
}

TEST(Brain, OscillatorsRunAtTheirFrequency) {
  using F = NeuronFunction;
  const double dt = 0.01;
  const std::vector<double> zeros(200, 0.0);
  // 2 Hz wave: sin(2 pi 2 t) at t = k dt; step k starts at t = k dt
  const auto wave = run(F::oscillate_wave, zeros, 2, dt);
  for (int k = 0; k < 200; k += 7) {
    EXPECT_NEAR(wave[k], std::sin(2 * kPi * 2 * k * dt), 1e-9) << "step " << k;
  }
  // period 0.5 s = 50 steps
  EXPECT_NEAR(wave[13], wave[63], 1e-9);
  // frequencies above 4 Hz are capped; the input shifts the phase
  const auto fast = run(F::oscillate_wave, zeros, -10, dt);
  EXPECT_NEAR(fast[3], std::sin(2 * kPi * 4 * 3 * dt), 1e-9);
  const auto shifted = run(F::oscillate_wave, std::vector<double>(5, kPi / 2), 2, dt);
  EXPECT_NEAR(shifted[0], 1.0, 1e-12);
  // sawtooth: 0 at t = 0 rising like the sine, +0.5 a quarter period later, period 50 steps
  const auto saw = run(F::oscillate_saw, zeros, 2, dt);
  EXPECT_NEAR(saw[0], 0.0, 1e-12);
  EXPECT_NEAR(saw[12], 2 * (0.24 + 0.5) - 1, 1e-9);
  EXPECT_NEAR(saw[24], 2 * (0.48 + 0.5) - 1, 1e-9);
  EXPECT_LT(saw[26], -0.8);  // wrapped past the half period
  EXPECT_NEAR(saw[7], saw[57], 1e-9);
  for (double value : saw) {
    EXPECT_GE(value, -1.0);
    EXPECT_LE(value, 1.0);
  }
}

TEST(Brain, UpdateIsSynchronous) {
  using F = NeuronFunction;
  TestPlan plan = planWithSensors(1);
  // neuron 0 = 1; neuron 1 copies neuron 0; neuron 2 copies neuron 1; neuron 3 counts itself
  plan.neurons.push_back(neuronOf(F::constant, {}, 1));
  plan.neurons.push_back(neuronOf(F::sum, {Wire{plan.neuronSignal(0), 1}, Wire{}, Wire{}}));
  plan.neurons.push_back(neuronOf(F::sum, {Wire{plan.neuronSignal(1), 1}, Wire{}, Wire{}}));
  plan.neurons.push_back(neuronOf(F::sum, {Wire{plan.neuronSignal(3), 1}, Wire{-1, 1}, Wire{}}));
  Brain brain(plan, 0.1);
  const std::vector<std::vector<double>> expected{{1, 0, 0, 1}, {1, 1, 0, 2}, {1, 1, 1, 3}};
  for (const auto& row : expected) {
    brain.step();
    for (int n = 0; n < 4; ++n) {
      EXPECT_EQ(brain.signals()[plan.neuronSignal(n)], row[n]);
    }
  }
}

TEST(Brain, EffectorCommandsAddTheOscillatorAndAreClamped) {
  TestPlan plan = planWithSensors(1);
  plan.effectors.push_back({Wire{0, 1}, {}});
  plan.effectors.push_back({Wire{0, 2}, {true, 0.5, 1.0, kPi / 2, 0.2}});
  plan.effectors.push_back({Wire{-1, 0}, {true, 0.8, 2.0, 0.0, 0.0}});
  Brain brain(plan, 0.025);
  ASSERT_EQ(brain.effectors().size(), 3u);
  brain.sensors()[0] = 0.3;
  brain.step();  // t = 0
  EXPECT_NEAR(brain.effectors()[0], 0.3, kTol);
  EXPECT_NEAR(brain.effectors()[1], 1.0, kTol);  // 0.6 + 0.5 + 0.2 clamped
  EXPECT_NEAR(brain.effectors()[2], 0.0, kTol);
  brain.sensors()[0] = -5;
  brain.step();  // t = 0.025
  EXPECT_EQ(brain.effectors()[0], -1.0);
  EXPECT_EQ(brain.effectors()[1], -1.0);
  EXPECT_NEAR(brain.effectors()[2], 0.8 * std::sin(2 * kPi * 2 * 0.025), 1e-12);
  // a 2 Hz oscillator repeats every 20 steps of 0.025 s
  brain.sensors()[0] = 0;
  std::vector<double> third;
  for (int k = 2; k < 45; ++k) {
    brain.step();
    third.push_back(brain.effectors()[2]);
  }
  EXPECT_NEAR(third[3], third[23], 1e-9);
  EXPECT_NEAR(brain.time(), 45 * 0.025, 1e-12);
}

TEST(Brain, OutputsStayFiniteUnderHostileSensorValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> hostile{nan, inf, -inf, 1e308, -1e308, 0, 1e-320, -5e300};
  const int n_functions = static_cast<int>(NeuronFunction::count_);
  TestPlan plan = planWithSensors(3);
  // every function reading the sensors, and a second layer reading the first
  for (int f = 0; f < n_functions; ++f) {
    plan.neurons.push_back(
        neuronOf(static_cast<NeuronFunction>(f), {Wire{0, 5}, Wire{1, -5}, Wire{2, 5}}, 1e300));
  }
  for (int f = 0; f < n_functions; ++f) {
    plan.neurons.push_back(
        neuronOf(static_cast<NeuronFunction>(f),
                 {Wire{plan.neuronSignal(f), 5}, Wire{plan.neuronSignal((f + 1) % n_functions), 5},
                  Wire{plan.neuronSignal((f + 7) % n_functions), -5}},
                 -3));
  }
  plan.effectors.push_back({Wire{0, 1}, {true, 1e300, 4, 0, 1e300}});
  plan.effectors.push_back({Wire{plan.neuronSignal(3), 1}, {}});
  Brain brain(plan, 1.0 / 240);
  for (std::size_t i = 0; i < hostile.size() * hostile.size(); ++i) {
    brain.sensors()[0] = hostile[i % hostile.size()];
    brain.sensors()[1] = hostile[(i / hostile.size()) % hostile.size()];
    brain.sensors()[2] = hostile[(i * 3 + 1) % hostile.size()];
    brain.step();
    for (int n = 0; n < 2 * n_functions; ++n) {
      const double value = brain.signals()[plan.neuronSignal(n)];
      ASSERT_TRUE(std::isfinite(value)) << "neuron " << n << " step " << i;
      ASSERT_LE(std::fabs(value), 1000.0) << "neuron " << n << " step " << i;
    }
    for (double command : brain.effectors()) {
      ASSERT_TRUE(std::isfinite(command));
      ASSERT_LE(std::fabs(command), 1.0);
    }
  }
}

// a small network with every kind of state, driven by a fixed sensor sequence
std::vector<double> trace(Brain& brain, const TestPlan& plan, int steps) {
  std::vector<double> out;
  for (int k = 0; k < steps; ++k) {
    brain.sensors()[0] = std::sin(0.37 * k);
    brain.sensors()[1] = 0.5 * std::cos(0.11 * k);
    brain.step();
    for (int s = 0; s < plan.signalCount(); ++s) {
      out.push_back(brain.signals()[s]);
    }
    for (double command : brain.effectors()) {
      out.push_back(command);
    }
  }
  return out;
}

TEST(Brain, ResetRestoresTheInitialBehaviourExactly) {
  using F = NeuronFunction;
  TestPlan plan = planWithSensors(2);
  plan.neurons.push_back(neuronOf(F::integrate, {Wire{0, 1}, Wire{}, Wire{}}));
  plan.neurons.push_back(neuronOf(F::differentiate, {Wire{1, 2}, Wire{}, Wire{}}));
  plan.neurons.push_back(neuronOf(F::smooth, {Wire{plan.neuronSignal(0), 1}, Wire{}, Wire{}}, 3));
  plan.neurons.push_back(neuronOf(F::memory, {Wire{0, 1}, Wire{}, Wire{}}, 0.6));
  plan.neurons.push_back(neuronOf(F::oscillate_wave, {Wire{plan.neuronSignal(3), 1}, {}, {}}, 1.3));
  plan.neurons.push_back(
      neuronOf(F::sum, {Wire{plan.neuronSignal(4), 1}, Wire{plan.neuronSignal(5), 0.5}, {}}));
  plan.effectors.push_back({Wire{plan.neuronSignal(5), 1}, {true, 0.3, 1.7, 0.2, 0}});
  Brain brain(plan, 1.0 / 60);
  const std::vector<double> first = trace(brain, plan, 120);
  brain.reset();
  EXPECT_EQ(brain.time(), 0.0);
  for (int n = 0; n < static_cast<int>(plan.neurons.size()); ++n) {
    EXPECT_EQ(brain.signals()[plan.neuronSignal(n)], 0.0);
  }
  const std::vector<double> second = trace(brain, plan, 120);
  EXPECT_EQ(first, second);
  // a fresh brain behaves the same too
  Brain fresh(plan, 1.0 / 60);
  EXPECT_EQ(trace(fresh, plan, 120), first);
}

TEST(Brain, RejectsBadTimeStepsAndWires) {
  TestPlan plan = planWithSensors(2);
  EXPECT_THROW(Brain(plan, 0.0), ConfigError);
  EXPECT_THROW(Brain(plan, std::numeric_limits<double>::quiet_NaN()), ConfigError);
  plan.neurons.push_back(neuronOf(NeuronFunction::sum, {Wire{7, 1}, Wire{}, Wire{}}));
  EXPECT_THROW(Brain(plan, 0.1), Error);
  plan.neurons[0].inputs[0] = Wire{2, 1};
  EXPECT_NO_THROW(Brain(plan, 0.1));
  plan.effectors.push_back({Wire{3, 1}, {}});
  EXPECT_THROW(Brain(plan, 0.1), Error);
  // a plan made for another body
  NeuralNetworkPlan network;
  network.sensor_count = 2;
  EXPECT_THROW(network.build(0.1, 3, 0), Error);
  EXPECT_THROW(network.build(0.1, 2, 1), Error);
  SineOscillatorsPlan sine;
  sine.oscillators.resize(2);
  EXPECT_THROW(sine.build(0.1, 0, 3), Error);
}

// the controller of a developed creature
std::unique_ptr<Controller> controllerOf(const Creature& creature, double time_step) {
  return creature.controller->build(time_step, creature.body.sensors.size(),
                                    creature.body.effectors.size());
}

TEST(Brain, DevelopedRandomGenomesCompileAndStayFinite) {
  const graph::GenomeLimits limits;
  for (std::uint64_t individual = 0; individual < 200; ++individual) {
    const Creature creature =
        graph::develop(graph::randomGenome(limits, 17, 0, individual), limits);
    std::unique_ptr<Controller> controller = controllerOf(creature, 1.0 / 240);
    std::vector<double> sensors(creature.body.sensors.size());
    std::vector<double> drives(creature.body.effectors.size());
    for (int k = 0; k < 100; ++k) {
      for (std::size_t s = 0; s < sensors.size(); ++s)
        sensors[s] = std::sin(0.1 * k + static_cast<double>(s));
      controller->step(sensors, drives);
    }
    for (double value : controller->signals()) {
      ASSERT_TRUE(std::isfinite(value)) << "individual " << individual;
    }
    for (double drive : drives) {
      ASSERT_TRUE(std::isfinite(drive)) << "individual " << individual;
    }
  }
}

TEST(Brain, StepDoesNotAllocate) {
  const graph::GenomeLimits limits;
  for (std::uint64_t individual = 0; individual < 20; ++individual) {
    const Creature creature = graph::develop(graph::randomGenome(limits, 5, 0, individual), limits);
    std::unique_ptr<Controller> controller = controllerOf(creature, 1.0 / 240);
    std::vector<double> sensors(creature.body.sensors.size());
    std::vector<double> drives(creature.body.effectors.size());
    const long before = allocationCount();
    for (int k = 0; k < 500; ++k) {
      for (double& sensor : sensors)
        sensor = 0.5 * std::sin(0.01 * k);
      controller->step(sensors, drives);
    }
    controller->reset();
    controller->step(sensors, drives);
    EXPECT_EQ(allocationCount(), before) << "individual " << individual;
  }
}

// the oscillators alone: amplitude * sin(2 pi f t + phase) + offset at t = k dt, 0 when off
TEST(SineOscillators, DriveEachEffector) {
  SineOscillatorsPlan plan;
  plan.oscillators = {{true, 0.5, 2.0, 0.3, 0.1}, {false, 1, 1, 0, 0.7}};
  std::unique_ptr<Controller> controller = plan.build(0.01, 4, 2);
  std::vector<double> sensors(4, 9.0), drives(2, 5.0);
  for (int k = 0; k < 30; ++k) {
    controller->step(sensors, drives);
    EXPECT_NEAR(drives[0], 0.5 * std::sin(2 * kPi * 2.0 * k * 0.01 + 0.3) + 0.1, 1e-12);
    EXPECT_EQ(drives[1], 0.0);
  }
  controller->reset();
  controller->step(sensors, drives);
  EXPECT_NEAR(drives[0], 0.5 * std::sin(0.3) + 0.1, 1e-12);
  EXPECT_THROW(SineOscillators({}, 0.0), ConfigError);
}

// the sum adds its parts' drives in order and names itself after them
TEST(ControllerSum, AddsTheDrivesOfItsParts) {
  TestPlan plan = planWithSensors(1);
  plan.effectors.push_back({Wire{0, 0.25}, {true, 0.5, 1.0, 0.0, 0.0}});
  std::shared_ptr<const ControllerPlan> sum = controllerPlanOf(plan);
  EXPECT_EQ(sum->kind(), "network+sine");
  std::unique_ptr<Controller> controller = sum->build(0.05, 1, 1);
  std::vector<double> sensors{2.0}, drives(1);
  controller->step(sensors, drives);  // t = 0
  EXPECT_EQ(drives[0], 0.5);
  controller->step(sensors, drives);  // t = 0.05
  EXPECT_EQ(drives[0], 0.5 + (0.5 * std::sin(2 * kPi * 1.0 * 0.05 + 0.0) + 0.0));
}

}  // namespace
}  // namespace cambrian
