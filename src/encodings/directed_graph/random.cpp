// cambrian: random genomes (the first generation) and the random genes they are made of.
#include "encodings/directed_graph/random.hpp"

#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/repair.hpp"

#include <algorithm>

namespace cambrian::graph {
namespace {

// uniform in a preferred sub-range [lo, hi] intersected with the allowed range [min, max]
double uniformWithin(Rng& rng, double lo, double hi, double min, double max) {
  double a = clampToRange(lo, min, max), b = clampToRange(hi, min, max);
  if (b < a)
    std::swap(a, b);
  return rng.uniform(a, b);
}

// a random wire into an effector: usually one of the node's neurons, else a sensor or the brain
NeuronInput randomEffectorInput(const PartGene& node, const GenomeLimits& limits, Rng& rng) {
  NeuronInput input = randomNeuronInput(limits, rng);
  double pick = rng.uniform();
  if (!node.neurons.empty() && pick < 0.7) {
    input.source = SignalSource::local_neuron;
    input.index = static_cast<std::uint16_t>(rng.below(node.neurons.size()));
  } else if (pick < 0.85) {
    input.source = SignalSource::local_sensor;
  } else {
    input.source = SignalSource::brain_neuron;
  }
  // effectors want a strong signal
  double max_weight = std::min(2.0, limits.max_weight);
  input.weight = (rng.bernoulli(0.5) ? 1.0 : -1.0) * rng.uniform(0.5 * max_weight, max_weight);
  return input;
}

}  // namespace

NeuronInput randomNeuronInput(const GenomeLimits& limits, Rng& rng) {
  NeuronInput input;
  input.source = static_cast<SignalSource>(rng.below(kSignalSourceCount));
  input.slot = static_cast<std::uint16_t>(rng.below(4));
  input.index = static_cast<std::uint16_t>(rng.below(8));
  double max_weight = std::min(2.0, std::max(0.0, limits.max_weight));
  input.weight = rng.uniform(-max_weight, max_weight);
  return input;
}

NeuronGene randomNeuronGene(const GenomeLimits& limits, Rng& rng) {
  NeuronGene neuron;
  const std::span<const NeuronFunction> set = neuronSet(limits);
  neuron.function = set[rng.below(set.size())];
  // oscillators read their frequency from the parameter: keep it moderate
  neuron.parameter = rng.uniform(-4.0, 4.0);
  int inputs = std::min(neuronArity(neuron.function), std::max(0, limits.max_inputs));
  for (int i = 0; i < inputs; ++i)
    neuron.inputs.push_back(randomNeuronInput(limits, rng));
  return neuron;
}

PartGene randomPartGene(const GenomeLimits& limits, Rng& rng) {
  PartGene node;
  // body: moderate boxes of moderate density
  for (int k = 0; k < 3; ++k) {
    node.dimensions[k] = uniformWithin(rng, 0.08, 0.45, limits.min_part_size, limits.max_part_size);
  }
  node.density = uniformWithin(rng, 500, 1500, limits.min_density, limits.max_density);

  // joint to the parent, any allowed type
  node.joint_type = allowedJointType(limits, rng.below(allowedJointTypeCount(limits)));
  for (int k = 0; k < 3; ++k)
    node.joint_limit[k] = rng.uniform(0.3, 1.5);
  node.recursive_limit = 1;

  // local neurons
  int max_neurons = std::min(3, std::max(0, limits.max_neurons_per_node));
  int neurons = rng.between(0, max_neurons);
  for (int i = 0; i < neurons; ++i)
    node.neurons.push_back(randomNeuronGene(limits, rng));

  // one effector per degree of freedom
  int dof = degreesOfFreedom(node.joint_type);
  for (int d = 0; d < dof; ++d)
    node.effectors.push_back({randomEffectorInput(node, limits, rng)});

  // Minemonics' morphogene, drawn last (without it a node draws what it always drew)
  if (limits.morphogenes) {
    node.shape = static_cast<PartShape>(rng.below(kPartShapeCount));
    node.friction = rng.uniform(limits.min_friction, limits.max_friction);
    node.restitution = rng.uniform(limits.min_restitution, limits.max_restitution);
    for (int k = 0; k < 3; ++k)
      node.anchor[k] = rng.uniform(-kPositionBound, kPositionBound);
    node.segment_shrink = rng.uniform(limits.min_shrink, limits.max_shrink);
    for (int k = 0; k < 3; ++k)
      node.joint_damping[k] = rng.uniform(limits.min_joint_damping, limits.max_joint_damping);
  }
  // Sims' photosensitive parts, drawn after that (without them a node draws what it always drew)
  if (limits.photosensors == Photosensors::chosen)
    node.photosensitive = rng.bernoulli(0.5);
  return node;
}

ConnectionGene randomConnectionGene(std::uint16_t from, std::uint16_t to,
                                    const GenomeLimits& limits, Rng& rng) {
  ConnectionGene c;
  c.from = from;
  c.to = to;

  // placement on the parent and the child's orientation and scale
  for (int k = 0; k < 3; ++k)
    c.position[k] = rng.uniform(-1.0, 1.0);
  for (int k = 0; k < 3; ++k)
    c.orientation[k] = rng.uniform(-0.8, 0.8);
  c.scale = uniformWithin(rng, 0.75, 1.15, limits.min_scale, limits.max_scale);

  // mirror copies now and then: mostly one plane, sometimes two
  double mirror = rng.uniform();
  if (mirror < 0.2) {
    c.reflection = static_cast<std::uint8_t>(1u << rng.below(3));
  } else if (mirror < 0.27) {
    c.reflection = static_cast<std::uint8_t>(kReflectionMask & ~(1u << rng.below(3)));
  }
  c.terminal_only = rng.bernoulli(0.1);

  // Minemonics joint controller now and then, always of the run's kind
  c.controller.kind = limits.joint_controller;
  if (rng.bernoulli(limits.joint_controller_chance)) {
    c.controller = randomJointController(limits, rng);
  }

  // Minemonics' flip and mirror flags, each on half the time (its MorphogeneBranch)
  if (limits.morphogenes) {
    c.flip = rng.bernoulli(0.5);
    c.mirror = rng.bernoulli(0.5);
  }
  return c;
}

JointControllerGene randomJointController(const GenomeLimits& limits, Rng& rng) {
  JointControllerGene controller;
  controller.enabled = true;
  if (limits.joint_controller == JointControllerKind::sine) {
    controller.amplitude = rng.uniform(0.2, 1.0);
    controller.frequency = uniformWithin(rng, 0.3, 2.0, 0, limits.max_frequency);
    controller.phase = rng.uniform(-kControllerPhaseBound, kControllerPhaseBound);
    controller.offset = rng.uniform(-0.3, 0.3);
    return controller;
  }
  // chaotic: z swings within about +-3.6 on the double scroll, so these amplitudes span about
  // +-0.2 to +-1 of drive
  controller.kind = JointControllerKind::chaotic;
  controller.amplitude = rng.uniform(0.05, 0.3);
  controller.offset = rng.uniform(-0.3, 0.3);
  for (double& v : controller.chua_start)
    v = rng.uniform(-kChuaStartBound, kChuaStartBound);
  controller.chua_speed =
      rng.bernoulli(0.5) ? rng.uniform(kChuaSpeedMin, 1.0) : rng.uniform(1.0, kChuaSpeedMax);
  return controller;
}

ProjectileGene randomProjectileGene(const GenomeLimits& limits, Rng& rng) {
  ProjectileGene projectile;
  projectile.dimensions = Vec3{1, 1, 1} * limits.projectile_side;
  projectile.density = limits.projectile_density;
  if (limits.projectile_mutation) {
    for (int k = 0; k < 3; ++k) {
      projectile.dimensions[k] =
          uniformWithin(rng, 0.08, 0.45, limits.projectile_min_side, limits.projectile_max_side);
    }
    if (limits.projectile_density_mutation)
      projectile.density = uniformWithin(rng, 500, 1500, limits.min_density, limits.max_density);
  }
  for (int k = 0; k < 3; ++k)
    projectile.position[k] = rng.uniform(-kPositionBound, kPositionBound);
  projectile.trigger = randomNeuronInput(limits, rng);
  return projectile;
}

Genome randomGenome(const GenomeLimits& limits, std::uint64_t seed, std::uint64_t generation,
                    std::uint64_t individual) {
  Rng rng(seed, RngPurpose::random_genome, generation, individual);
  Genome genome;

  // node count: 1..6, mostly 2..4, and no more nodes than connections can reach
  static constexpr int kNodeWeights[] = {1, 3, 3, 2, 1, 1};  // for 1..6 nodes
  int pick = static_cast<int>(rng.below(11)), nodes = 1;
  while (pick >= kNodeWeights[nodes - 1]) {
    pick -= kNodeWeights[nodes - 1];
    ++nodes;
  }
  nodes = std::clamp(nodes, 1, std::max(1, std::min(limits.max_nodes, limits.max_connections + 1)));
  for (int i = 0; i < nodes; ++i)
    genome.nodes.push_back(randomPartGene(limits, rng));

  // a spanning tree from the root: every node is reached from an earlier one
  for (int i = 1; i < nodes; ++i) {
    auto from = static_cast<std::uint16_t>(rng.below(static_cast<std::uint64_t>(i)));
    genome.connections.push_back(
        randomConnectionGene(from, static_cast<std::uint16_t>(i), limits, rng));
  }

  // extra edges: self-connections (chains) and cross links
  int extra = rng.between(0, 2);
  for (int e = 0; e < extra; ++e) {
    if (static_cast<int>(genome.connections.size()) >= limits.max_connections)
      break;
    auto from = static_cast<std::uint16_t>(rng.below(static_cast<std::uint64_t>(nodes)));
    auto to = rng.bernoulli(0.5)
                  ? from
                  : static_cast<std::uint16_t>(rng.below(static_cast<std::uint64_t>(nodes)));
    ConnectionGene c = randomConnectionGene(from, to, limits, rng);
    // a self-connection needs a recursive limit above 1 to repeat
    if (from == to && limits.max_recursive_limit >= 2) {
      int hi = std::min(3, limits.max_recursive_limit);
      genome.nodes[to].recursive_limit = static_cast<std::uint8_t>(rng.between(2, hi));
      c.reflection = 0;
    }
    genome.connections.push_back(c);
  }

  // global brain neurons
  int brain = rng.between(0, std::min(3, std::max(0, limits.max_brain_neurons)));
  for (int i = 0; i < brain; ++i)
    genome.brain.push_back(randomNeuronGene(limits, rng));

  // a catapult's projectile, drawn last (other genomes draw exactly what they drew before)
  if (limits.catapult)
    genome.projectile = randomProjectileGene(limits, rng);

  // whatever the limits, the result is valid
  fitToLimits(genome, limits);
  return genome;
}

}  // namespace cambrian::graph
