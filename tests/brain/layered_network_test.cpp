// Tests of Walking with Dinosaurs' layered network: every node function and its missing-input
// defaults, feed-forward layers and subnets, wave and saw counters, joint strengths, finiteness,
// build()'s refusals, reset and allocation-free steps.
#include "brain/layered_network.hpp"

#include "cambrian/error.hpp"

#include "brain/allocation_counter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace cambrian {
namespace {

using F = LayeredFunction;
constexpr double kTol = 1e-12;

// a node of `function` reading `inputs` (input_count = their number)
LayeredNode nodeOf(F function, std::vector<LayeredInput> inputs = {}, double value = 0) {
  LayeredNode node;
  node.function = function;
  node.value = value;
  node.input_count = static_cast<int>(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
    node.inputs[i] = inputs[i];
  return node;
}

// a sensor node reading sensor `index`
LayeredNode sensorNode(int index) {
  return nodeOf(F::sensor, {{index, 1}});
}

// a constant node of value `value`
LayeredNode constantNode(double value) {
  return nodeOf(F::constant, {}, value);
}

// a built network with no joints
std::unique_ptr<Controller> buildWithoutJoints(const LayeredNetworkPlan& plan) {
  return plan.build(0.01, plan.sensor_count, 0);
}

// one node of `function` fed `values` (each from a sensor node, times `weights`, 1 if not
// given): its value after one step
double evaluate(F function, std::vector<double> values, std::vector<double> weights = {},
                double value = 0) {
  LayeredNetworkPlan plan;
  plan.sensor_count = values.size();
  std::vector<LayeredNode> first;
  std::vector<LayeredInput> inputs;
  for (std::size_t i = 0; i < values.size(); ++i) {
    first.push_back(sensorNode(static_cast<int>(i)));
    inputs.push_back({static_cast<int>(i), i < weights.size() ? weights[i] : 1.0});
  }
  // a first layer cannot be empty: with no inputs, a constant stands in
  if (first.empty())
    first.push_back(constantNode(0));
  plan.main.layers = {first, {nodeOf(function, inputs, value)}};
  std::unique_ptr<Controller> controller = buildWithoutJoints(plan);
  std::vector<double> drives;
  controller->step(values, drives);
  return controller->signals().back();
}

// a plan build() accepts: 2 sensors, a two-layer main net, one two-layer subnet, one joint
LayeredNetworkPlan validPlan() {
  LayeredNetworkPlan plan;
  plan.sensor_count = 2;
  plan.main.layers = {{sensorNode(0), sensorNode(1)}, {nodeOf(F::sum, {{0, 1}, {1, 1}})}};
  LayeredNet subnet;
  subnet.layers = {{nodeOf(F::product, {{0, 2}})},
                   {constantNode(0.5), constantNode(-0.25), nodeOf(F::sum, {{0, 1}})}};
  plan.subnets = {subnet};
  plan.joints = {{0, {0, 1, 2}, 1.0}};
  return plan;
}

// build() of `plan` for `sensors` and `effectors` throws Error(failure) naming `word`
void expectRefusal(const LayeredNetworkPlan& plan, std::size_t sensors, std::size_t effectors,
                   const std::string& word) {
  try {
    plan.build(0.01, sensors, effectors);
    ADD_FAILURE() << "build() accepted a plan it should refuse for '" << word << "'";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ExitCode::failure);
    EXPECT_NE(std::string(error.what()).find(word), std::string::npos)
        << "message '" << error.what() << "' does not name '" << word << "'";
  }
}

// the kind and the names of the functions
TEST(LayeredNetwork, NamesItsKindAndFunctions) {
  EXPECT_EQ(LayeredNetworkPlan().kind(), "layered");
  EXPECT_STREQ(layeredFunctionName(F::sensor), "sensor");
  EXPECT_STREQ(layeredFunctionName(F::sum), "sum");
  EXPECT_STREQ(layeredFunctionName(F::sum_threshold), "sum_threshold");
  EXPECT_STREQ(layeredFunctionName(F::if_nonzero), "if_nonzero");
  EXPECT_STREQ(layeredFunctionName(F::arctangent), "arctangent");
  EXPECT_STREQ(layeredFunctionName(F::saw), "saw");
  EXPECT_STREQ(layeredFunctionName(F::constant), "constant");
  EXPECT_STREQ(layeredFunctionName(static_cast<F>(20)), "unknown");
  EXPECT_STREQ(layeredFunctionName(static_cast<F>(-2)), "unknown");
}

// every function on hand-computed inputs
TEST(LayeredNetwork, EveryFunctionComputesItsFormula) {
  EXPECT_NEAR(evaluate(F::sum, {2, 3}), 5, kTol);
  EXPECT_NEAR(evaluate(F::product, {2, -3}), -6, kTol);
  EXPECT_NEAR(evaluate(F::divide, {3, 4}), 0.75, kTol);
  EXPECT_EQ(evaluate(F::sum_threshold, {1, 2, 2.5}), 1);
  EXPECT_EQ(evaluate(F::sum_threshold, {1, 1, 2.5}), 0);
  EXPECT_EQ(evaluate(F::sum_threshold, {1, 1.5, 2.5}), 0);  // not above c
  EXPECT_EQ(evaluate(F::greater_than, {2, 1}), 1);
  EXPECT_EQ(evaluate(F::greater_than, {1, 2}), 0);
  EXPECT_EQ(evaluate(F::greater_than, {1, 1}), 0);
  EXPECT_EQ(evaluate(F::sign_of, {-3}), -1);
  EXPECT_EQ(evaluate(F::sign_of, {2}), 1);
  EXPECT_EQ(evaluate(F::sign_of, {0}), 0);
  EXPECT_EQ(evaluate(F::minimum, {3, -1, 2}), -1);
  EXPECT_EQ(evaluate(F::maximum, {3, -1, 2}), 3);
  EXPECT_EQ(evaluate(F::absolute, {-2.5}), 2.5);
  EXPECT_EQ(evaluate(F::if_nonzero, {4, 1}), 4);
  EXPECT_EQ(evaluate(F::if_nonzero, {4, -0.5}), 4);
  EXPECT_EQ(evaluate(F::if_nonzero, {4, 0}), 0);
  EXPECT_NEAR(evaluate(F::interpolate, {1, 2, 6}), 3, kTol);
  EXPECT_NEAR(evaluate(F::sine, {0.5}), std::sin(0.5), kTol);
  EXPECT_NEAR(evaluate(F::cosine, {0.5}), std::cos(0.5), kTol);
  EXPECT_NEAR(evaluate(F::arctangent, {2}), std::atan(2.0), kTol);
  EXPECT_NEAR(evaluate(F::logarithm, {std::numbers::e}), 1, kTol);
  EXPECT_EQ(evaluate(F::logarithm, {-2}), -2);
  EXPECT_EQ(evaluate(F::logarithm, {0}), 0);
  EXPECT_NEAR(evaluate(F::power, {2, 3}), 8, kTol);
  EXPECT_NEAR(evaluate(F::power, {9, 0.5}), 3, kTol);
  EXPECT_NEAR(evaluate(F::sigmoid, {0}), 0.5, kTol);
  EXPECT_NEAR(evaluate(F::sigmoid, {1}), 1 / (1 + std::exp(-1.0)), kTol);
  EXPECT_EQ(evaluate(F::constant, {}, {}, 7.5), 7.5);
  EXPECT_EQ(evaluate(F::constant, {1, 2}, {}, -7.5), -7.5);  // inputs ignored
}

// an input's value is its weight times its source's value (sigmoid's too)
TEST(LayeredNetwork, InputsAreWeighted) {
  EXPECT_NEAR(evaluate(F::sum, {3, 4}, {2, -1}), 2, kTol);
  EXPECT_NEAR(evaluate(F::greater_than, {3, 4}, {2, 1}), 1, kTol);
  EXPECT_NEAR(evaluate(F::sigmoid, {1}, {2}), 1 / (1 + std::exp(-2.0)), kTol);
  EXPECT_NEAR(evaluate(F::interpolate, {1, 1, 1}, {1, 2, 6}), 3, kTol);
  EXPECT_NEAR(evaluate(F::sine, {1}, {0.5}), std::sin(0.5), kTol);
}

// an input the node lacks takes the value that changes the result least
TEST(LayeredNetwork, MissingInputsTakeTheValueThatChangesTheResultLeast) {
  // sum: 0
  EXPECT_EQ(evaluate(F::sum, {2}), 2);
  EXPECT_EQ(evaluate(F::sum, {}), 0);
  // product: 1
  EXPECT_EQ(evaluate(F::product, {3}), 3);
  EXPECT_EQ(evaluate(F::product, {}), 1);
  // divide: b = 1 (a = 0)
  EXPECT_EQ(evaluate(F::divide, {3}), 3);
  EXPECT_EQ(evaluate(F::divide, {}), 0);
  // sum_threshold: a, b, c = 0
  EXPECT_EQ(evaluate(F::sum_threshold, {1, 2}), 1);
  EXPECT_EQ(evaluate(F::sum_threshold, {-1, 0.5}), 0);
  EXPECT_EQ(evaluate(F::sum_threshold, {0.5}), 1);
  EXPECT_EQ(evaluate(F::sum_threshold, {}), 0);
  // greater_than: b = 0
  EXPECT_EQ(evaluate(F::greater_than, {0.5}), 1);
  EXPECT_EQ(evaluate(F::greater_than, {-0.5}), 0);
  EXPECT_EQ(evaluate(F::greater_than, {}), 0);
  // minimum and maximum: only the present inputs, 0 with none
  EXPECT_EQ(evaluate(F::minimum, {4, 2}), 2);
  EXPECT_EQ(evaluate(F::minimum, {4}), 4);
  EXPECT_EQ(evaluate(F::minimum, {}), 0);
  EXPECT_EQ(evaluate(F::maximum, {-4, -2}), -2);
  EXPECT_EQ(evaluate(F::maximum, {-4}), -4);
  EXPECT_EQ(evaluate(F::maximum, {}), 0);
  // interpolate: the average of the present inputs, 0 with none
  EXPECT_NEAR(evaluate(F::interpolate, {1, 2}), 1.5, kTol);
  EXPECT_EQ(evaluate(F::interpolate, {6}), 6);
  EXPECT_EQ(evaluate(F::interpolate, {}), 0);
  // if_nonzero: a missing b counts as nonzero
  EXPECT_EQ(evaluate(F::if_nonzero, {5}), 5);
  EXPECT_EQ(evaluate(F::if_nonzero, {}), 0);
  // power: b = 1
  EXPECT_EQ(evaluate(F::power, {5}), 5);
  EXPECT_EQ(evaluate(F::power, {}), 0);
  // one-input functions: a = 0
  EXPECT_EQ(evaluate(F::sign_of, {}), 0);
  EXPECT_EQ(evaluate(F::absolute, {}), 0);
  EXPECT_EQ(evaluate(F::sine, {}), 0);
  EXPECT_EQ(evaluate(F::cosine, {}), 1);
  EXPECT_EQ(evaluate(F::arctangent, {}), 0);
  EXPECT_EQ(evaluate(F::logarithm, {}), 0);
  EXPECT_EQ(evaluate(F::sigmoid, {}), 0.5);
}

// a sensor node reads a sensor of the whole array, unweighted, in whichever layer it is
TEST(LayeredNetwork, SensorNodesReadTheirSensorUnweightedInAnyLayer) {
  LayeredNetworkPlan plan;
  plan.sensor_count = 3;
  plan.main.layers = {{nodeOf(F::sensor, {{1, 5}})},
                      {nodeOf(F::sum, {{0, 1}})},
                      {nodeOf(F::sensor, {{2, -3}}), nodeOf(F::sensor, {{0, 1}})}};
  LayeredNet subnet;
  subnet.layers = {{nodeOf(F::sensor, {{2, 7}}, 0)}};
  subnet.layers[0][0].input_count = 0;  // reads inputs[0] whatever its input count
  plan.subnets = {subnet};
  std::unique_ptr<Controller> controller = buildWithoutJoints(plan);
  std::vector<double> sensors{0.25, -1.5, 4}, drives;
  controller->step(sensors, drives);
  const std::vector<double> expected{0.25, -1.5, 4, -1.5, -1.5, 4, 0.25, 4};
  EXPECT_EQ(std::vector<double>(controller->signals().begin(), controller->signals().end()),
            expected);
}

// feed-forward: a change in a sensor reaches a three-layer net's last layer in the same step
TEST(LayeredNetwork, EachLayerReadsTheLayerComputedBeforeItInTheSameStep) {
  LayeredNetworkPlan plan;
  plan.sensor_count = 1;
  plan.main.layers = {{sensorNode(0), constantNode(1)},
                      {nodeOf(F::sum, {{0, 2}, {1, 1}})},
                      {nodeOf(F::product, {{0, 3}})}};
  std::unique_ptr<Controller> controller = buildWithoutJoints(plan);
  std::vector<double> sensors{1}, drives;
  controller->step(sensors, drives);
  EXPECT_EQ(controller->signals().back(), 9);  // 3 (2 x 1 + 1)
  sensors[0] = -2;
  controller->step(sensors, drives);
  EXPECT_EQ(controller->signals().back(), -9);  // 3 (2 x -2 + 1)
}

// subnets follow the main net, subnet 0 first, each first layer reading the main net's last
// layer as computed this step; signals are the sensors then the nodes in that order
TEST(LayeredNetwork, SubnetsReadTheMainNetsLastLayerThisStep) {
  LayeredNetworkPlan plan;
  plan.sensor_count = 2;
  plan.main.layers = {{sensorNode(0), sensorNode(1)},
                      {nodeOf(F::product, {{0, 1}, {1, 1}}), constantNode(10)}};
  LayeredNet first, second;
  first.layers = {{nodeOf(F::sum, {{0, 1}, {1, 1}})}, {nodeOf(F::product, {{0, 2}})}};
  second.layers = {{nodeOf(F::sum, {{0, -1}, {1, 0.5}}), nodeOf(F::sensor, {{1, 1}})}};
  plan.subnets = {first, second};
  EXPECT_EQ(plan.neuronCount(), 8);
  std::unique_ptr<Controller> controller = buildWithoutJoints(plan);
  std::vector<double> sensors{2, 3}, drives;
  controller->step(sensors, drives);
  // sensors; main: 2, 3, 6, 10; subnet 0: 16, 32; subnet 1: -6 + 5, 3
  const std::vector<double> expected{2, 3, 2, 3, 6, 10, 16, 32, -1, 3};
  EXPECT_EQ(std::vector<double>(controller->signals().begin(), controller->signals().end()),
            expected);
  sensors = {1, -1};
  controller->step(sensors, drives);
  const std::vector<double> next{1, -1, 1, -1, -1, 10, 9, 18, 6, -1};
  EXPECT_EQ(std::vector<double>(controller->signals().begin(), controller->signals().end()), next);
}

// wave gives sin(k 2 pi / 360) and saw sin(k 2 pi / 4), k the node's earlier calculations,
// whatever their inputs; reset() starts them again
TEST(LayeredNetwork, WaveAndSawCountTheirCalculationsAndRestartAfterReset) {
  LayeredNetworkPlan plan;
  plan.sensor_count = 1;
  plan.main.layers = {{sensorNode(0)},
                      {nodeOf(F::wave, {{0, 1}}), nodeOf(F::saw, {{0, 1}}), nodeOf(F::wave)}};
  std::unique_ptr<Controller> controller = buildWithoutJoints(plan);
  std::vector<double> sensors{0.7}, drives;
  const double saw[] = {0, 1, 0, -1, 0, 1, 0, -1};
  for (int round = 0; round < 2; ++round) {
    for (int k = 0; k < 8; ++k) {
      sensors[0] = 0.3 * k;
      controller->step(sensors, drives);
      const double wave = std::sin(k * 2 * std::numbers::pi / 360);
      EXPECT_NEAR(controller->signals()[2], wave, 1e-6) << "round " << round << " k " << k;
      EXPECT_NEAR(controller->signals()[3], saw[k], 1e-6) << "round " << round << " k " << k;
      EXPECT_NEAR(controller->signals()[4], wave, 1e-6) << "round " << round << " k " << k;
    }
    controller->reset();
  }
}

// a joint's three torques are scaled together to its strength; each drive is torque / strength
TEST(LayeredNetwork, JointTorquesAreHeldTogetherToTheStrength) {
  LayeredNetworkPlan plan;
  plan.main.layers = {{constantNode(1)}};
  LayeredNet subnet;
  subnet.layers = {{constantNode(3), constantNode(4), constantNode(0)}};
  plan.subnets = {subnet, subnet, subnet, subnet};
  plan.joints = {{0, {0, 1, 2}, 2.5},  // |(3, 4, 0)| = 5 > 2.5: scaled by a half
                 {1, {0, 1, 2}, 10},   // below the strength: unchanged
                 {2, {2, 0, 1}, 5},    // at the strength: unchanged, axes as named
                 {3, {0, 1, 2}, 0}};   // no strength: no drive
  std::unique_ptr<Controller> controller = plan.build(0.01, 0, 12);
  std::vector<double> sensors, drives(12, 9.0);
  controller->step(sensors, drives);
  const std::vector<double> expected{0.6, 0.8, 0, 0.3, 0.4, 0, 0, 0.6, 0.8, 0, 0, 0};
  for (std::size_t e = 0; e < expected.size(); ++e)
    EXPECT_NEAR(drives[e], expected[e], kTol) << "effector " << e;
}

// a joint's torques come from its own subnet's last layer
TEST(LayeredNetwork, JointsReadTheirSubnetsLastLayer) {
  LayeredNetworkPlan plan;
  plan.sensor_count = 1;
  plan.main.layers = {{sensorNode(0)}};
  LayeredNet subnet;
  subnet.layers = {{constantNode(0.5)},
                   {nodeOf(F::product, {{0, 1}}), constantNode(-0.25), constantNode(0.125)}};
  LayeredNet other;
  other.layers = {{nodeOf(F::product, {{0, 0.5}})}};
  plan.subnets = {subnet, other};
  plan.joints = {{1, {0, 0, 0}, 100}, {0, {2, 1, 0}, 1}};
  std::unique_ptr<Controller> controller = plan.build(0.01, 1, 6);
  std::vector<double> sensors{8}, drives(6);
  controller->step(sensors, drives);
  const std::vector<double> expected{0.04, 0.04, 0.04, 0.125, -0.25, 0.5};
  for (std::size_t e = 0; e < expected.size(); ++e)
    EXPECT_NEAR(drives[e], expected[e], kTol) << "effector " << e;
}

// non-finite results become 0 and huge ones are held to +-kLayeredBound
TEST(LayeredNetwork, NonFiniteResultsBecomeFiniteAndLargeOnesAreBounded) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(evaluate(F::divide, {0, 0}), 0);
  EXPECT_EQ(evaluate(F::divide, {1, 0}), 0);
  EXPECT_EQ(evaluate(F::power, {-8, 0.5}), 0);
  EXPECT_EQ(evaluate(F::power, {10, 400}), 0);
  EXPECT_EQ(evaluate(F::power, {10, 7}), kLayeredBound);
  EXPECT_EQ(evaluate(F::product, {-1e6, 1e6}), -kLayeredBound);
  EXPECT_EQ(evaluate(F::sensor, {nan}), 0);
  EXPECT_EQ(evaluate(F::sum, {1, 1}, {nan, 1}), 0);
  EXPECT_EQ(evaluate(F::constant, {}, {}, std::numeric_limits<double>::infinity()), 0);
  EXPECT_EQ(evaluate(F::constant, {}, {}, -1e9), -kLayeredBound);
  // a sigmoid of a huge input stays finite
  EXPECT_EQ(evaluate(F::sigmoid, {-1e6}, {1e6}), 0);
}

// build() refuses a plan that does not fit the body or reads outside its layers
TEST(LayeredNetwork, BuildRefusesInconsistentPlans) {
  EXPECT_NO_THROW(validPlan().build(0.01, 2, 3));
  // the body
  expectRefusal(validPlan(), 2, 4, "effectors");
  expectRefusal(validPlan(), 3, 3, "sensors");
  // nets and layers
  LayeredNetworkPlan plan = validPlan();
  plan.main.layers.clear();
  expectRefusal(plan, 2, 3, "no layers");
  plan = validPlan();
  plan.subnets[0].layers.clear();
  expectRefusal(plan, 2, 3, "no layers");
  plan = validPlan();
  plan.main.layers[1].clear();
  expectRefusal(plan, 2, 3, "empty");
  plan = validPlan();
  plan.subnets[0].layers[0].clear();
  expectRefusal(plan, 2, 3, "empty");
  // inputs
  plan = validPlan();
  plan.main.layers[1][0].inputs[1].index = 2;
  expectRefusal(plan, 2, 3, "previous layer");
  plan = validPlan();
  plan.main.layers[1][0].inputs[0].index = -1;
  expectRefusal(plan, 2, 3, "previous layer");
  plan = validPlan();
  plan.subnets[0].layers[0][0].inputs[0].index = 1;  // the main net's last layer has 1 node
  expectRefusal(plan, 2, 3, "previous layer");
  plan = validPlan();
  plan.subnets[0].layers[1][2].inputs[0].index = 1;  // the subnet's first layer has 1 node
  expectRefusal(plan, 2, 3, "previous layer");
  plan = validPlan();
  plan.main.layers[1][0].input_count = 4;
  expectRefusal(plan, 2, 3, "input_count");
  plan = validPlan();
  plan.main.layers[1][0].input_count = -1;
  expectRefusal(plan, 2, 3, "input_count");
  plan = validPlan();
  plan.main.layers[1][0].function = static_cast<F>(20);
  expectRefusal(plan, 2, 3, "unknown function");
  plan = validPlan();
  plan.main.layers[1][0].function = static_cast<F>(-2);
  expectRefusal(plan, 2, 3, "unknown function");
  // sensor nodes
  plan = validPlan();
  plan.main.layers[0][1].inputs[0].index = 2;
  expectRefusal(plan, 2, 3, "sensor 2");
  plan = validPlan();
  plan.subnets[0].layers[1][0] = sensorNode(-1);
  expectRefusal(plan, 2, 3, "sensor -1");
  plan = validPlan();
  plan.sensor_count = 0;
  plan.main.layers[0] = {constantNode(1), constantNode(2)};
  plan.main.layers[1][0] = sensorNode(0);
  expectRefusal(plan, 0, 3, "0 sensors");
  // joints
  plan = validPlan();
  plan.joints[0].subnet = 1;
  expectRefusal(plan, 2, 3, "subnet");
  plan = validPlan();
  plan.joints[0].subnet = -1;
  expectRefusal(plan, 2, 3, "subnet");
  plan = validPlan();
  plan.joints[0].nodes[2] = 3;
  expectRefusal(plan, 2, 3, "last layer");
  plan = validPlan();
  plan.joints[0].nodes[0] = -1;
  expectRefusal(plan, 2, 3, "last layer");
}

// neuronCount() counts every node of the main net and the subnets
TEST(LayeredNetwork, NeuronCountCountsEveryNodeOfEveryNet) {
  EXPECT_EQ(validPlan().neuronCount(), 7);
  EXPECT_EQ(LayeredNetworkPlan().neuronCount(), 0);
}

// a plan exercising every function, its outputs over `steps` steps (signals and drives)
std::vector<std::vector<double>> run(Controller& controller, int steps) {
  std::vector<std::vector<double>> outputs;
  std::vector<double> sensors(2), drives(3);
  for (int k = 0; k < steps; ++k) {
    sensors = {0.5 * std::sin(0.1 * k), std::cos(0.07 * k)};
    controller.step(sensors, drives);
    std::vector<double> out(controller.signals().begin(), controller.signals().end());
    out.insert(out.end(), drives.begin(), drives.end());
    outputs.push_back(out);
  }
  return outputs;
}

// a plan with a node of every function between the main net's layers
LayeredNetworkPlan everyFunctionPlan() {
  LayeredNetworkPlan plan = validPlan();
  std::vector<LayeredNode> middle;
  for (int f = -1; f < kLayeredFunctionKinds - 1; ++f)
    middle.push_back(nodeOf(static_cast<F>(f), {{0, 1.5}, {1, -0.75}, {1, 0.5}}, 0.3));
  std::vector<LayeredInput> inputs{{0, 1}, {18, 1}, {20, 1}};  // sensor, wave, constant
  plan.main.layers = {plan.main.layers[0], middle, {nodeOf(F::interpolate, inputs)}};
  return plan;
}

// step() allocates nothing, before or after reset()
TEST(LayeredNetwork, StepDoesNotAllocate) {
  std::unique_ptr<Controller> controller = everyFunctionPlan().build(0.01, 2, 3);
  std::vector<double> sensors(2), drives(3);
  const long before = allocationCount();
  for (int k = 0; k < 500; ++k) {
    sensors = {std::sin(0.01 * k), std::cos(0.01 * k)};
    controller->step(sensors, drives);
  }
  controller->reset();
  controller->step(sensors, drives);
  EXPECT_EQ(allocationCount(), before);
}

// reset() brings back the first steps' outputs exactly
TEST(LayeredNetwork, ResetRestoresTheFirstStepsOutputsExactly) {
  std::unique_ptr<Controller> controller = everyFunctionPlan().build(0.01, 2, 3);
  const auto first = run(*controller, 50);
  controller->reset();
  for (double signal : controller->signals())
    EXPECT_EQ(signal, 0);
  EXPECT_EQ(run(*controller, 50), first);
  // the outputs were not all alike: the wave and the drives moved
  EXPECT_NE(first.front(), first.back());
}

}  // namespace
}  // namespace cambrian
