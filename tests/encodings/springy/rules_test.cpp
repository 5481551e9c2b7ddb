// The consistency rules 1 to 7: each fires on an organism built to break it, naming the rule and
// the part.
#include "encodings/springy/rules.hpp"

#include "cambrian/error.hpp"

#include "encodings/springy/organisms.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian::springy {
namespace {

using test::node;
using test::tube;

// the message checkOrganism gives, "" when the organism is valid
std::string broken(const Organism& organism, const MuscleLimits& limits = {}) {
  try {
    checkOrganism(organism, limits);
  } catch (const GenomeError& e) {
    return e.what();
  }
  return "";
}

bool says(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

TEST(Rules, TheTestOrganismsAreValid) {
  EXPECT_EQ(broken(test::pyramid()), "");
  EXPECT_EQ(broken(test::screenshotMuscle()), "");
}

TEST(Rules, Rule1TheOrganismIsConnected) {
  Organism o = test::pyramid();
  o.nodes.push_back(node("loner", 3, 0, 0.1));
  const std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 1")) << message;
  EXPECT_TRUE(says(message, "'loner'")) << message;
}

TEST(Rules, Rule2NoPartsIntersect) {
  // a tube shorter than its nodes' radii
  Organism o;
  o.nodes = {node("a", 0, 0, 0.1), node("b", 0.15, 0, 0.1)};
  o.tubes = {tube("r", 0, 1, TubeKind::rod)};
  std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 2")) << message;
  EXPECT_TRUE(says(message, "rod 'r'")) << message;
  // two nodes overlapping, not joined
  o = test::pyramid();
  o.nodes.push_back(node("near", 0.05, 0.1, 0.1));
  o.tubes.push_back(tube("to_near", 4, 1, TubeKind::rod));
  message = broken(o);
  EXPECT_TRUE(says(message, "rule 2")) << message;
  EXPECT_TRUE(says(message, "nodes 'a' and 'near' overlap")) << message;
  // a tube through a node that is not its end
  o = Organism{};
  o.nodes = {node("a", 0, 0, 0.1), node("b", 2, 0, 0.1), node("middle", 1, 0.1, 0.1),
             node("up", 1, 1, 0.1)};
  o.tubes = {tube("long", 0, 1, TubeKind::rod), tube("stem", 2, 3, TubeKind::rod),
             tube("side", 1, 3, TubeKind::rod)};
  message = broken(o);
  EXPECT_TRUE(says(message, "rule 2")) << message;
  EXPECT_TRUE(says(message, "rod 'long' (nodes 'a' and 'b') passes through node 'middle'"))
      << message;
  // two tubes crossing: a square's diagonals
  o = Organism{};
  o.nodes = {node("a", 0, 0, 0.1), node("b", 1, 0, 0.1), node("c", 1, 1, 0.1),
             node("d", 0, 1, 0.1)};
  o.tubes = {tube("ac", 0, 2, TubeKind::rod), tube("bd", 1, 3, TubeKind::rod),
             tube("ab", 0, 1, TubeKind::rod)};
  message = broken(o);
  EXPECT_TRUE(says(message, "rule 2")) << message;
  EXPECT_TRUE(says(message,
                   "rod 'ac' (nodes 'a' and 'c') and rod 'bd' (nodes 'b' and 'd') "
                   "intersect"))
      << message;
  // tubes meeting at a node do not count
  o.tubes = {tube("ab", 0, 1, TubeKind::rod), tube("bc", 1, 2, TubeKind::rod),
             tube("cd", 2, 3, TubeKind::rod), tube("da", 3, 0, TubeKind::rod)};
  EXPECT_EQ(broken(o), "");
}

TEST(Rules, Rule3AmplitudeAndFrequencyAreNotNegative) {
  Organism o = test::screenshotMuscle();
  o.tubes[0].muscle.frequency = -1;
  std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 3")) << message;
  EXPECT_TRUE(says(message, "muscle 'm' (nodes 'left' and 'right')")) << message;
  o = test::screenshotMuscle();
  o.tubes[0].muscle.amplitude = -0.215;
  EXPECT_TRUE(says(broken(o), "rule 3"));
}

// Fig. A.5 with L_i moved to 1.2 m: outside 0.701 .. 1.131
TEST(Rules, Rule4TheInitialLengthIsInsideTheRange) {
  Organism o = test::screenshotMuscle();
  o.nodes[1].position.x = 1.2;
  const std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 4")) << message;
  EXPECT_TRUE(says(message, "1.2 m is outside 0.701 .. 1.131 m")) << message;
}

TEST(Rules, Rule5TheShortestLengthKeepsTheNodesApart) {
  Organism o = test::screenshotMuscle();
  o.tubes[0].muscle = {0.6, 0.44, 1, FirstMove::lengthen};  // 0.16 .. 1.04
  const std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 5")) << message;
  EXPECT_TRUE(says(message, "0.16")) << message;
}

TEST(Rules, Rule6TheLongestLengthIsAtMostTheMaximalLength) {
  Organism o = test::screenshotMuscle();
  MuscleLimits limits;
  limits.max_length = 1.1;
  const std::string message = broken(o, limits);
  EXPECT_TRUE(says(message, "rule 6")) << message;
  EXPECT_TRUE(says(message, "1.131 m is above 1.1 m")) << message;
}

TEST(Rules, Rule7TheFrequencyIsAtMostTheMaximalFrequency) {
  Organism o = test::screenshotMuscle();
  o.tubes[0].muscle.frequency = 2.5;
  const std::string message = broken(o);
  EXPECT_TRUE(says(message, "rule 7")) << message;
  EXPECT_TRUE(says(message, "2.5 Hz is above 2 Hz")) << message;
  o.tubes[0].muscle.frequency = 2;  // the range is 0–2 Hz
  EXPECT_EQ(broken(o), "");
}

TEST(Rules, WhatIsNotAnOrganismIsRefusedByName) {
  Organism o = test::pyramid();
  o.tubes[1].b = o.tubes[1].a;
  EXPECT_TRUE(says(broken(o), "tube 'bc' joins node 'b' to itself"));
  o = test::pyramid();
  o.tubes[1].b = 9;
  EXPECT_TRUE(says(broken(o), "tube 'bc' joins a node that does not exist"));
  o = test::pyramid();
  o.nodes[2].name = "a";
  EXPECT_TRUE(says(broken(o), "two nodes are named 'a'"));
  o = test::pyramid();
  o.nodes[2].mass = 0;
  EXPECT_TRUE(says(broken(o), "node 'c': mass 0 must be > 0"));
  EXPECT_TRUE(says(broken(Organism{}), "no nodes"));
}

TEST(Rules, SegmentDistances) {
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}), 0);
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}), 1);
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0, 0}, {1, 0, 0}, {0.5, -1, 2}, {0.5, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}), 2);
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0, 0}, {0, 0, 0}, {3, 4, 0}, {3, 4, 0}), 5);
  EXPECT_DOUBLE_EQ(pointSegmentDistance({0.5, 2, 0}, {0, 0, 0}, {1, 0, 0}), 2);
  EXPECT_DOUBLE_EQ(pointSegmentDistance({-3, 4, 0}, {0, 0, 0}, {1, 0, 0}), 5);
}

}  // namespace
}  // namespace cambrian::springy
