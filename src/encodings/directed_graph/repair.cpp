// cambrian: truncation and clamping that make any genome valid under GenomeLimits.
#include "encodings/directed_graph/repair.hpp"

#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/graph.hpp"

#include <algorithm>
#include <cstdint>

namespace cambrian::graph {
namespace {

// an enumeration's raw value taken modulo its number of values
template <typename Enum>
Enum wrapEnum(Enum value, int count) {
  return static_cast<Enum>(static_cast<int>(value) % count);
}

// a list shortened to at most `limit` entries (a negative limit empties it)
template <typename List>
void truncate(List& list, int limit) {
  std::size_t keep = static_cast<std::size_t>(std::max(0, limit));
  if (list.size() > keep)
    list.resize(keep);
}

void fitInput(NeuronInput& input, const GenomeLimits& limits) {
  input.source = wrapEnum(input.source, kSignalSourceCount);
  double w = std::max(0.0, limits.max_weight);
  input.weight = clampToRange(input.weight, -w, w);
}

void fitNeurons(std::vector<NeuronGene>& neurons, int limit, const GenomeLimits& limits) {
  truncate(neurons, limit);
  for (NeuronGene& neuron : neurons) {
    neuron.function = wrapEnum(neuron.function, kNeuronFunctionCount);
    if (!neuronFunctionAllowed(limits, neuron.function)) {
      const std::span<const NeuronFunction> set = neuronSet(limits);
      neuron.function = set[static_cast<std::size_t>(neuron.function) % set.size()];
    }
    neuron.parameter =
        clampToRange(neuron.parameter, -kNeuronParameterBound, kNeuronParameterBound);
    truncate(neuron.inputs, limits.max_inputs);
    for (NeuronInput& input : neuron.inputs)
      fitInput(input, limits);
  }
}

void fitNode(PartGene& node, const GenomeLimits& limits) {
  node.shape = wrapEnum(node.shape, kPartShapeCount);
  for (int k = 0; k < 3; ++k) {
    node.dimensions[k] =
        clampToRange(node.dimensions[k], limits.min_part_size, limits.max_part_size);
    node.joint_limit[k] = clampToRange(node.joint_limit[k], 0, kJointLimitMax);
  }
  node.density = clampToRange(node.density, limits.min_density, limits.max_density);
  node.joint_type = wrapEnum(node.joint_type, kJointTypeCount);
  if (!jointTypeAllowed(limits, node.joint_type)) {
    node.joint_type = allowedJointType(
        limits, static_cast<unsigned>(node.joint_type) % allowedJointTypeCount(limits));
  }
  int max_recursion = std::clamp(limits.max_recursive_limit, 1, 255);
  node.recursive_limit = static_cast<std::uint8_t>(
      std::clamp(static_cast<int>(node.recursive_limit), 1, max_recursion));
  node.friction = clampToRange(node.friction, limits.min_friction, limits.max_friction);
  if (node.restitution != kWorldRestitution) {
    node.restitution =
        clampToRange(node.restitution, limits.min_restitution, limits.max_restitution);
  }
  for (int k = 0; k < 3; ++k)
    node.anchor[k] = clampToRange(node.anchor[k], -kPositionBound, kPositionBound);
  node.segment_shrink = clampToRange(node.segment_shrink, limits.min_shrink, limits.max_shrink);
  for (int k = 0; k < 3; ++k) {
    if (node.joint_damping[k] != kWorldDamping) {
      node.joint_damping[k] =
          clampToRange(node.joint_damping[k], limits.min_joint_damping, limits.max_joint_damping);
    }
  }
  fitNeurons(node.neurons, limits.max_neurons_per_node, limits);
  truncate(node.effectors, kMaxEffectors);
  for (EffectorGene& effector : node.effectors)
    fitInput(effector.input, limits);
}

void fitConnection(ConnectionGene& c, const GenomeLimits& limits) {
  for (int k = 0; k < 3; ++k) {
    c.position[k] = clampToRange(c.position[k], -kPositionBound, kPositionBound);
    c.orientation[k] = clampToRange(c.orientation[k], -kOrientationBound, kOrientationBound);
  }
  c.scale = clampToRange(c.scale, limits.min_scale, limits.max_scale);
  c.reflection &= kReflectionMask;
  JointControllerGene& j = c.controller;
  j.amplitude = clampToRange(j.amplitude, 0, kControllerAmplitudeMax);
  j.frequency = clampToRange(j.frequency, 0, std::max(0.0, limits.max_frequency));
  j.phase = clampToRange(j.phase, -kControllerPhaseBound, kControllerPhaseBound);
  j.offset = clampToRange(j.offset, -kControllerOffsetBound, kControllerOffsetBound);
  if (j.kind != JointControllerKind::sine && j.kind != JointControllerKind::chaotic)
    j.kind = JointControllerKind::sine;
  for (double& v : j.chua_start)
    v = clampToRange(v, -kChuaStartBound, kChuaStartBound);
  j.chua_speed = clampToRange(j.chua_speed, kChuaSpeedMin, kChuaSpeedMax);
}

// a catapult's projectile within its own size range and the density range; position within the
// connection bounds
void fitProjectile(ProjectileGene& projectile, const GenomeLimits& limits) {
  for (int k = 0; k < 3; ++k) {
    projectile.dimensions[k] = clampToRange(projectile.dimensions[k], limits.projectile_min_side,
                                            limits.projectile_max_side);
    projectile.position[k] = clampToRange(projectile.position[k], -kPositionBound, kPositionBound);
  }
  projectile.density = clampToRange(projectile.density, limits.min_density, limits.max_density);
  fitInput(projectile.trigger, limits);
}

}  // namespace

void fitToLimits(Genome& genome, const GenomeLimits& limits) {
  // graph: a root exists, at most max_nodes nodes, connections inside the graph
  if (genome.nodes.empty())
    genome.nodes.emplace_back();
  std::size_t max_nodes = static_cast<std::size_t>(std::max(1, limits.max_nodes));
  std::vector<bool> keep(genome.nodes.size());
  for (std::size_t i = 0; i < keep.size(); ++i)
    keep[i] = i < max_nodes;
  removeNodes(genome, keep);
  truncate(genome.connections, limits.max_connections);

  // every gene within its ranges
  for (PartGene& node : genome.nodes)
    fitNode(node, limits);
  for (ConnectionGene& c : genome.connections)
    fitConnection(c, limits);
  fitNeurons(genome.brain, limits.max_brain_neurons, limits);

  // a projectile in every catapult genome and in no other
  if (!limits.catapult) {
    genome.projectile.reset();
    return;
  }
  if (!genome.projectile) {
    genome.projectile.emplace();
    genome.projectile->dimensions = Vec3{1, 1, 1} * limits.projectile_side;
    genome.projectile->density = limits.projectile_density;
  }
  fitProjectile(*genome.projectile, limits);
}

}  // namespace cambrian::graph
