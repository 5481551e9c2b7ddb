// cambrian: Sims' genetic operators on the directed-graph genome: mutation, crossover, grafting.
#include "encodings/directed_graph/operators.hpp"

#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/graph.hpp"
#include "encodings/directed_graph/random.hpp"
#include "encodings/directed_graph/repair.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace cambrian::graph {
namespace {

// per-parameter perturbation, scaled to each parameter's range (Sims 1994)
class Perturber {
 public:
  Perturber(const GenomeLimits& limits, const MutationSettings& settings, Rng& rng)
      : limits_(limits), settings_(settings), rng_(rng) {}

  // with probability parameter_rate: v += normal * perturbation * (hi - lo), clamped
  void number(double& v, double lo, double hi) {
    if (!rng_.bernoulli(settings_.parameter_rate))
      return;
    v = clampToRange(v + rng_.normal() * settings_.perturbation * (hi - lo), lo, hi);
  }
  void vec3(Vec3& v, double lo, double hi) {
    for (int k = 0; k < 3; ++k)
      number(v[k], lo, hi);
  }
  // with probability parameter_rate: a fresh value in [0, count)
  template <typename Enum>
  void redraw(Enum& value, int count) {
    if (rng_.bernoulli(settings_.parameter_rate)) {
      value = static_cast<Enum>(rng_.below(static_cast<std::uint64_t>(count)));
    }
  }
  void flip(bool& value) {
    if (rng_.bernoulli(settings_.parameter_rate))
      value = !value;
  }

  void input(NeuronInput& in) {
    redraw(in.source, kSignalSourceCount);
    if (rng_.bernoulli(settings_.parameter_rate))
      in.slot = static_cast<std::uint16_t>(rng_.below(4));
    if (rng_.bernoulli(settings_.parameter_rate))
      in.index = static_cast<std::uint16_t>(rng_.below(8));
    number(in.weight, -limits_.max_weight, limits_.max_weight);
  }

  void neuron(NeuronGene& n) {
    // a new function may read more inputs: give it random ones
    if (rng_.bernoulli(settings_.parameter_rate)) {
      const std::span<const NeuronFunction> set = neuronSet(limits_);
      n.function = set[rng_.below(set.size())];
      int wanted = std::min(neuronArity(n.function), std::max(0, limits_.max_inputs));
      while (static_cast<int>(n.inputs.size()) < wanted) {
        n.inputs.push_back(randomNeuronInput(limits_, rng_));
      }
    }
    number(n.parameter, -kNeuronParameterBound, kNeuronParameterBound);
    for (NeuronInput& in : n.inputs)
      input(in);
  }

  void node(PartGene& p) {
    // body
    vec3(p.dimensions, limits_.min_part_size, limits_.max_part_size);
    number(p.density, limits_.min_density, limits_.max_density);

    // joint, keeping one effector per degree of freedom
    if (rng_.bernoulli(settings_.parameter_rate)) {
      p.joint_type = allowedJointType(limits_, rng_.below(allowedJointTypeCount(limits_)));
      auto dof = static_cast<std::size_t>(degreesOfFreedom(p.joint_type));
      if (p.effectors.size() > dof)
        p.effectors.resize(dof);
      while (p.effectors.size() < dof)
        p.effectors.push_back({randomNeuronInput(limits_, rng_)});
    }
    vec3(p.joint_limit, 0, kJointLimitMax);
    if (rng_.bernoulli(settings_.parameter_rate)) {
      int step = rng_.bernoulli(0.5) ? 1 : -1;
      int limit =
          std::clamp(p.recursive_limit + step, 1, std::clamp(limits_.max_recursive_limit, 1, 255));
      p.recursive_limit = static_cast<std::uint8_t>(limit);
    }

    // controller genes of the part
    for (NeuronGene& n : p.neurons)
      neuron(n);
    for (EffectorGene& e : p.effectors)
      input(e.input);

    // Minemonics' morphogene, then Sims' photosensitive parts, last (without them a node draws
    // what it always drew)
    if (limits_.morphogenes) {
      redraw(p.shape, kPartShapeCount);
      number(p.friction, limits_.min_friction, limits_.max_friction);
      if (p.restitution != kWorldRestitution)
        number(p.restitution, limits_.min_restitution, limits_.max_restitution);
      vec3(p.anchor, -kPositionBound, kPositionBound);
      number(p.segment_shrink, limits_.min_shrink, limits_.max_shrink);
      for (int k = 0; k < 3; ++k) {
        if (p.joint_damping[k] != kWorldDamping)
          number(p.joint_damping[k], limits_.min_joint_damping, limits_.max_joint_damping);
      }
    }
    if (limits_.photosensors == Photosensors::chosen)
      flip(p.photosensitive);
  }

  void connection(ConnectionGene& c) {
    // placement
    vec3(c.position, -kPositionBound, kPositionBound);
    vec3(c.orientation, -kOrientationBound, kOrientationBound);
    number(c.scale, limits_.min_scale, limits_.max_scale);
    if (rng_.bernoulli(settings_.parameter_rate)) {
      c.reflection = static_cast<std::uint8_t>(c.reflection ^ (1u << rng_.below(3)));
    }
    flip(c.terminal_only);
    controller(c.controller);

    // Minemonics' flip and mirror flags, last
    if (limits_.morphogenes) {
      flip(c.flip);
      flip(c.mirror);
    }
  }

  // joint controller: the fields its kind reads (the kind itself is the run's)
  void controller(JointControllerGene& j) {
    flip(j.enabled);
    number(j.amplitude, 0, kControllerAmplitudeMax);
    if (j.kind == JointControllerKind::sine) {
      number(j.frequency, 0, limits_.max_frequency);
      number(j.phase, -kControllerPhaseBound, kControllerPhaseBound);
      number(j.offset, -kControllerOffsetBound, kControllerOffsetBound);
      return;
    }
    number(j.offset, -kControllerOffsetBound, kControllerOffsetBound);
    for (double& v : j.chua_start)
      number(v, -kChuaStartBound, kChuaStartBound);
    number(j.chua_speed, kChuaSpeedMin, kChuaSpeedMax);
  }

  // a catapult's projectile: where the arm holds it and the release wire always; its size and
  // shape only with genome.projectile_mutation, its density only with
  // projectile_density_mutation too (the mechanism itself is not in the genome)
  void projectile(ProjectileGene& p) {
    vec3(p.position, -kPositionBound, kPositionBound);
    input(p.trigger);
    if (!limits_.projectile_mutation)
      return;
    vec3(p.dimensions, limits_.projectile_min_side, limits_.projectile_max_side);
    if (limits_.projectile_density_mutation)
      number(p.density, limits_.min_density, limits_.max_density);
  }

 private:
  const GenomeLimits& limits_;
  const MutationSettings& settings_;
  Rng& rng_;
};

// a uniformly chosen node reachable from the root
std::uint16_t randomReachableNode(const Genome& genome, Rng& rng) {
  std::vector<bool> reached = reachableNodes(genome);
  std::vector<std::uint16_t> candidates;
  for (std::size_t i = 0; i < reached.size(); ++i) {
    if (reached[i])
      candidates.push_back(static_cast<std::uint16_t>(i));
  }
  return candidates[rng.below(candidates.size())];
}

// with add_neuron_rate a random neuron is appended; with remove_neuron_rate one is erased
void mutateNeuronList(std::vector<NeuronGene>& neurons, int limit, const GenomeLimits& limits,
                      const MutationSettings& settings, Rng& rng) {
  if (rng.bernoulli(settings.add_neuron_rate) && static_cast<int>(neurons.size()) < limit) {
    neurons.push_back(randomNeuronGene(limits, rng));
  }
  if (rng.bernoulli(settings.remove_neuron_rate) && !neurons.empty()) {
    neurons.erase(neurons.begin() + static_cast<std::ptrdiff_t>(rng.below(neurons.size())));
  }
}

}  // namespace

Genome mutate(const Genome& parent, const GenomeLimits& limits, const MutationSettings& settings,
              Rng& rng) {
  Genome g = parent;
  if (g.nodes.empty())
    g.nodes.emplace_back();

  // parameters of every gene
  Perturber perturb(limits, settings, rng);
  for (PartGene& node : g.nodes)
    perturb.node(node);
  for (ConnectionGene& c : g.connections)
    perturb.connection(c);
  for (NeuronGene& n : g.brain)
    perturb.neuron(n);
  if (g.projectile)
    perturb.projectile(*g.projectile);

  // add a node, with a connection to it from a reachable node
  int node_count = static_cast<int>(g.nodes.size());
  int connection_count = static_cast<int>(g.connections.size());
  if (rng.bernoulli(settings.add_node_rate) && node_count < limits.max_nodes &&
      connection_count < limits.max_connections) {
    std::uint16_t from = randomReachableNode(g, rng);
    g.nodes.push_back(randomPartGene(limits, rng));
    g.connections.push_back(
        randomConnectionGene(from, static_cast<std::uint16_t>(node_count), limits, rng));
  }

  // remove a node other than the root, with the connections that touch it
  if (rng.bernoulli(settings.remove_node_rate) && g.nodes.size() > 1) {
    std::size_t victim = 1 + rng.below(g.nodes.size() - 1);
    std::vector<bool> keep(g.nodes.size(), true);
    keep[victim] = false;
    removeNodes(g, keep);
  }

  // add a connection between any two nodes (self-connections included)
  if (rng.bernoulli(settings.add_connection_rate) &&
      static_cast<int>(g.connections.size()) < limits.max_connections) {
    auto from = static_cast<std::uint16_t>(rng.below(g.nodes.size()));
    auto to = static_cast<std::uint16_t>(rng.below(g.nodes.size()));
    g.connections.push_back(randomConnectionGene(from, to, limits, rng));
  }

  // remove a connection
  if (rng.bernoulli(settings.remove_connection_rate) && !g.connections.empty()) {
    g.connections.erase(g.connections.begin() +
                        static_cast<std::ptrdiff_t>(rng.below(g.connections.size())));
  }

  // re-point connections to other nodes
  for (ConnectionGene& c : g.connections) {
    if (rng.bernoulli(settings.repoint_rate)) {
      c.to = static_cast<std::uint16_t>(rng.below(g.nodes.size()));
    }
  }

  // add and remove neurons, per node and in the brain
  for (PartGene& node : g.nodes) {
    mutateNeuronList(node.neurons, limits.max_neurons_per_node, limits, settings, rng);
  }
  mutateNeuronList(g.brain, limits.max_brain_neurons, limits, settings, rng);

  // within limits, then unconnected nodes kept as hidden genes (Chaumont) or collected
  fitToLimits(g, limits);
  if (!settings.keep_unconnected)
    g = removeUnreachableNodes(std::move(g));
  return g;
}

Genome crossover(const Genome& a, const Genome& b, const GenomeLimits& limits, Rng& rng) {
  // one or two crossover points along the aligned node lists
  std::size_t longest = std::max<std::size_t>({a.nodes.size(), b.nodes.size(), 1});
  std::vector<std::size_t> points(rng.bernoulli(0.5) ? 1 : 2);
  for (std::size_t& point : points)
    point = 1 + rng.below(longest);
  std::sort(points.begin(), points.end());

  // copy nodes from a, switching parent at each point, until the current parent runs out
  Genome child;
  std::vector<const Genome*> origin;
  const Genome* source = &a;
  std::size_t next_point = 0;
  for (std::size_t i = 0;; ++i) {
    while (next_point < points.size() && points[next_point] <= i) {
      source = source == &a ? &b : &a;
      ++next_point;
    }
    if (i >= source->nodes.size())
      break;
    child.nodes.push_back(source->nodes[i]);
    origin.push_back(source);
  }

  // connections travel with their `from` node, `to` clamped into the child
  if (!child.nodes.empty()) {
    auto last = static_cast<std::uint16_t>(child.nodes.size() - 1);
    for (std::size_t i = 0; i < child.nodes.size(); ++i) {
      for (ConnectionGene c : origin[i]->connections) {
        if (c.from != i)
          continue;
        c.to = std::min(c.to, last);
        child.connections.push_back(c);
      }
    }
  }

  // the brain comes whole from one parent; the arm (node 0) and its projectile from the first
  // (Chaumont et al.'s Figure 6)
  child.brain = rng.bernoulli(0.5) ? a.brain : b.brain;
  child.projectile = a.projectile;
  fitToLimits(child, limits);
  return child;
}

Genome graft(const Genome& a, const Genome& b, const GenomeLimits& limits, Rng& rng,
             GraftInto into) {
  Genome g = a;
  if (g.nodes.empty())
    g.nodes.emplace_back();
  std::size_t offset = g.nodes.size();
  std::size_t a_connections = g.connections.size();

  // append b's graph, indices shifted (never past the 16-bit index range)
  std::size_t appended =
      std::min(b.nodes.size(), std::size_t{65535} - std::min<std::size_t>(offset, 65535));
  for (std::size_t i = 0; i < appended; ++i)
    g.nodes.push_back(b.nodes[i]);
  for (ConnectionGene c : b.connections) {
    if (c.from >= appended || c.to >= appended)
      continue;
    c.from = static_cast<std::uint16_t>(c.from + offset);
    c.to = static_cast<std::uint16_t>(c.to + offset);
    g.connections.push_back(c);
  }

  // one of a's connections now leads into b's root or a random node of b (or a new one does);
  // the root draws nothing, so grafts into the root are what they always were
  if (appended > 0) {
    auto b_root = static_cast<std::uint16_t>(
        offset + (into == GraftInto::any_node ? rng.below(appended) : 0));
    if (a_connections > 0) {
      g.connections[rng.below(a_connections)].to = b_root;
    } else {
      auto from = static_cast<std::uint16_t>(rng.below(offset));
      g.connections.insert(g.connections.begin(), randomConnectionGene(from, b_root, limits, rng));
    }
  }

  // b's nodes that cannot be reached are dropped; a's are kept
  std::vector<bool> keep = reachableNodes(g);
  for (std::size_t i = 0; i < offset; ++i)
    keep[i] = true;
  removeNodes(g, keep);
  fitToLimits(g, limits);
  return g;
}

}  // namespace cambrian::graph
