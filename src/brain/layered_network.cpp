// cambrian: Walking with Dinosaurs' layered network compiled into flat arrays and evaluated layer
// by layer, feed-forward within each step, without allocating.
#include "brain/layered_network.hpp"

#include "cambrian/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cambrian {
namespace {

// the seed's pi, kept so wave and saw nodes match it
constexpr double kSeedPi = 3.1415926;

// non-finite values become 0, finite ones are clamped to +-kLayeredBound
double bounded(double value) {
  if (!std::isfinite(value))
    return 0;
  return std::clamp(value, -kLayeredBound, kLayeredBound);
}

// where a node sits in the plan, for error messages ("subnet 2 layer 1 node 0")
std::string nodeName(const std::string& net, std::size_t layer, std::size_t node) {
  return net + " layer " + std::to_string(layer) + " node " + std::to_string(node);
}

// throws unless every layer of `net` is non-empty, every node's function is known, and every
// input it reads is inside its previous layer (`first_previous` nodes for the first layer) or,
// for a sensor node, inside the sensors
void checkNet(const LayeredNet& net, const std::string& name, std::size_t first_previous,
              std::size_t sensors) {
  if (net.layers.empty())
    throw Error(ExitCode::failure, "layered network: the " + name + " has no layers");
  std::size_t previous = first_previous;
  for (std::size_t l = 0; l < net.layers.size(); ++l) {
    const std::vector<LayeredNode>& layer = net.layers[l];
    if (layer.empty())
      throw Error(ExitCode::failure,
                  "layered network: the " + name + " layer " + std::to_string(l) + " is empty");
    for (std::size_t n = 0; n < layer.size(); ++n) {
      const LayeredNode& node = layer[n];
      const int function = static_cast<int>(node.function);
      if (function < -1 || function >= kLayeredFunctionKinds - 1)
        throw Error(ExitCode::failure, "layered network: " + nodeName(name, l, n) +
                                           " has unknown function " + std::to_string(function));
      if (node.input_count < 0 || node.input_count > 3)
        throw Error(ExitCode::failure, "layered network: " + nodeName(name, l, n) +
                                           " has input_count " + std::to_string(node.input_count) +
                                           ", not 0..3");
      // a sensor node reads inputs[0] as a sensor index, whatever its input_count
      if (node.function == LayeredFunction::sensor) {
        const int index = node.inputs[0].index;
        if (index < 0 || static_cast<std::size_t>(index) >= sensors)
          throw Error(ExitCode::failure, "layered network: " + nodeName(name, l, n) +
                                             " reads sensor " + std::to_string(index) +
                                             " but the body has " + std::to_string(sensors) +
                                             " sensors");
        continue;
      }
      for (int i = 0; i < node.input_count; ++i) {
        const int index = node.inputs[i].index;
        if (index < 0 || static_cast<std::size_t>(index) >= previous)
          throw Error(ExitCode::failure,
                      "layered network: " + nodeName(name, l, n) + " input " + std::to_string(i) +
                          " reads node " + std::to_string(index) + " but its previous layer has " +
                          std::to_string(previous) + " nodes");
      }
    }
    previous = layer.size();
  }
}

}  // namespace

const char* layeredFunctionName(LayeredFunction function) {
  static constexpr const char* kNames[] = {
      "sensor",  "sum",     "product",    "divide",    "sum_threshold", "greater_than",
      "sign_of", "minimum", "maximum",    "absolute",  "if_nonzero",    "interpolate",
      "sine",    "cosine",  "arctangent", "logarithm", "power",         "sigmoid",
      "wave",    "saw",     "constant"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) == kLayeredFunctionKinds);
  const int i = static_cast<int>(function) + 1;
  return i >= 0 && i < kLayeredFunctionKinds ? kNames[i] : "unknown";
}

std::unique_ptr<Controller> LayeredNetworkPlan::build(double, std::size_t sensors,
                                                      std::size_t effectors) const {
  // the body: a sensor per sensor the plan was made for, three effectors per joint
  if (sensors != sensor_count || effectors != 3 * joints.size())
    throw Error(ExitCode::failure,
                "layered network: made for " + std::to_string(sensor_count) + " sensors and " +
                    std::to_string(3 * joints.size()) + " effectors (3 per joint), the body has " +
                    std::to_string(sensors) + " and " + std::to_string(effectors));

  // the nets: the main net reads the sensors, every subnet the main net's last layer
  checkNet(main, "main net", sensors, sensors);
  const std::size_t main_last = main.layers.back().size();
  for (std::size_t s = 0; s < subnets.size(); ++s)
    checkNet(subnets[s], "subnet " + std::to_string(s), main_last, sensors);

  // the joints: each reads three nodes of an existing subnet's last layer
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const LayeredMuscles& joint = joints[j];
    if (joint.subnet < 0 || static_cast<std::size_t>(joint.subnet) >= subnets.size())
      throw Error(ExitCode::failure, "layered network: joint " + std::to_string(j) +
                                         " reads subnet " + std::to_string(joint.subnet) +
                                         " but the plan has " + std::to_string(subnets.size()) +
                                         " subnets");
    const std::size_t last = subnets[joint.subnet].layers.back().size();
    for (int k = 0; k < 3; ++k) {
      if (joint.nodes[k] < 0 || static_cast<std::size_t>(joint.nodes[k]) >= last)
        throw Error(ExitCode::failure, "layered network: joint " + std::to_string(j) + " axis " +
                                           std::to_string(k) + " reads node " +
                                           std::to_string(joint.nodes[k]) + " but subnet " +
                                           std::to_string(joint.subnet) + "'s last layer has " +
                                           std::to_string(last) + " nodes");
    }
  }
  return std::make_unique<LayeredNetwork>(*this);
}

int LayeredNetworkPlan::neuronCount() const {
  std::size_t count = 0;
  for (const auto& layer : main.layers)
    count += layer.size();
  for (const LayeredNet& subnet : subnets)
    for (const auto& layer : subnet.layers)
      count += layer.size();
  return static_cast<int>(count);
}

LayeredNetwork::LayeredNetwork(const LayeredNetworkPlan& plan) {
  sensor_count_ = static_cast<int>(plan.sensor_count);

  // one net's nodes, appended in evaluation order; `previous` is the signal of the first node
  // of the layer its first layer reads. Returns the signal of the first node of its last layer.
  auto compile = [this](const LayeredNet& net, int previous) {
    int start = sensor_count_ + node_count_;
    for (const std::vector<LayeredNode>& layer : net.layers) {
      start = sensor_count_ + node_count_;
      for (const LayeredNode& node : layer) {
        function_.push_back(static_cast<std::int8_t>(node.function));
        value_.push_back(node.value);
        count_.push_back(static_cast<std::uint8_t>(node.input_count));
        for (int i = 0; i < 3; ++i) {
          // a sensor node's first input names a sensor, which is its signal
          const bool sensor = node.function == LayeredFunction::sensor;
          source_.push_back(sensor ? node.inputs[0].index : previous + node.inputs[i].index);
          weight_.push_back(node.inputs[i].weight);
        }
        ++node_count_;
      }
      previous = start;
    }
    return start;
  };
  const int main_last = compile(plan.main, 0);
  std::vector<int> subnet_last;
  for (const LayeredNet& subnet : plan.subnets)
    subnet_last.push_back(compile(subnet, main_last));

  // the joints: three torque signals and a strength each
  for (const LayeredMuscles& joint : plan.joints) {
    for (int k = 0; k < 3; ++k)
      torque_.push_back(subnet_last[joint.subnet] + joint.nodes[k]);
    strength_.push_back(joint.strength);
  }
  signals_.assign(static_cast<std::size_t>(sensor_count_ + node_count_), 0.0);
  counter_.assign(static_cast<std::size_t>(node_count_), 0);
}

void LayeredNetwork::reset() {
  std::fill(signals_.begin(), signals_.end(), 0.0);
  std::fill(counter_.begin(), counter_.end(), 0);
}

void LayeredNetwork::step(std::span<const double> sensors, std::span<double> drives) {
  std::copy_n(sensors.begin(), std::min<std::size_t>(sensors.size(), sensor_count_),
              signals_.begin());
  double* signals = signals_.data();

  // every node in evaluation order, each reading the layer before it as computed this step.
  // An input the function reads but the node lacks takes the value that changes the result
  // least:
  //   function          missing input(s)              so that
  //   sum               a, b = 0                      sum of the present ones
  //   product           a, b = 1                      product of the present ones
  //   divide            a = 0, b = 1                  a / 1 = a
  //   sum_threshold     a, b = 0; c = 0               1 if a + b > 0
  //   greater_than      a = 0; b = 0                  1 if a > 0
  //   minimum, maximum  only the present ones count   0 when none is present
  //   interpolate       only the present ones count   their average, 0 when none
  //   if_nonzero        a = 0; b counts as nonzero    a
  //   power             a = 0; b = 1                  a
  //   one-input ones    a = 0                         f(0), e.g. sigmoid 0.5
  for (int n = 0; n < node_count_; ++n) {
    const int* source = source_.data() + 3 * n;
    const double* weight = weight_.data() + 3 * n;
    const int count = count_[n];
    // the weighted inputs present, missing ones `otherwise`
    auto input = [&](int i, double otherwise) {
      return i < count ? weight[i] * signals[source[i]] : otherwise;
    };
    double out = 0;
    switch (static_cast<LayeredFunction>(function_[n])) {
      case LayeredFunction::sensor:
        out = signals[source[0]];
        break;
      case LayeredFunction::sum:
        out = input(0, 0) + input(1, 0);
        break;
      case LayeredFunction::product:
        out = input(0, 1) * input(1, 1);
        break;
      case LayeredFunction::divide:
        out = input(0, 0) / input(1, 1);
        break;
      case LayeredFunction::sum_threshold:
        out = input(0, 0) + input(1, 0) > input(2, 0) ? 1.0 : 0.0;
        break;
      case LayeredFunction::greater_than:
        out = input(0, 0) > input(1, 0) ? 1.0 : 0.0;
        break;
      case LayeredFunction::sign_of: {
        const double a = input(0, 0);
        out = a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
        break;
      }
      case LayeredFunction::minimum:
      case LayeredFunction::maximum: {
        const bool least = static_cast<LayeredFunction>(function_[n]) == LayeredFunction::minimum;
        for (int i = 0; i < count; ++i) {
          const double v = input(i, 0);
          out = i == 0 ? v : (least ? std::min(out, v) : std::max(out, v));
        }
        break;
      }
      case LayeredFunction::absolute:
        out = std::fabs(input(0, 0));
        break;
      case LayeredFunction::if_nonzero:
        out = count < 2 || input(1, 0) != 0 ? input(0, 0) : 0.0;
        break;
      case LayeredFunction::interpolate: {
        for (int i = 0; i < count; ++i)
          out += input(i, 0);
        out = count > 0 ? out / count : 0.0;
        break;
      }
      case LayeredFunction::sine:
        out = std::sin(input(0, 0));
        break;
      case LayeredFunction::cosine:
        out = std::cos(input(0, 0));
        break;
      case LayeredFunction::arctangent:
        out = std::atan(input(0, 0));
        break;
      case LayeredFunction::logarithm: {
        const double a = input(0, 0);
        out = a > 0 ? std::log(a) : a;
        break;
      }
      case LayeredFunction::power:
        out = std::pow(input(0, 0), input(1, 1));
        break;
      case LayeredFunction::sigmoid:
        out = 1.0 / (1.0 + std::exp(-input(0, 0)));
        break;
      // wave and saw ignore their inputs: k is how many times the node was calculated before
      case LayeredFunction::wave:
        out = std::sin(static_cast<double>(counter_[n]) * 2 * kSeedPi / 360);
        break;
      case LayeredFunction::saw:
        out = std::sin(static_cast<double>(counter_[n]) * 2 * kSeedPi / 4);
        break;
      case LayeredFunction::constant:
        out = value_[n];
        break;
    }
    ++counter_[n];
    signals[sensor_count_ + n] = bounded(out);
  }

  // each joint's torques, held together to its strength, as fractions of the strength
  for (std::size_t j = 0; j < strength_.size() && 3 * j + 2 < drives.size(); ++j) {
    const double strength = strength_[j];
    const double t0 = signals[torque_[3 * j]];
    const double t1 = signals[torque_[3 * j + 1]];
    const double t2 = signals[torque_[3 * j + 2]];
    const double norm = std::sqrt(t0 * t0 + t1 * t1 + t2 * t2);
    // a non-positive (or NaN) strength drives nothing
    double scale = 0;
    if (strength > 0)
      scale = (norm > strength ? strength / norm : 1.0) / strength;
    drives[3 * j] = t0 * scale;
    drives[3 * j + 1] = t1 * scale;
    drives[3 * j + 2] = t2 * scale;
  }
}

}  // namespace cambrian
