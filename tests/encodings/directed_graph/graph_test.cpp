#include "encodings/directed_graph/graph.hpp"

#include "cambrian/encodings.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/operators.hpp"

#include <gtest/gtest.h>

namespace cambrian::graph {
namespace {

// a genome with `n` default nodes and the given edges
Genome graph(std::size_t n, std::vector<std::pair<int, int>> edges) {
  Genome g;
  g.nodes.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    g.nodes[i].density = 1000 + static_cast<double>(i);
  for (auto [from, to] : edges) {
    ConnectionGene c;
    c.from = static_cast<std::uint16_t>(from);
    c.to = static_cast<std::uint16_t>(to);
    g.connections.push_back(c);
  }
  return g;
}

TEST(Graph, ReachableFollowsDirectedEdges) {
  // 0 -> 2 -> 3 -> 3; 1 -> 0 does not make 1 reachable; 4 is isolated
  Genome g = graph(5, {{0, 2}, {2, 3}, {3, 3}, {1, 0}});
  EXPECT_EQ(reachableNodes(g), (std::vector<bool>{true, false, true, true, false}));
}

TEST(Graph, RemoveNodesRenumbers) {
  Genome g = graph(4, {{0, 1}, {0, 3}, {3, 2}, {1, 3}});
  removeNodes(g, {true, false, true, true});
  ASSERT_EQ(g.nodes.size(), 3u);
  EXPECT_EQ(g.nodes[1].density, 1002);
  EXPECT_EQ(g.nodes[2].density, 1003);
  // 0->1 and 1->3 touch the removed node; 0->3 becomes 0->2, 3->2 becomes 2->1
  ASSERT_EQ(g.connections.size(), 2u);
  EXPECT_EQ(g.connections[0].from, 0);
  EXPECT_EQ(g.connections[0].to, 2);
  EXPECT_EQ(g.connections[1].from, 2);
  EXPECT_EQ(g.connections[1].to, 1);
}

// removeUnreachableNodes keeps exactly the reachable nodes, in order, and their edges
TEST(Graph, RemoveUnreachableKeepsExactlyReachable) {
  Genome g = graph(6, {{0, 3}, {3, 5}, {1, 2}, {2, 3}, {5, 5}});
  Genome kept = removeUnreachableNodes(g);
  ASSERT_EQ(kept.nodes.size(), 3u);
  EXPECT_EQ(kept.nodes[0].density, 1000);
  EXPECT_EQ(kept.nodes[1].density, 1003);
  EXPECT_EQ(kept.nodes[2].density, 1005);
  ASSERT_EQ(kept.connections.size(), 3u);
  EXPECT_EQ(kept.connections[0].from, 0);
  EXPECT_EQ(kept.connections[0].to, 1);
  EXPECT_EQ(kept.connections[1].from, 1);
  EXPECT_EQ(kept.connections[1].to, 2);
  EXPECT_EQ(kept.connections[2].from, 2);
  EXPECT_EQ(kept.connections[2].to, 2);
  // a fully reachable genome is unchanged
  EXPECT_EQ(removeUnreachableNodes(kept), kept);
}

// removesNothing says exactly when removeNodes would leave the genome as it is
TEST(Graph, RemovesNothingOnlyWhereEverythingStays) {
  Genome g = graph(3, {{0, 1}, {1, 2}});
  EXPECT_TRUE(removesNothing(g, reachableNodes(g)));
  Genome same = g;
  removeNodes(same, reachableNodes(g));
  EXPECT_EQ(same, g);
  // a node dropped, a keep list too short, a connection's end out of range: each one removes
  EXPECT_FALSE(removesNothing(g, {true, false, true}));
  EXPECT_FALSE(removesNothing(g, {true, true}));
  Genome dangling = graph(3, {{0, 1}, {1, 2}, {2, 7}});
  EXPECT_FALSE(removesNothing(dangling, reachableNodes(dangling)));
  removeNodes(dangling, reachableNodes(dangling));
  EXPECT_EQ(dangling, g);
}

}  // namespace
}  // namespace cambrian::graph
