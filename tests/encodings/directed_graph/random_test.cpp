#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/chaotic_limits.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

namespace cambrian::graph {
namespace {

// 10,000 random genomes are all valid under the default limits
TEST(RandomGenome, AlwaysValid) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 10000; ++i) {
    Genome genome = randomGenome(limits, 7, i / 100, i % 100);
    ASSERT_NO_THROW(validateGenome(genome, limits)) << "individual " << i;
  }
}

// tight limits are respected too
TEST(RandomGenome, ValidUnderTightLimits) {
  GenomeLimits limits;
  limits.max_nodes = 2;
  limits.max_connections = 1;
  limits.max_neurons_per_node = 1;
  limits.max_brain_neurons = 0;
  limits.max_inputs = 1;
  limits.max_recursive_limit = 1;
  limits.min_part_size = 0.2;
  limits.max_part_size = 0.3;
  limits.max_weight = 0.5;
  limits.max_frequency = 0.5;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    Genome genome = randomGenome(limits, 3, 0, i);
    ASSERT_NO_THROW(validateGenome(genome, limits)) << "individual " << i;
  }
}

// the same (seed, generation, individual) gives the same genome
TEST(RandomGenome, Deterministic) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 200; ++i) {
    EXPECT_EQ(randomGenome(limits, 11, 2, i), randomGenome(limits, 11, 2, i));
  }
}

// different individuals, generations and seeds give different genomes
TEST(RandomGenome, DiffersBetweenIndividuals) {
  GenomeLimits limits;
  Genome base = randomGenome(limits, 11, 2, 5);
  EXPECT_NE(base, randomGenome(limits, 11, 2, 6));
  EXPECT_NE(base, randomGenome(limits, 11, 3, 5));
  EXPECT_NE(base, randomGenome(limits, 12, 2, 5));
  std::set<std::vector<std::uint8_t>> distinct;
  for (std::uint64_t i = 0; i < 500; ++i)
    distinct.insert(serializeGenome(randomGenome(limits, 1, 0, i)));
  EXPECT_EQ(distinct.size(), 500u);
}

// the population is diverse: node counts, joints, functions, reflection, recursion, controllers
TEST(RandomGenome, Diverse) {
  GenomeLimits limits;
  std::set<std::size_t> node_counts;
  std::array<int, 4> joints{};
  std::set<int> functions, sources;
  int reflections = 0, self_connections = 0, controllers = 0, terminal = 0, recursive = 0;
  int with_brain = 0, effectors_wired = 0, effectors = 0, unreachable = 0;
  for (std::uint64_t i = 0; i < 3000; ++i) {
    Genome genome = randomGenome(limits, 5, 0, i);
    node_counts.insert(genome.nodes.size());
    std::vector<bool> reached = reachableNodes(genome);
    unreachable += static_cast<int>(std::count(reached.begin(), reached.end(), false));
    for (const PartGene& node : genome.nodes) {
      ++joints[static_cast<int>(node.joint_type)];
      if (node.recursive_limit > 1)
        ++recursive;
      for (const NeuronGene& neuron : node.neurons) {
        functions.insert(static_cast<int>(neuron.function));
        for (const NeuronInput& input : neuron.inputs)
          sources.insert(static_cast<int>(input.source));
      }
      // one effector per degree of freedom
      EXPECT_EQ(static_cast<int>(node.effectors.size()), degreesOfFreedom(node.joint_type));
      for (const EffectorGene& effector : node.effectors) {
        ++effectors;
        if (effector.input.source == SignalSource::local_neuron ||
            effector.input.source == SignalSource::local_sensor ||
            effector.input.source == SignalSource::brain_neuron) {
          ++effectors_wired;
        }
      }
    }
    for (const ConnectionGene& c : genome.connections) {
      if (c.reflection != 0)
        ++reflections;
      if (c.from == c.to)
        ++self_connections;
      if (c.controller.enabled)
        ++controllers;
      if (c.terminal_only)
        ++terminal;
    }
    if (!genome.brain.empty())
      ++with_brain;
  }
  EXPECT_EQ(*node_counts.begin(), 1u);
  EXPECT_GE(*node_counts.rbegin(), 6u);
  for (int count : joints)
    EXPECT_GT(count, 0);
  EXPECT_EQ(functions.size(), neuronSet(GenomeLimits{}).size());  // the whole sims set
  EXPECT_EQ(sources.size(), 7u);
  EXPECT_GT(reflections, 100);
  EXPECT_GT(self_connections, 100);
  EXPECT_GT(recursive, 100);
  EXPECT_GT(controllers, 100);
  EXPECT_GT(terminal, 10);
  EXPECT_GT(with_brain, 1000);
  EXPECT_EQ(effectors_wired, effectors);
  EXPECT_EQ(unreachable, 0);
}

// every node of a random genome is reachable from the root
TEST(RandomGenome, ConnectionsReachFromRoot) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 500; ++i) {
    Genome genome = randomGenome(limits, 9, 1, i);
    std::vector<bool> reached = reachableNodes(genome);
    EXPECT_TRUE(std::all_of(reached.begin(), reached.end(), [](bool b) { return b; }));
  }
}

// a chaotic run's random connections all carry chaotic controllers, on at the chance asked,
// started in Minemonics' box at speeds on both sides of 1; every genome is valid
TEST(RandomGenome, ChaoticControllersOnEveryJoint) {
  int connections = 0, on = 0, slow = 0, fast = 0;
  for (double chance : {1.0, 0.5}) {
    const GenomeLimits limits = test::chaoticLimits(chance);
    for (std::uint64_t i = 0; i < 300; ++i) {
      const Genome g = randomGenome(limits, 61, 0, i);
      ASSERT_NO_THROW(validateGenome(g, limits));
      for (const ConnectionGene& c : g.connections) {
        EXPECT_EQ(c.controller.kind, JointControllerKind::chaotic);
        if (chance == 1.0) {
          EXPECT_TRUE(c.controller.enabled);
          for (double v : c.controller.chua_start)
            EXPECT_LE(std::abs(v), 0.5);
          slow += c.controller.chua_speed < 1;
          fast += c.controller.chua_speed > 1;
        } else {
          ++connections;
          on += c.controller.enabled;
        }
      }
    }
  }
  EXPECT_NEAR(static_cast<double>(on) / connections, 0.5, 0.05);
  EXPECT_NEAR(static_cast<double>(slow) / (slow + fast), 0.5, 0.05);
}

// Sims' photosensitive parts: drawn with probability 1/2, only under genome.photosensors =
// chosen (elsewhere a node draws what it always drew)
TEST(RandomGenome, PhotosensitivePartsOnlyWhereTheGenomeChooses) {
  GenomeLimits chosen;
  chosen.photosensors = Photosensors::chosen;
  int nodes = 0, photosensitive = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    const Genome g = randomGenome(chosen, 62, 0, i);
    ASSERT_NO_THROW(validateGenome(g, chosen));
    for (const PartGene& node : g.nodes) {
      ++nodes;
      photosensitive += node.photosensitive;
    }
    const Genome plain = randomGenome(GenomeLimits{}, 62, 0, i);
    for (const PartGene& node : plain.nodes)
      ASSERT_FALSE(node.photosensitive);
  }
  EXPECT_NEAR(static_cast<double>(photosensitive) / nodes, 0.5, 0.05);
}

}  // namespace
}  // namespace cambrian::graph
