// cambrian: Walking with Dinosaurs' layered network as a controller — a main net fed by the
// sensors and one subnet per joint fed by the main net's last layer, every layer computed in
// order each step; a joint's three muscles read three nodes of its subnet's last layer, and their
// torques together are held to the joint's strength.
#pragma once

#include "cambrian/controller.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cambrian {

/// WWD's node functions, numbered as the seed numbers them (sensor is its function -1).
enum class LayeredFunction : std::int8_t {
  sensor = -1,    ///< sensor `inputs[0].index` as it was read after the last physics step
  sum = 0,        ///< a + b
  product,        ///< a b
  divide,         ///< a / b
  sum_threshold,  ///< 1 if a + b > c, else 0
  greater_than,   ///< 1 if a > b, else 0
  sign_of,        ///< 1, -1 or 0 by the sign of a
  minimum,        ///< the least of a, b, c
  maximum,        ///< the greatest of a, b, c
  absolute,       ///< |a|
  if_nonzero,     ///< a if b != 0, else 0
  interpolate,    ///< (a + b + c) / 3
  sine,           ///< sin a
  cosine,         ///< cos a
  arctangent,     ///< atan a
  logarithm,      ///< ln a if a > 0, else a
  power,          ///< a to the power b
  sigmoid,        ///< 1 / (1 + exp(-a))
  wave,           ///< sin(k 2 pi / 360), k the node's calculations before this one
  saw,            ///< sin(k 2 pi / 4)
  constant,       ///< the node's value (the grammar's `value` node)
};
/// Number of LayeredFunction values from sensor to constant.
constexpr int kLayeredFunctionKinds = 21;
/// Lower-case name ("sum_threshold").
const char* layeredFunctionName(LayeredFunction function);

/// One weighted input of a node: weight x (the previous layer's node `index`). A sensor node's
/// first input names a sensor instead and its weight is not used.
struct LayeredInput {
  int index = 0;
  double weight = 1;
  friend bool operator==(const LayeredInput&, const LayeredInput&) = default;
};

/// A node: its function, its value (constant nodes) and 0 to 3 inputs. An input a function reads
/// but the node lacks takes the value that changes the result least (see layered_network.cpp).
struct LayeredNode {
  LayeredFunction function = LayeredFunction::constant;
  double value = 0;
  int input_count = 0;  ///< 0..3
  std::array<LayeredInput, 3> inputs{};
  friend bool operator==(const LayeredNode&, const LayeredNode&) = default;
};

/// A net: layers of nodes. The first layer reads the sensors (the main net) or the main net's
/// last layer (a subnet); each later layer reads the one before it.
struct LayeredNet {
  std::vector<std::vector<LayeredNode>> layers;  ///< at least one layer of at least one node
  friend bool operator==(const LayeredNet&, const LayeredNet&) = default;
};

/// A joint's three muscles: the nodes of its subnet's last layer that drive its axes, and its
/// strength. Effectors 3j, 3j + 1, 3j + 2 of the body are joint j's axes 0, 1, 2.
struct LayeredMuscles {
  int subnet = 0;              ///< index into LayeredNetworkPlan::subnets
  std::array<int, 3> nodes{};  ///< in the subnet's last layer, per axis
  double strength = 1;         ///< N m; the three torques together are held to it
  friend bool operator==(const LayeredMuscles&, const LayeredMuscles&) = default;
};

/// The whole network. Every node value is finite and within +-kLayeredBound.
class LayeredNetworkPlan : public ControllerPlan {
 public:
  LayeredNet main;
  std::vector<LayeredNet> subnets;     ///< one per joint, in joint order
  std::vector<LayeredMuscles> joints;  ///< one per joint; 3 effectors each
  std::size_t sensor_count = 0;        ///< sensors the inputs were made for

  std::string kind() const override { return "layered"; }
  /// Throws Error(failure) unless effectors == 3 x joints, sensors == sensor_count, and every
  /// index is inside its layer, sensor list or subnet list.
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
  int neuronCount() const override;
};

/// Node values are clamped to +-kLayeredBound; a non-finite result becomes 0.
constexpr double kLayeredBound = 1e6;

/// The running network. step(): every layer of the main net, then of each subnet in order, each
/// node from the values of the layer before it computed this step (the first layer from the
/// sensors just written); then each joint's torques (the node values, N m) are scaled
/// together so their Euclidean length is at most the strength, and each drive is torque /
/// strength. No heap allocation in step().
class LayeredNetwork : public Controller {
 public:
  explicit LayeredNetwork(const LayeredNetworkPlan& plan);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override;
  /// The sensors, then every node in evaluation order.
  std::span<const double> signals() const override { return signals_; }

 private:
  // compiled from the plan: see layered_network.cpp. Every index below is into signals_, which
  // holds the sensors and then every node's value in evaluation order.
  std::vector<double> signals_;
  std::vector<std::int8_t> function_;   // per node: its LayeredFunction
  std::vector<double> value_;           // per node: its value (constant nodes)
  std::vector<std::uint8_t> count_;     // per node: its input count, 0..3
  std::vector<int> source_;             // 3 per node: the signal each input reads
  std::vector<double> weight_;          // 3 per node
  std::vector<std::uint64_t> counter_;  // per node: calculations so far (wave, saw)
  std::vector<int> torque_;             // 3 per joint: the signals of its torques
  std::vector<double> strength_;        // per joint
  int sensor_count_ = 0, node_count_ = 0;
};

}  // namespace cambrian
