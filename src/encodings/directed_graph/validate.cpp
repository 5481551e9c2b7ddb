// cambrian: structural and range checks of a genome against GenomeLimits.
#include "cambrian/error.hpp"

#include "core/number_text.hpp"
#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <string>

namespace cambrian::graph {
namespace {

// throws unless lo <= value <= hi (NaN fails), naming the gene, field and the bound's origin
void checkRange(const std::string& where, const std::string& field, double value, double lo,
                const std::string& lo_name, double hi, const std::string& hi_name) {
  if (value >= lo && value <= hi)
    return;
  std::string text = where + ": " + field + " = " + formatNumber(value);
  if (value < lo) {
    throw GenomeError(text + " is below " + lo_name + " " + formatNumber(lo));
  }
  if (value > hi) {
    throw GenomeError(text + " is above " + hi_name + " " + formatNumber(hi));
  }
  throw GenomeError(text + " is not a number");
}

// the same check for a range with fixed (not configurable) bounds
void checkFixedRange(const std::string& where, const std::string& field, double value, double lo,
                     double hi) {
  checkRange(where, field, value, lo, "the minimum", hi, "the maximum");
}

// throws unless a count is at most its limit
void checkCount(const std::string& where, const std::string& what, std::size_t count, int limit,
                const std::string& limit_name) {
  if (static_cast<long long>(count) <= static_cast<long long>(limit))
    return;
  throw GenomeError(where + ": " + std::to_string(count) + " " + what + " exceed " + limit_name +
                    " " + std::to_string(limit));
}

// throws unless an enumeration's raw value names one of its `count` values
void checkEnum(const std::string& where, const std::string& field, int value, int count) {
  if (value >= 0 && value < count)
    return;
  throw GenomeError(where + ": " + field + " = " + std::to_string(value) +
                    " is not a valid value (0.." + std::to_string(count - 1) + ")");
}

// one input wire: its source and weight
void checkInput(const std::string& where, const NeuronInput& input, const GenomeLimits& limits) {
  checkEnum(where, "source", static_cast<int>(input.source), kSignalSourceCount);
  checkRange(where, "weight", input.weight, -limits.max_weight, "-genome.max_weight",
             limits.max_weight, "genome.max_weight");
}

// one neuron: function, parameter and inputs
void checkNeuron(const std::string& where, const NeuronGene& neuron, const GenomeLimits& limits) {
  checkEnum(where, "function", static_cast<int>(neuron.function), kNeuronFunctionCount);
  if (!neuronFunctionAllowed(limits, neuron.function)) {
    throw GenomeError(where + ": function " + neuronFunctionName(neuron.function) +
                      " is not in genome.neuron_set " + neuronSetName(limits.neuron_set));
  }
  checkFixedRange(where, "parameter", neuron.parameter, -kNeuronParameterBound,
                  kNeuronParameterBound);
  checkCount(where, "inputs", neuron.inputs.size(), limits.max_inputs, "genome.max_inputs");
  for (std::size_t i = 0; i < neuron.inputs.size(); ++i) {
    checkInput(where + ": input " + std::to_string(i), neuron.inputs[i], limits);
  }
}

// one node: shape, sizes, density, joint, recursion, neurons, effectors
void checkNode(std::size_t index, const PartGene& node, const GenomeLimits& limits) {
  std::string where = "node " + std::to_string(index);
  checkEnum(where, "shape", static_cast<int>(node.shape), kPartShapeCount);
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    checkRange(where, std::string("dimensions.") + kAxes[k], node.dimensions[k],
               limits.min_part_size, "genome.min_part_size", limits.max_part_size,
               "genome.max_part_size");
  }
  checkRange(where, "density", node.density, limits.min_density, "genome.min_density",
             limits.max_density, "genome.max_density");
  checkEnum(where, "joint_type", static_cast<int>(node.joint_type), kJointTypeCount);
  if (!jointTypeAllowed(limits, node.joint_type)) {
    throw GenomeError(where + ": joint " + kJointNames[static_cast<int>(node.joint_type)] +
                      " is not among genome.joint_types");
  }
  for (int k = 0; k < 3; ++k) {
    checkFixedRange(where, std::string("joint_limit.") + kAxes[k], node.joint_limit[k], 0,
                    kJointLimitMax);
  }
  checkRange(where, "recursive_limit", node.recursive_limit, 1, "the minimum",
             limits.max_recursive_limit, "genome.max_recursive_limit");
  checkRange(where, "friction", node.friction, limits.min_friction, "genome.min_friction",
             limits.max_friction, "genome.max_friction");
  if (node.restitution != kWorldRestitution) {
    checkRange(where, "restitution", node.restitution, limits.min_restitution,
               "genome.min_restitution", limits.max_restitution, "genome.max_restitution");
  }
  for (int k = 0; k < 3; ++k) {
    checkFixedRange(where, std::string("anchor.") + kAxes[k], node.anchor[k], -kPositionBound,
                    kPositionBound);
  }
  checkRange(where, "segment_shrink", node.segment_shrink, limits.min_shrink, "genome.min_shrink",
             limits.max_shrink, "genome.max_shrink");
  for (int k = 0; k < 3; ++k) {
    if (node.joint_damping[k] != kWorldDamping) {
      checkRange(where, std::string("joint_damping.") + kAxes[k], node.joint_damping[k],
                 limits.min_joint_damping, "genome.min_joint_damping", limits.max_joint_damping,
                 "genome.max_joint_damping");
    }
  }
  checkCount(where, "neurons", node.neurons.size(), limits.max_neurons_per_node,
             "genome.max_neurons_per_node");
  for (std::size_t i = 0; i < node.neurons.size(); ++i) {
    checkNeuron(where + ": neuron " + std::to_string(i), node.neurons[i], limits);
  }
  checkCount(where, "effectors", node.effectors.size(), kMaxEffectors, "the maximum");
  for (std::size_t i = 0; i < node.effectors.size(); ++i) {
    checkInput(where + ": effector " + std::to_string(i), node.effectors[i].input, limits);
  }
}

// one connection: endpoints, placement, reflection bits and controller
void checkConnection(std::size_t index, const ConnectionGene& connection, std::size_t node_count,
                     const GenomeLimits& limits) {
  std::string where = "connection " + std::to_string(index);
  if (connection.from >= node_count) {
    throw GenomeError(where + ": from = " + std::to_string(connection.from) +
                      " but the genome has " + std::to_string(node_count) + " nodes");
  }
  if (connection.to >= node_count) {
    throw GenomeError(where + ": to = " + std::to_string(connection.to) + " but the genome has " +
                      std::to_string(node_count) + " nodes");
  }
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    checkFixedRange(where, std::string("position.") + kAxes[k], connection.position[k],
                    -kPositionBound, kPositionBound);
  }
  for (int k = 0; k < 3; ++k) {
    checkFixedRange(where, std::string("orientation.") + kAxes[k], connection.orientation[k],
                    -kOrientationBound, kOrientationBound);
  }
  checkRange(where, "scale", connection.scale, limits.min_scale, "genome.min_scale",
             limits.max_scale, "genome.max_scale");
  if ((connection.reflection & ~kReflectionMask) != 0) {
    throw GenomeError(where + ": reflection = " + std::to_string(connection.reflection) +
                      " uses bits other than 0..2 (x, y, z)");
  }
  const JointControllerGene& controller = connection.controller;
  checkFixedRange(where, "controller.amplitude", controller.amplitude, 0, kControllerAmplitudeMax);
  checkRange(where, "controller.frequency", controller.frequency, 0, "the minimum",
             limits.max_frequency, "genome.max_frequency");
  checkFixedRange(where, "controller.phase", controller.phase, -kControllerPhaseBound,
                  kControllerPhaseBound);
  checkFixedRange(where, "controller.offset", controller.offset, -kControllerOffsetBound,
                  kControllerOffsetBound);
  if (controller.kind != JointControllerKind::sine &&
      controller.kind != JointControllerKind::chaotic) {
    throw GenomeError(where +
                      ": controller.kind = " + std::to_string(static_cast<int>(controller.kind)) +
                      " is neither sine (0) nor chaotic (1)");
  }
  for (int k = 0; k < 3; ++k) {
    checkFixedRange(where, std::string("controller.start.") + kAxes[k], controller.chua_start[k],
                    -kChuaStartBound, kChuaStartBound);
  }
  checkFixedRange(where, "controller.speed", controller.chua_speed, kChuaSpeedMin, kChuaSpeedMax);
}

}  // namespace

void validateGenome(const Genome& genome, const GenomeLimits& limits) {
  // graph size
  if (genome.nodes.empty())
    throw GenomeError("genome: has no nodes (node 0 is the root)");
  checkCount("genome", "nodes", genome.nodes.size(), limits.max_nodes, "genome.max_nodes");
  checkCount("genome", "connections", genome.connections.size(), limits.max_connections,
             "genome.max_connections");
  checkCount("genome", "brain neurons", genome.brain.size(), limits.max_brain_neurons,
             "genome.max_brain_neurons");

  // every gene
  for (std::size_t i = 0; i < genome.nodes.size(); ++i)
    checkNode(i, genome.nodes[i], limits);
  for (std::size_t i = 0; i < genome.connections.size(); ++i) {
    checkConnection(i, genome.connections[i], genome.nodes.size(), limits);
  }
  for (std::size_t i = 0; i < genome.brain.size(); ++i) {
    checkNeuron("brain: neuron " + std::to_string(i), genome.brain[i], limits);
  }

  // a projectile in every catapult genome and in no other
  if (limits.catapult != genome.projectile.has_value()) {
    throw GenomeError(limits.catapult
                          ? "genome: has no projectile, and genome.catapult = true needs one"
                          : "genome: has a projectile (a catapult's), and genome.catapult = false");
  }
  if (genome.projectile) {
    const ProjectileGene& p = *genome.projectile;
    static constexpr const char* kAxes[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      checkRange("projectile", std::string("size.") + kAxes[k], p.dimensions[k],
                 limits.projectile_min_side, "genome.projectile_min_side",
                 limits.projectile_max_side, "genome.projectile_max_side");
      checkFixedRange("projectile", std::string("position.") + kAxes[k], p.position[k],
                      -kPositionBound, kPositionBound);
    }
    checkRange("projectile", "density", p.density, limits.min_density, "genome.min_density",
               limits.max_density, "genome.max_density");
    checkInput("projectile: trigger", p.trigger, limits);
  }
}

bool hasMorphogeneFields(const Genome& genome) {
  const PartGene sims_part;
  for (const PartGene& node : genome.nodes) {
    if (node.shape != sims_part.shape || !sameBits(node.friction, sims_part.friction) ||
        !sameBits(node.restitution, sims_part.restitution) ||
        !sameBits(node.anchor, sims_part.anchor) ||
        !sameBits(node.segment_shrink, sims_part.segment_shrink) ||
        !sameBits(node.joint_damping, sims_part.joint_damping))
      return true;
  }
  for (const ConnectionGene& c : genome.connections) {
    if (c.flip || c.mirror)
      return true;
  }
  return false;
}

}  // namespace cambrian::graph
