// Tests of Minemonics' reaper operators on the directed graph: validity, and each operator's
// effect on hand-made genomes.
#include "encodings/directed_graph/reaper_operators.hpp"

#include "cambrian/rng.hpp"

#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace cambrian::graph {
namespace {

// a genome of one box of `size`
Genome oneBox(Vec3 size) {
  Genome g;
  g.nodes.emplace_back();
  g.nodes[0].dimensions = size;
  return g;
}

// every operator, repeated along many lineages, leaves valid genomes that develop
TEST(ReaperOperators, AlwaysValidAndDevelop) {
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  for (std::uint64_t lineage = 0; lineage < 60; ++lineage) {
    Genome g = randomGenome(limits, 81, 0, lineage);
    for (std::uint64_t step = 0; step < 24; ++step) {
      Rng rng(81, RngPurpose::variation, step, lineage);
      Genome donor = randomGenome(limits, 82, step, lineage);
      switch (step % 6) {
        case 0:
          g = specifyGenes(g, limits, settings, rng);
          break;
        case 1:
          g = splitGenes(g, limits, settings, rng);
          break;
        case 2:
          g = purgeGene(g, limits, rng);
          break;
        case 3:
          g = specifyBranches(g, limits, settings, rng);
          break;
        case 4:
          g = growStubs(g, limits, settings, rng);
          break;
        default:
          g = graftFeature(g, donor, limits, settings, rng);
          break;
      }
      ASSERT_NO_THROW(validateGenome(g, limits)) << "lineage " << lineage << " step " << step;
      ASSERT_NO_THROW(develop(g, limits)) << "lineage " << lineage << " step " << step;
    }
  }
}

// the world-space box around a part
struct Box {
  Vec3 lo, hi;
};
Box boxOf(const PartPlan& part) {
  Box box{part.pose.position, part.pose.position};
  for (int k = 0; k < 3; ++k) {
    Vec3 axis{0, 0, 0};
    axis[k] = 0.5 * part.size[k];
    const Vec3 half = rotate(part.pose.rotation, axis);
    for (int j = 0; j < 3; ++j) {
      box.lo[j] -= std::abs(half[j]);
      box.hi[j] += std::abs(half[j]);
    }
  }
  return box;
}

// a split gene's halves fill the box the gene filled, and what hung on the face the second half
// covers hangs where it hung before, turned as before: along each of x, y and z
TEST(ReaperOperators, GeneSplitHalvesFillTheBoxAndKeepWhatHungOnIt) {
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  settings.gene_split_chance = 1;
  std::set<int> axes_seen;
  for (int face = 0; face < 3; ++face) {
    // a root box and a child on its +face (a hinge, slightly turned), too small to split
    Genome g = oneBox({0.4, 0.3, 0.2});
    g.nodes.emplace_back();
    g.nodes[1].dimensions = {0.09, 0.08, 0.07};
    ConnectionGene c;
    c.from = 0;
    c.to = 1;
    c.position = {0.2, -0.3, 0.1};
    c.position[face] = 1;
    c.orientation = {0.1, 0.2, 0.3};
    g.connections.push_back(c);
    const BodyPlan before = develop(g, limits).body;

    for (std::uint64_t draw = 0; draw < 40; ++draw) {
      Rng rng(83, RngPurpose::test, static_cast<std::uint64_t>(face), draw);
      Genome split = splitGenes(g, limits, settings, rng);
      // the root's split: the axis whose side was halved
      int axis = -1;
      for (int k = 0; k < 3; ++k) {
        if (split.nodes[0].dimensions[k] < g.nodes[0].dimensions[k] - 1e-12)
          axis = k;
      }
      ASSERT_GE(axis, 0);
      axes_seen.insert(axis);
      const BodyPlan after = develop(split, limits).body;
      // the root's second half (node 2) and the child (node 1)
      std::size_t half = 0, child = 0;
      for (std::size_t p = 1; p < after.parts.size(); ++p) {
        if (after.parts[p].node == 2 && after.parts[p].parent == 0)
          half = p;
        if (after.parts[p].node == 1)
          child = p;
      }
      ASSERT_GT(half, 0u) << "axis " << axis;
      ASSERT_GT(child, 0u);
      ASSERT_EQ(split.nodes.size(), 3u);
      EXPECT_EQ(after.parts[half].joint, JointType::fixed);

      // the two halves: the root's box shifted, with the root's volume
      const Box whole = boxOf(before.parts[0]);
      Box a = boxOf(after.parts[0]), b = boxOf(after.parts[half]);
      Box both{{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
               {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(both.hi[k] - both.lo[k], whole.hi[k] - whole.lo[k], 1e-9) << "axis " << axis;
      const Vec3 s0 = after.parts[0].size, s1 = after.parts[half].size, s = before.parts[0].size;
      EXPECT_NEAR(s0.x * s0.y * s0.z + s1.x * s1.y * s1.z, s.x * s.y * s.z, 1e-12);

      // the child: same place relative to that box, same turn, when it hung on the covered face
      // (for axis == face); otherwise it stays on the first half
      const PartPlan& was = before.parts[1];
      const PartPlan& is = after.parts[child];
      if (axis == face) {
        EXPECT_EQ(is.parent, half);
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(is.pose.position[k] - both.lo[k], was.pose.position[k] - whole.lo[k], 1e-9)
              << "axis " << axis << " component " << k;
        }
        const Quat q = is.pose.rotation, r = was.pose.rotation;
        EXPECT_NEAR(std::abs(q.w * r.w + q.x * r.x + q.y * r.y + q.z * r.z), 1, 1e-9);
      } else {
        EXPECT_EQ(is.parent, 0u);
      }
    }
  }
  EXPECT_EQ(axes_seen.size(), 3u);
}

// no split below genome.min_part_size, nor past the node limit
TEST(ReaperOperators, GeneSplitKeepsToTheLimits) {
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  settings.gene_split_chance = 1;
  Rng rng(84, RngPurpose::test);
  limits.min_part_size = 0.06;
  EXPECT_EQ(splitGenes(oneBox({0.1, 0.1, 0.1}), limits, settings, rng), oneBox({0.1, 0.1, 0.1}));
  limits.min_part_size = 0.05;
  limits.max_nodes = 1;
  EXPECT_EQ(splitGenes(oneBox({0.4, 0.4, 0.4}), limits, settings, rng), oneBox({0.4, 0.4, 0.4}));
  // without rigid joints, the halves' joint is the first allowed type, held at 0
  limits.max_nodes = 20;
  limits.joint_types = 1u << static_cast<int>(JointType::revolute);
  Genome split = splitGenes(oneBox({0.4, 0.4, 0.4}), limits, settings, rng);
  ASSERT_EQ(split.nodes.size(), 2u);
  EXPECT_EQ(split.nodes[1].joint_type, JointType::revolute);
  EXPECT_EQ(split.nodes[1].joint_limit, (Vec3{0, 0, 0}));
}

// purge: one non-root gene is re-drawn and nothing else leads into it; a one-gene genome stays
TEST(ReaperOperators, GenePurgeCutsOneGeneOff) {
  GenomeLimits limits;
  Genome g = oneBox({0.3, 0.3, 0.3});
  for (int i = 0; i < 3; ++i)
    g.nodes.emplace_back();
  // 0 -> 1, 0 -> 2, 1 -> 2, 2 -> 2, 2 -> 3
  for (auto [from, to] :
       std::array<std::pair<int, int>, 5>{{{0, 1}, {0, 2}, {1, 2}, {2, 2}, {2, 3}}}) {
    ConnectionGene c;
    c.from = static_cast<std::uint16_t>(from);
    c.to = static_cast<std::uint16_t>(to);
    g.connections.push_back(c);
  }
  std::set<int> purged_seen;
  for (std::uint64_t draw = 0; draw < 30; ++draw) {
    Rng rng(85, RngPurpose::test, 0, draw);
    Genome p = purgeGene(g, limits, rng);
    ASSERT_EQ(p.nodes.size(), g.nodes.size());
    EXPECT_EQ(p.nodes[0], g.nodes[0]);
    int purged = -1;
    for (int i = 1; i < 4; ++i) {
      if (!(p.nodes[static_cast<std::size_t>(i)] == g.nodes[static_cast<std::size_t>(i)]))
        purged = i;
    }
    ASSERT_GT(purged, 0) << "draw " << draw;
    purged_seen.insert(purged);
    for (const ConnectionGene& c : p.connections)
      EXPECT_FALSE(c.to == purged && c.from != purged) << "draw " << draw;
    // every other connection is kept
    const auto kept = std::count_if(
        g.connections.begin(), g.connections.end(),
        [&](const ConnectionGene& c) { return !(c.to == purged && c.from != purged); });
    EXPECT_EQ(static_cast<long>(p.connections.size()), kept);
  }
  EXPECT_EQ(purged_seen, (std::set<int>{1, 2, 3}));
  Rng rng(85, RngPurpose::test);
  EXPECT_EQ(purgeGene(oneBox({0.3, 0.3, 0.3}), limits, rng), oneBox({0.3, 0.3, 0.3}));
}

// branch specification re-draws one connection per chosen gene, ends kept; gene specification
// re-draws genes, connections kept
TEST(ReaperOperators, SpecificationsRedrawGenesOrConnectionsOnly) {
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  settings.branch_specification_chance = 1;
  settings.gene_specification_chance = 1;
  for (std::uint64_t i = 0; i < 50; ++i) {
    Genome g = randomGenome(limits, 86, 0, i);
    Rng rng(86, RngPurpose::test, 1, i);
    Genome b = specifyBranches(g, limits, settings, rng);
    EXPECT_EQ(b.nodes, g.nodes);
    ASSERT_EQ(b.connections.size(), g.connections.size());
    std::set<int> changed_from;
    for (std::size_t c = 0; c < g.connections.size(); ++c) {
      EXPECT_EQ(b.connections[c].from, g.connections[c].from);
      EXPECT_EQ(b.connections[c].to, g.connections[c].to);
      if (!(b.connections[c] == g.connections[c])) {
        EXPECT_TRUE(changed_from.insert(g.connections[c].from).second)
            << "two connections of one gene re-drawn";
      }
    }
    // every gene with connections had one re-drawn (chance 1)
    std::set<int> with_connections;
    for (const ConnectionGene& c : g.connections)
      with_connections.insert(c.from);
    EXPECT_EQ(changed_from, with_connections) << "genome " << i;

    Genome s = specifyGenes(g, limits, settings, rng);
    EXPECT_EQ(s.connections, g.connections);
    ASSERT_EQ(s.nodes.size(), g.nodes.size());
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      EXPECT_FALSE(s.nodes[n] == g.nodes[n]) << "genome " << i << " node " << n;
  }
}

// grow stub adds 0..grow_stub_max connections per gene and changes nothing else
TEST(ReaperOperators, GrowStubAddsUpToTheMostConnectionsPerGene) {
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  settings.grow_stub_chance = 1;
  int grown = 0;
  for (std::uint64_t i = 0; i < 50; ++i) {
    Genome g = randomGenome(limits, 87, 0, i);
    Rng rng(87, RngPurpose::test, 1, i);
    Genome s = growStubs(g, limits, settings, rng);
    EXPECT_EQ(s.nodes, g.nodes);
    ASSERT_GE(s.connections.size(), g.connections.size());
    EXPECT_TRUE(std::equal(g.connections.begin(), g.connections.end(), s.connections.begin()));
    std::vector<int> added(g.nodes.size(), 0);
    for (std::size_t c = g.connections.size(); c < s.connections.size(); ++c) {
      ASSERT_LT(s.connections[c].to, g.nodes.size());
      ++added[s.connections[c].from];
    }
    for (int a : added)
      EXPECT_LE(a, settings.grow_stub_max);
    grown += static_cast<int>(s.connections.size() - g.connections.size());
  }
  EXPECT_GT(grown, 0);
  settings.grow_stub_max = 0;
  Genome g = randomGenome(limits, 87, 0, 0);
  Rng rng(87, RngPurpose::test);
  EXPECT_EQ(growStubs(g, limits, settings, rng), g);
}

// a feature: the chosen gene first, genes down to the depth, breadth first, with their
// connections; a chain 0 -> 1 -> 2 -> 3 -> 4 with a branch 1 -> 4 and a loop 2 -> 2
TEST(ReaperOperators, AFeatureIsTheGenesDownToItsDepth) {
  Genome donor;
  for (int i = 0; i < 5; ++i) {
    donor.nodes.emplace_back();
    donor.nodes.back().density = 1000 + i;  // tells the genes apart
  }
  for (auto [from, to] :
       std::array<std::pair<int, int>, 6>{{{0, 1}, {1, 2}, {2, 3}, {3, 4}, {1, 4}, {2, 2}}}) {
    ConnectionGene c;
    c.from = static_cast<std::uint16_t>(from);
    c.to = static_cast<std::uint16_t>(to);
    donor.connections.push_back(c);
  }
  auto densities = [](const Genome& g) {
    std::vector<int> d;
    for (const PartGene& node : g.nodes)
      d.push_back(static_cast<int>(node.density) - 1000);
    return d;
  };
  // from gene 1, two levels: 1, then 2 and 4 (breadth first, connection order)
  Genome two = featureOf(donor, 1, 2);
  EXPECT_EQ(densities(two), (std::vector<int>{1, 2, 4}));
  // connections among them: 1 -> 2, 1 -> 4, 2 -> 2, renumbered
  ASSERT_EQ(two.connections.size(), 3u);
  EXPECT_EQ(two.connections[0].from, 0);
  EXPECT_EQ(two.connections[0].to, 1);
  EXPECT_EQ(two.connections[1].to, 2);
  EXPECT_EQ(two.connections[2].from, 1);
  EXPECT_EQ(two.connections[2].to, 1);
  EXPECT_EQ(densities(featureOf(donor, 1, 1)), (std::vector<int>{1}));
  EXPECT_EQ(densities(featureOf(donor, 0, 10)), (std::vector<int>{0, 1, 2, 4, 3}));
  EXPECT_EQ(densities(featureOf(donor, 3, 5)), (std::vector<int>{3, 4}));

  // grafted: the receiver keeps its genes, and its new genes are a feature of the donor
  GenomeLimits limits;
  ReaperOperatorSettings settings;
  Genome receiver = oneBox({0.3, 0.3, 0.3});
  receiver.nodes[0].density = 900;
  for (std::uint64_t draw = 0; draw < 20; ++draw) {
    Rng rng(88, RngPurpose::test, 0, draw);
    Genome grafted = graftFeature(receiver, donor, limits, settings, rng);
    ASSERT_GE(grafted.nodes.size(), 2u);
    EXPECT_EQ(grafted.nodes[0], receiver.nodes[0]);
    EXPECT_EQ(grafted.connections.front().from, 0);
    EXPECT_EQ(grafted.connections.front().to, 1);
  }
}

}  // namespace
}  // namespace cambrian::graph

namespace cambrian::graph {
namespace {

// a chain genome of `n` boxes, node i of side 0.1 + 0.01 i + `mark`, each led to from the last
Genome chainOf(int n, double mark) {
  Genome g;
  for (int i = 0; i < n; ++i) {
    PartGene node;
    node.dimensions = {0.1 + 0.01 * i + mark, 0.1, 0.1};
    g.nodes.push_back(node);
    if (i > 0) {
      ConnectionGene c;
      c.from = static_cast<std::uint16_t>(i - 1);
      c.to = static_cast<std::uint16_t>(i);
      g.connections.push_back(c);
    }
  }
  return g;
}

// Minemonics' crossover: a run of the mother's genes then a run of the father's, each with the
// connections leaving it; ends inside a segment kept, the others led into the child; valid
TEST(ReaperOperators, ASegmentCrossoverJoinsARunOfEachParent) {
  const GenomeLimits limits;
  ReaperOperatorSettings settings;
  settings.segment_branch_redraws = 0;
  const Genome mother = chainOf(6, 0), father = chainOf(5, 0.5);
  std::set<std::size_t> sizes;
  int with_father = 0;
  for (std::uint64_t i = 0; i < 400; ++i) {
    Rng rng(5, RngPurpose::test, i, 0);
    const Genome child = crossSegments(mother, father, limits, settings, rng);
    ASSERT_NO_THROW(validateGenome(child, limits)) << i;
    sizes.insert(child.nodes.size());
    // the mother's run, then the father's: consecutive genes of each
    std::size_t m = 0;
    while (m < child.nodes.size() && child.nodes[m].dimensions.x < 0.5)
      ++m;
    ASSERT_GE(m, 1u) << i;  // the root is the mother's
    for (std::size_t k = 1; k < child.nodes.size(); ++k) {
      if (k == m)
        continue;
      EXPECT_NEAR(child.nodes[k].dimensions.x - child.nodes[k - 1].dimensions.x, 0.01, 1e-12);
    }
    with_father += child.nodes.size() > m;
    // every gene's outgoing chain link inside its run is kept; every connection is valid
    for (const ConnectionGene& c : child.connections) {
      ASSERT_LT(c.to, child.nodes.size());
      const bool same_run = (c.from < m) == (c.to < m);
      if (same_run && c.to == c.from + 1u)
        continue;
      // a repaired end: the parent's link left its run (the last gene of a run)
      EXPECT_TRUE(c.from + 1u == m || c.from + 1u == child.nodes.size()) << i;
    }
  }
  EXPECT_GT(sizes.size(), 6u);
  EXPECT_GT(with_father, 200);

  // the re-draws change connections but keep their ends
  settings.segment_branch_redraws = 10;
  Rng plain(9, RngPurpose::test, 0, 0), redrawn(9, RngPurpose::test, 0, 0);
  ReaperOperatorSettings none = settings;
  none.segment_branch_redraws = 0;
  const Genome a = crossSegments(mother, father, limits, none, plain);
  const Genome b = crossSegments(mother, father, limits, settings, redrawn);
  ASSERT_EQ(a.nodes, b.nodes);
  ASSERT_EQ(a.connections.size(), b.connections.size());
  bool changed = false;
  for (std::size_t c = 0; c < a.connections.size(); ++c) {
    EXPECT_EQ(a.connections[c].from, b.connections[c].from);
    EXPECT_EQ(a.connections[c].to, b.connections[c].to);
    changed = changed || !(a.connections[c] == b.connections[c]);
  }
  EXPECT_TRUE(changed || a.connections.empty());
}

}  // namespace
}  // namespace cambrian::graph
