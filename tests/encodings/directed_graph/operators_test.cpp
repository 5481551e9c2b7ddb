#include "encodings/directed_graph/operators.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/rng.hpp"

#include "encodings/directed_graph/catapult_limits.hpp"
#include "encodings/directed_graph/chaotic_limits.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace cambrian::graph {
namespace {

// settings with every rate high, so that structure changes often
MutationSettings aggressive(bool keep_unconnected) {
  MutationSettings s;
  s.parameter_rate = 0.5;
  s.perturbation = 0.5;
  s.add_node_rate = s.remove_node_rate = 0.5;
  s.add_connection_rate = s.remove_connection_rate = 0.5;
  s.repoint_rate = 0.3;
  s.add_neuron_rate = s.remove_neuron_rate = 0.5;
  s.keep_unconnected = keep_unconnected;
  return s;
}

// repeated mutation (a lineage) stays valid, with both unconnected-node policies
TEST(Mutate, AlwaysValid) {
  GenomeLimits limits;
  for (bool keep : {true, false}) {
    MutationSettings gentle;
    gentle.keep_unconnected = keep;
    for (std::uint64_t lineage = 0; lineage < 100; ++lineage) {
      Genome g = randomGenome(limits, 71, 0, lineage);
      for (std::uint64_t generation = 0; generation < 30; ++generation) {
        Rng rng(71, RngPurpose::variation, generation, lineage);
        g = mutate(g, limits, generation % 2 ? aggressive(keep) : gentle, rng);
        ASSERT_NO_THROW(validateGenome(g, limits))
            << "lineage " << lineage << " generation " << generation;
        if (!keep) {
          std::vector<bool> reached = reachableNodes(g);
          EXPECT_TRUE(std::all_of(reached.begin(), reached.end(), [](bool b) { return b; }));
        }
      }
    }
  }
}

// the same Rng key and counter give the same child; another counter usually another child
TEST(Mutate, Deterministic) {
  GenomeLimits limits;
  int differ = 0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Genome parent = randomGenome(limits, 72, 0, i);
    Rng a(5, RngPurpose::variation, 1, i), b(5, RngPurpose::variation, 1, i);
    EXPECT_EQ(mutate(parent, limits, aggressive(true), a),
              mutate(parent, limits, aggressive(true), b));
    Rng c(5, RngPurpose::variation, 2, i);
    Rng d(5, RngPurpose::variation, 1, i);
    if (mutate(parent, limits, aggressive(true), c) != mutate(parent, limits, aggressive(true), d))
      ++differ;
  }
  EXPECT_GT(differ, 190);
}

// with every rate 0 the child is the parent
TEST(Mutate, RateZeroReturnsParent) {
  GenomeLimits limits;
  MutationSettings none;
  none.parameter_rate = none.add_node_rate = none.remove_node_rate = 0;
  none.add_connection_rate = none.remove_connection_rate = none.repoint_rate = 0;
  none.add_neuron_rate = none.remove_neuron_rate = 0;
  for (bool keep : {true, false}) {
    none.keep_unconnected = keep;
    for (std::uint64_t i = 0; i < 300; ++i) {
      Genome parent = randomGenome(limits, 73, 0, i);
      Rng rng(6, RngPurpose::variation, 0, i);
      EXPECT_EQ(mutate(parent, limits, none, rng), parent);
    }
  }
}

// default settings change something in most children, but not everything
TEST(Mutate, DefaultSettingsChangeSomething) {
  GenomeLimits limits;
  int changed = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    Genome parent = randomGenome(limits, 74, 0, i);
    Rng rng(7, RngPurpose::variation, 0, i);
    Genome child = mutate(parent, limits, MutationSettings{}, rng);
    if (child != parent)
      ++changed;
    EXPECT_EQ(
        child.nodes[0].neurons.size() <= static_cast<std::size_t>(limits.max_neurons_per_node),
        true);
  }
  EXPECT_GT(changed, 250);
}

// structural mutation adds and removes nodes and connections over many trials
TEST(Mutate, ChangesStructure) {
  GenomeLimits limits;
  bool grew = false, shrank = false, rewired = false;
  for (std::uint64_t i = 0; i < 300; ++i) {
    Genome parent = randomGenome(limits, 75, 0, i);
    Rng rng(8, RngPurpose::variation, 0, i);
    Genome child = mutate(parent, limits, aggressive(true), rng);
    grew |= child.nodes.size() > parent.nodes.size();
    shrank |= child.nodes.size() < parent.nodes.size();
    rewired |= child.connections.size() != parent.connections.size();
  }
  EXPECT_TRUE(grew);
  EXPECT_TRUE(shrank);
  EXPECT_TRUE(rewired);
}

// crossover: valid, deterministic, root from a, nodes from both parents
TEST(Crossover, ValidDeterministicAndMixed) {
  GenomeLimits limits;
  int mixed = 0;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    Genome a = randomGenome(limits, 76, 0, i), b = randomGenome(limits, 76, 1, i);
    Rng r1(9, RngPurpose::variation, 0, i), r2(9, RngPurpose::variation, 0, i);
    Genome child = crossover(a, b, limits, r1);
    ASSERT_NO_THROW(validateGenome(child, limits)) << "pair " << i;
    EXPECT_EQ(child, crossover(a, b, limits, r2));
    EXPECT_EQ(child.nodes[0], a.nodes[0]);
    bool from_b = false;
    for (std::size_t n = 1; n < child.nodes.size(); ++n) {
      from_b |= n < b.nodes.size() && child.nodes[n] == b.nodes[n] &&
                !(n < a.nodes.size() && a.nodes[n] == b.nodes[n]);
    }
    if (from_b)
      ++mixed;
  }
  EXPECT_GT(mixed, 300);
}

// connections travel with their `from` node
TEST(Crossover, ConnectionsTravelWithFromNode) {
  Genome a, b;
  a.nodes.resize(3);
  b.nodes.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    a.nodes[i].density = 1000 + static_cast<double>(i);
    b.nodes[i].density = 2000 + static_cast<double>(i);
  }
  auto edge = [](int from, int to, double scale) {
    ConnectionGene c;
    c.from = static_cast<std::uint16_t>(from);
    c.to = static_cast<std::uint16_t>(to);
    c.scale = scale;
    return c;
  };
  a.connections = {edge(0, 1, 0.6), edge(1, 2, 0.7), edge(2, 2, 0.8)};
  b.connections = {edge(0, 2, 1.6), edge(1, 2, 1.7), edge(2, 0, 1.8)};
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Rng rng(10, RngPurpose::variation, 0, i);
    Genome child = crossover(a, b, limits, rng);
    for (const ConnectionGene& c : child.connections) {
      const Genome& origin = child.nodes[c.from].density < 2000 ? a : b;
      bool found = std::any_of(
          origin.connections.begin(), origin.connections.end(),
          [&](const ConnectionGene& o) { return o.from == c.from && o.scale == c.scale; });
      EXPECT_TRUE(found);
    }
  }
}

// grafting: valid, deterministic, keeps a's root and reaches b's root
TEST(Graft, ValidDeterministicAndJoined) {
  GenomeLimits limits;
  int joined = 0;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    Genome a = randomGenome(limits, 77, 0, i), b = randomGenome(limits, 77, 1, i);
    Rng r1(11, RngPurpose::variation, 0, i), r2(11, RngPurpose::variation, 0, i);
    Genome child = graft(a, b, limits, r1);
    ASSERT_NO_THROW(validateGenome(child, limits)) << "pair " << i;
    EXPECT_EQ(child, graft(a, b, limits, r2));
    EXPECT_EQ(child.nodes[0], a.nodes[0]);
    // b's root follows a's nodes when it fits
    if (a.nodes.size() + 1 <= static_cast<std::size_t>(limits.max_nodes)) {
      ASSERT_GT(child.nodes.size(), a.nodes.size());
      EXPECT_EQ(child.nodes[a.nodes.size()], b.nodes[0]);
      bool into_b = std::any_of(child.connections.begin(), child.connections.end(),
                                [&](const ConnectionGene& c) {
                                  return c.to == a.nodes.size() && c.from < a.nodes.size();
                                });
      EXPECT_TRUE(into_b);
      ++joined;
    }
  }
  EXPECT_GT(joined, 1900);
}

// grafting onto a genome without connections adds one to b's root
TEST(Graft, AddsConnectionWhenNone) {
  Genome a, b;
  a.nodes.resize(1);
  b.nodes.resize(2);
  ConnectionGene c;
  c.from = 0;
  c.to = 1;
  b.connections.push_back(c);
  GenomeLimits limits;
  Rng rng(12, RngPurpose::variation);
  Genome child = graft(a, b, limits, rng);
  EXPECT_EQ(child.nodes.size(), 3u);
  ASSERT_EQ(child.connections.size(), 2u);
  EXPECT_EQ(child.connections[0].from, 0);
  EXPECT_EQ(child.connections[0].to, 1);
  EXPECT_EQ(child.connections[1].from, 1);
  EXPECT_EQ(child.connections[1].to, 2);
}

// operators truncate to tight limits
TEST(Operators, RespectTightLimits) {
  GenomeLimits wide, tight;
  tight.max_nodes = 3;
  tight.max_connections = 3;
  tight.max_neurons_per_node = 1;
  tight.max_brain_neurons = 1;
  tight.max_inputs = 1;
  for (std::uint64_t i = 0; i < 500; ++i) {
    Genome a = randomGenome(wide, 78, 0, i), b = randomGenome(wide, 78, 1, i);
    Rng rng(13, RngPurpose::variation, 0, i);
    ASSERT_NO_THROW(validateGenome(mutate(a, tight, aggressive(true), rng), tight));
    ASSERT_NO_THROW(validateGenome(crossover(a, b, tight, rng), tight));
    ASSERT_NO_THROW(validateGenome(graft(a, b, tight, rng), tight));
  }
}

using test::catapultLimits;

// operators keep one arm and one projectile: a child's projectile is its first parent's (and its
// arm is that parent's node 0); mutation moves the grip and the release wire always, the block
// only with projectile_mutation
TEST(Operators, KeepOneArmAndOneProjectile) {
  int moved = 0, resized_fixed = 0, resized_free = 0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const Genome a = randomGenome(catapultLimits(), 11, 0, i);
    const Genome b = randomGenome(catapultLimits(), 12, 0, i);
    Rng rng(13, RngPurpose::variation, 0, i);
    const Genome child = crossover(a, b, catapultLimits(), rng);
    EXPECT_EQ(child.projectile, a.projectile);
    EXPECT_EQ(child.nodes[0], a.nodes[0]);
    const Genome grafted = graft(a, b, catapultLimits(), rng);
    EXPECT_EQ(grafted.projectile, a.projectile);
    EXPECT_EQ(grafted.nodes[0], a.nodes[0]);
    MutationSettings settings;
    settings.parameter_rate = 0.5;
    const Genome fixed = mutate(a, catapultLimits(false), settings, rng);
    ASSERT_TRUE(fixed.projectile.has_value());
    EXPECT_NO_THROW(validateGenome(fixed, catapultLimits(false)));
    moved += fixed.projectile->position != a.projectile->position ? 1 : 0;
    resized_fixed += fixed.projectile->dimensions != a.projectile->dimensions ? 1 : 0;
    const Genome free = mutate(a, catapultLimits(true), settings, rng);
    resized_free += free.projectile->dimensions != a.projectile->dimensions ? 1 : 0;
  }
  EXPECT_GT(moved, 150);
  EXPECT_EQ(resized_fixed, 0);
  EXPECT_GT(resized_free, 150);
}

// a mutable projectile keeps to its own size range, whatever the parts' range, and keeps its
// density unless projectile_density_mutation lets that change too
TEST(Operators, AProjectileMutatesWithinItsOwnRange) {
  GenomeLimits limits = catapultLimits(true);
  limits.projectile_min_side = 0.1;
  limits.projectile_max_side = 0.3;
  MutationSettings settings;
  settings.parameter_rate = 1;
  settings.perturbation = 10;
  int reached_max = 0, reached_min = 0, density_changed = 0, density_free = 0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Genome g = randomGenome(limits, 21, 0, i);
    const double density = g.projectile->density;
    Rng rng(22, RngPurpose::variation, 0, i);
    for (int step = 0; step < 5; ++step) {
      g = mutate(g, limits, settings, rng);
      ASSERT_NO_THROW(validateGenome(g, limits));
    }
    for (int k = 0; k < 3; ++k) {
      reached_max += g.projectile->dimensions[k] > 0.29 ? 1 : 0;
      reached_min += g.projectile->dimensions[k] < 0.11 ? 1 : 0;
    }
    density_changed += g.projectile->density != density ? 1 : 0;
    GenomeLimits dense = limits;
    dense.projectile_density_mutation = true;
    density_free += mutate(g, dense, settings, rng).projectile->density != density ? 1 : 0;
  }
  EXPECT_GT(reached_max, 20);
  EXPECT_GT(reached_min, 20);
  EXPECT_EQ(density_changed, 0);
  EXPECT_GT(density_free, 150);
}

// grafting into the root brings the second parent's root along every time; into any node, a
// graft below it leaves that root behind (dropped, unreachable) about two times in three
TEST(Operators, GraftIntoAnyNode) {
  Genome a;
  a.nodes.emplace_back();
  a.nodes[0].dimensions = {0.5, 0.5, 0.5};
  Genome b;
  for (double side : {0.11, 0.22, 0.33}) {
    b.nodes.emplace_back();
    b.nodes.back().dimensions = {side, side, side};
  }
  for (std::uint16_t from : {0, 1}) {
    ConnectionGene c;
    c.from = from;
    c.to = static_cast<std::uint16_t>(from + 1);
    b.connections.push_back(c);
  }
  auto has_b_root = [](const Genome& g) {
    return std::any_of(g.nodes.begin(), g.nodes.end(),
                       [](const PartGene& n) { return n.dimensions.x == 0.11; });
  };
  int root_kept = 0, any_kept = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    Rng rng(17, RngPurpose::variation, 0, i);
    root_kept += has_b_root(graft(a, b, GenomeLimits{}, rng, GraftInto::root)) ? 1 : 0;
    any_kept += has_b_root(graft(a, b, GenomeLimits{}, rng, GraftInto::any_node)) ? 1 : 0;
  }
  EXPECT_EQ(root_kept, 300);
  EXPECT_GT(any_kept, 60);
  EXPECT_LT(any_kept, 140);
}

// mutation, crossover and grafting in a chaotic run keep every controller chaotic and valid, and
// mutation moves the circuits' starts and speeds
TEST(Operators, ChaoticControllersStayChaoticAndValid) {
  const GenomeLimits limits = test::chaoticLimits();
  int moved = 0;
  for (std::uint64_t lineage = 0; lineage < 50; ++lineage) {
    Genome g = randomGenome(limits, 73, 0, lineage);
    const Genome other = randomGenome(limits, 74, 0, lineage);
    for (std::uint64_t generation = 0; generation < 20; ++generation) {
      Rng rng(73, RngPurpose::variation, generation, lineage);
      const Genome before = g;
      g = mutate(g, limits, aggressive(true), rng);
      g = generation % 3 == 0 ? crossover(g, other, limits, rng) : g;
      g = generation % 5 == 0 ? graft(g, other, limits, rng) : g;
      ASSERT_NO_THROW(validateGenome(g, limits));
      for (const ConnectionGene& c : g.connections)
        ASSERT_EQ(c.controller.kind, JointControllerKind::chaotic);
      for (std::size_t i = 0; i < std::min(g.connections.size(), before.connections.size()); ++i) {
        moved +=
            g.connections[i].controller.chua_start != before.connections[i].controller.chua_start ||
            g.connections[i].controller.chua_speed != before.connections[i].controller.chua_speed;
      }
    }
  }
  EXPECT_GT(moved, 100);
}

// mutation flips a node's photosensitive flag under genome.photosensors = chosen, never otherwise
TEST(Operators, MutationFlipsPhotosensitivePartsOnlyWhereTheGenomeChooses) {
  GenomeLimits chosen;
  chosen.photosensors = Photosensors::chosen;
  int flipped = 0;
  for (std::uint64_t i = 0; i < 100; ++i) {
    const Genome parent = randomGenome(chosen, 75, 0, i);
    Rng rng(75, RngPurpose::variation, 1, i);
    const Genome child = mutate(parent, chosen, aggressive(true), rng);
    ASSERT_NO_THROW(validateGenome(child, chosen));
    // nodes keep their places unless mutation adds or removes some
    if (child.nodes.size() == parent.nodes.size()) {
      for (std::size_t n = 0; n < child.nodes.size(); ++n)
        flipped += child.nodes[n].photosensitive != parent.nodes[n].photosensitive;
    }
    // elsewhere no node becomes photosensitive
    const Genome plain = randomGenome(GenomeLimits{}, 75, 0, i);
    for (const Photosensors where : {Photosensors::root, Photosensors::every_part}) {
      GenomeLimits limits;
      limits.photosensors = where;
      Rng plain_rng(75, RngPurpose::variation, 1, i);
      for (const PartGene& node : mutate(plain, limits, aggressive(true), plain_rng).nodes)
        ASSERT_FALSE(node.photosensitive) << i;
    }
  }
  EXPECT_GT(flipped, 20);
}

}  // namespace
}  // namespace cambrian::graph
