// Walking with Dinosaurs' grammar: the layer choosers, a hand-written DNA read gene by gene, zeros
// read past the end, the box limit, random DNA and writing a creature back as DNA.
#include "encodings/wwd/grammar.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace cambrian::wwd {
namespace {

constexpr double kDegree = kPi / 180;

// a gene read as a number in [lo, hi]
double between(double lo, double hi, Gene g) {
  return lo + g / 999.0 * (hi - lo);
}
// a gene read as a weight or constant value: max_weight (g - 500) / 500
double weight(Gene g, double max_weight = 5) {
  return max_weight * (g - 500.0) / 500;
}
// a gene read as a face coordinate: (g - 500) / 500
double coordinate(Gene g) {
  return (g - 500.0) / 500;
}

// A creature of two boxes, written gene by gene (default GrammarSettings); positions in brackets.
const Dna kTwoBoxes = {
    // [0, 5) root box: h w d Se, then its joint count
    999, 0, 333, 7,  // 10 x 0.05 x 3.3667 m, pressure sensor (7 is odd)
    7,               // 7 % 6 = 1 joint
    // [5, 38) joint 0: its subnet [5, 20)
    215,           // 215 % 100 = 15: two layers
    0,             // layer 0: chooser 0 with most probable 3: 2 nodes
    4, 999,        // ncv 4 % 4 = 0: constant 4.99
    6, 21,         // ncv 6 % 4 = 2 inputs, function 21 % 20 - 1 = 0: sum
    12, 3,         //   input genes
    0, 999,        //   weights -5, 4.99
    300,           // layer 1: chooser 300 with most probable 3: 1 node
    1, 0, 17,      // ncv 1: one input, function 0 - 1: sensor, input gene 17
    500,           //   weight 5 (500 - 500) / 500 = 0
    2, 5, 998,     // [20, 23) E: effector genes
    250,           // [23] screw: 250 2 pi / 1000 = pi / 2
    999, 0, 8,     // [24, 27) PRE: u 0.998, v -1, side 8 % 6 = 2 (+y)
    333, 666, 3,   // [27, 30) POST: u -0.334, v 0.332, side 3 (-y)
    999, 0, 333,   // [30, 33) DOF: 85, 0, 85/3 degrees
    0, 999, 0, 2,  // [33, 37) box 1: 0.05 x 10 x 0.05 m, no sensor (2 is even)
    6,             // [37] 6 % 6 = 0 joints on box 1
    // [38, 48) the main net
    114,          // 114 % 100 = 14: one layer
    525,          // chooser 525 with most probable 5: 1 node
    3, 39,        // ncv 3: three inputs, function 39 % 20 - 1 = 18: saw
    1, 2, 3,      //   input genes
    999, 0, 999,  //   weights 4.99, -5, 4.99
};

// every field readCreature reads from the genes: the layers of a net, node by node
void expectSameNet(const NetGenes& a, const NetGenes& b, const std::string& what) {
  ASSERT_EQ(a.layers.size(), b.layers.size()) << what;
  for (std::size_t l = 0; l < a.layers.size(); ++l) {
    ASSERT_EQ(a.layers[l].size(), b.layers[l].size()) << what << " layer " << l;
    for (std::size_t n = 0; n < a.layers[l].size(); ++n) {
      const NodeGenes& x = a.layers[l][n];
      const NodeGenes& y = b.layers[l][n];
      const std::string where = what + " layer " + std::to_string(l) + " node " + std::to_string(n);
      EXPECT_EQ(x.function, y.function) << where;
      EXPECT_EQ(x.value, y.value) << where;
      EXPECT_EQ(x.input_count, y.input_count) << where;
      EXPECT_EQ(x.inputs, y.inputs) << where;
      EXPECT_EQ(x.weights, y.weights) << where;
    }
  }
}

// two readings alike in every field but their spans, genes_read and truncated
void expectSameCreature(const CreatureGenes& a, const CreatureGenes& b) {
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(a.boxes[i].size, b.boxes[i].size) << "box " << i;
    EXPECT_EQ(a.boxes[i].pressure_sensor, b.boxes[i].pressure_sensor) << "box " << i;
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t j = 0; j < a.joints.size(); ++j) {
    const JointGenes& x = a.joints[j];
    const JointGenes& y = b.joints[j];
    const std::string what = "joint " + std::to_string(j);
    EXPECT_EQ(x.parent, y.parent) << what;
    EXPECT_EQ(x.child, y.child) << what;
    expectSameNet(x.subnet, y.subnet, what + "'s subnet");
    EXPECT_EQ(x.effector, y.effector) << what;
    EXPECT_NEAR(x.screw, y.screw, 1e-9) << what;
    for (const auto& [p, q] : {std::pair{x.pre, y.pre}, std::pair{x.post, y.post}}) {
      EXPECT_EQ(p.side, q.side) << what;
      EXPECT_EQ(p.u, q.u) << what;
      EXPECT_EQ(p.v, q.v) << what;
    }
    EXPECT_EQ(x.limit, y.limit) << what;
  }
  expectSameNet(a.main, b.main, "the main net");
}

// a joint to copy into hand-built creatures: kTwoBoxes' one
JointGenes aJoint(int parent, int child) {
  JointGenes joint = readCreature(kTwoBoxes, GrammarSettings{}).joints.at(0);
  joint.parent = parent;
  joint.child = child;
  return joint;
}

// 0-14 one layer, 15-39 two, 40-84 three, 85-99 four, the chooser taken mod 100
TEST(WwdGrammar, LayerCountsChangeAtTheirEdges) {
  EXPECT_EQ(layerCount(0), 1);
  EXPECT_EQ(layerCount(14), 1);
  EXPECT_EQ(layerCount(15), 2);
  EXPECT_EQ(layerCount(39), 2);
  EXPECT_EQ(layerCount(40), 3);
  EXPECT_EQ(layerCount(84), 3);
  EXPECT_EQ(layerCount(85), 4);
  EXPECT_EQ(layerCount(99), 4);
  EXPECT_EQ(layerCount(100), 1);
  EXPECT_EQ(layerCount(114), 1);
  EXPECT_EQ(layerCount(115), 2);
  EXPECT_EQ(layerCount(984), 3);
  EXPECT_EQ(layerCount(985), 4);
  EXPECT_EQ(layerCount(999), 4);
}

// most probable 5: 5 -+ i with 300 / 2^i per mille each. The choosers' boundaries are 150, 300
// (4, 6), 375, 450 (3, 7), 487.5, 525 (2, 8), 543.75, 562.5 (1, 9): chooser g < boundary picks
// the case, so 2 gets 450..487 (38), 8 gets 488..524 (37), 1 gets 525..543 (19), 9 gets 544..562
// (19), and 5 the 437 left
TEST(WwdGrammar, LayerSizesFollowTheSeedsChances) {
  std::map<int, int> counts;
  for (int g = 0; g < kGeneValues; ++g)
    ++counts[layerSize(static_cast<Gene>(g), 5)];
  const std::map<int, int> expected = {{1, 19},  {2, 38}, {3, 75}, {4, 150}, {5, 437},
                                       {6, 150}, {7, 75}, {8, 37}, {9, 19}};
  EXPECT_EQ(counts, expected);
  // the edges themselves
  EXPECT_EQ(layerSize(149, 5), 4);
  EXPECT_EQ(layerSize(150, 5), 6);
  EXPECT_EQ(layerSize(299, 5), 6);
  EXPECT_EQ(layerSize(300, 5), 3);
  EXPECT_EQ(layerSize(374, 5), 3);
  EXPECT_EQ(layerSize(375, 5), 7);
  EXPECT_EQ(layerSize(449, 5), 7);
  EXPECT_EQ(layerSize(450, 5), 2);
  EXPECT_EQ(layerSize(487, 5), 2);
  EXPECT_EQ(layerSize(488, 5), 8);
  EXPECT_EQ(layerSize(524, 5), 8);
  EXPECT_EQ(layerSize(525, 5), 1);
  EXPECT_EQ(layerSize(543, 5), 1);
  EXPECT_EQ(layerSize(544, 5), 9);
  EXPECT_EQ(layerSize(562, 5), 9);
  EXPECT_EQ(layerSize(563, 5), 5);
  EXPECT_EQ(layerSize(999, 5), 5);
}

// most probable 3 (the subnets): 2 and 4 150 each, 1 and 5 75 each, 3 the rest; most probable 1:
// always 1
TEST(WwdGrammar, SmallerNetsHaveFewerCases) {
  std::map<int, int> counts;
  for (int g = 0; g < kGeneValues; ++g)
    ++counts[layerSize(static_cast<Gene>(g), 3)];
  const std::map<int, int> expected = {{1, 75}, {2, 150}, {3, 550}, {4, 150}, {5, 75}};
  EXPECT_EQ(counts, expected);
  for (int g = 0; g < kGeneValues; ++g)
    ASSERT_EQ(layerSize(static_cast<Gene>(g), 1), 1) << g;
}

// kTwoBoxes read field by field
TEST(WwdGrammar, AHandWrittenDnaReadsGeneByGene) {
  const GrammarSettings settings;
  const CreatureGenes c = readCreature(kTwoBoxes, settings);
  EXPECT_EQ(c.genes_read, 48u);
  EXPECT_EQ(c.genes_read, kTwoBoxes.size());
  EXPECT_FALSE(c.truncated);

  // the boxes: min_side + g / 999 (max_side - min_side); the sensor from an odd gene
  ASSERT_EQ(c.boxes.size(), 2u);
  EXPECT_EQ(c.boxes[0].size.x, 10.0);
  EXPECT_EQ(c.boxes[0].size.y, 0.05);
  EXPECT_DOUBLE_EQ(c.boxes[0].size.z, 0.05 + 9.95 / 3);
  EXPECT_DOUBLE_EQ(c.boxes[0].size.z, between(0.05, 10, 333));
  EXPECT_TRUE(c.boxes[0].pressure_sensor);
  EXPECT_EQ(c.boxes[1].size, (Vec3{0.05, 10, 0.05}));
  EXPECT_FALSE(c.boxes[1].pressure_sensor);

  // the joint
  ASSERT_EQ(c.joints.size(), 1u);
  const JointGenes& j = c.joints[0];
  EXPECT_EQ(j.parent, 0);
  EXPECT_EQ(j.child, 1);
  EXPECT_EQ(j.span.begin, 5u);
  EXPECT_EQ(j.span.end, 38u);
  EXPECT_EQ(j.screw_gene, 23u);
  EXPECT_DOUBLE_EQ(j.screw, kPi / 2);
  EXPECT_EQ(j.effector, (std::array<Gene, 3>{2, 5, 998}));
  EXPECT_EQ(j.pre.side, 2);
  EXPECT_DOUBLE_EQ(j.pre.u, coordinate(999));
  EXPECT_DOUBLE_EQ(j.pre.u, 0.998);
  EXPECT_DOUBLE_EQ(j.pre.v, -1);
  EXPECT_EQ(j.post.side, 3);
  EXPECT_DOUBLE_EQ(j.post.u, -0.334);
  EXPECT_DOUBLE_EQ(j.post.v, 0.332);
  EXPECT_DOUBLE_EQ(j.limit.x, 85 * kDegree);
  EXPECT_EQ(j.limit.y, 0.0);
  EXPECT_DOUBLE_EQ(j.limit.z, 85.0 / 3 * kDegree);

  // its subnet: two layers of 2 and 1 nodes
  EXPECT_EQ(j.subnet.span.begin, 5u);
  EXPECT_EQ(j.subnet.span.end, 20u);
  ASSERT_EQ(j.subnet.layers.size(), 2u);
  ASSERT_EQ(j.subnet.layers[0].size(), 2u);
  ASSERT_EQ(j.subnet.layers[1].size(), 1u);
  const NodeGenes& constant = j.subnet.layers[0][0];
  EXPECT_EQ(constant.function, LayeredFunction::constant);
  EXPECT_EQ(constant.input_count, 0);
  EXPECT_DOUBLE_EQ(constant.value, 4.99);
  const NodeGenes& sum = j.subnet.layers[0][1];
  EXPECT_EQ(sum.function, LayeredFunction::sum);
  EXPECT_EQ(sum.input_count, 2);
  EXPECT_EQ(sum.inputs[0], 12);
  EXPECT_EQ(sum.inputs[1], 3);
  EXPECT_DOUBLE_EQ(sum.weights[0], -5);
  EXPECT_DOUBLE_EQ(sum.weights[1], 4.99);
  const NodeGenes& sensor = j.subnet.layers[1][0];
  EXPECT_EQ(sensor.function, LayeredFunction::sensor);
  EXPECT_EQ(sensor.input_count, 1);
  EXPECT_EQ(sensor.inputs[0], 17);
  EXPECT_DOUBLE_EQ(sensor.weights[0], weight(500));
  EXPECT_EQ(sensor.weights[0], 0.0);

  // the main net: one layer of one saw node
  EXPECT_EQ(c.main.span.begin, 38u);
  EXPECT_EQ(c.main.span.end, 48u);
  ASSERT_EQ(c.main.layers.size(), 1u);
  ASSERT_EQ(c.main.layers[0].size(), 1u);
  const NodeGenes& saw = c.main.layers[0][0];
  EXPECT_EQ(saw.function, LayeredFunction::saw);
  EXPECT_EQ(saw.input_count, 3);
  EXPECT_EQ(saw.inputs, (std::array<Gene, 3>{1, 2, 3}));
  EXPECT_EQ(saw.weights, (std::array<double, 3>{weight(999), -5, weight(999)}));
}

// the settings scale what the genes are read into
TEST(WwdGrammar, TheSettingsScaleTheNumbersRead) {
  GrammarSettings settings;
  settings.min_side = 1;
  settings.max_side = 2;
  settings.max_joint_limit = 45;
  settings.max_weight = 2;
  const CreatureGenes c = readCreature(kTwoBoxes, settings);
  EXPECT_EQ(c.boxes[0].size.x, 2.0);
  EXPECT_EQ(c.boxes[0].size.y, 1.0);
  EXPECT_DOUBLE_EQ(c.boxes[0].size.z, between(1, 2, 333));
  EXPECT_DOUBLE_EQ(c.joints[0].limit.x, 45 * kDegree);
  EXPECT_DOUBLE_EQ(c.joints[0].subnet.layers[0][0].value, weight(999, 2));
  EXPECT_DOUBLE_EQ(c.joints[0].subnet.layers[0][1].weights[0], -2);
  EXPECT_DOUBLE_EQ(c.joints[0].subnet.layers[1][0].weights[0], weight(500, 2));
}

// the function gene: 0 the sensor, 1..19 sum..saw, taken mod 20; the node case mod 4
TEST(WwdGrammar, TheNodeGenesPickTheFunctionModuloItsCases) {
  for (int f = 0; f < 40; ++f) {
    // one layer of one node: ncv 1 (one input), function f, input 0, weight 999
    const Dna dna = {0, 0, 0, 0, 0, 0, 525, 5, static_cast<Gene>(f), 0, 999};
    const CreatureGenes c = readCreature(dna, GrammarSettings{});
    ASSERT_EQ(c.main.layers.at(0).size(), 1u);
    const NodeGenes& node = c.main.layers[0][0];
    EXPECT_EQ(static_cast<int>(node.function), f % 20 - 1) << f;
    EXPECT_EQ(node.input_count, 1);
    EXPECT_EQ(c.genes_read, dna.size());
  }
}

// an empty DNA reads zeros: box 0 is min_side cubed without a sensor, 0 joints, and the main net
// one layer (0 % 100) of 4 nodes (chooser 0: most probable - 1), each a constant (ncv 0) of
// value max_weight (0 - 500) / 500 = -5: 4 + 1 + 1 + 1 + 4 x 2 = 15 genes
TEST(WwdGrammar, ReadingPastTheEndReadsZeros) {
  const GrammarSettings settings;
  const CreatureGenes c = readCreature({}, settings);
  ASSERT_EQ(c.boxes.size(), 1u);
  EXPECT_EQ(c.boxes[0].size, (Vec3{0.05, 0.05, 0.05}));
  EXPECT_FALSE(c.boxes[0].pressure_sensor);
  EXPECT_TRUE(c.joints.empty());
  EXPECT_FALSE(c.truncated);
  ASSERT_EQ(c.main.layers.size(), 1u);
  ASSERT_EQ(c.main.layers[0].size(), 4u);
  for (const NodeGenes& node : c.main.layers[0]) {
    EXPECT_EQ(node.function, LayeredFunction::constant);
    EXPECT_EQ(node.input_count, 0);
    EXPECT_EQ(node.value, -5.0);
  }
  EXPECT_EQ(c.main.span.begin, 5u);
  EXPECT_EQ(c.main.span.end, 15u);
  EXPECT_EQ(c.genes_read, 15u);

  // cut short inside a joint: the joint and the main net are read on over zeros, reading past the
  // DNA's end
  const Dna cut(kTwoBoxes.begin(), kTwoBoxes.begin() + 30);
  const CreatureGenes short_read = readCreature(cut, settings);
  ASSERT_EQ(short_read.joints.size(), 1u);
  EXPECT_EQ(short_read.joints[0].span.end, 38u);
  EXPECT_EQ(short_read.joints[0].limit, (Vec3{0, 0, 0}));
  EXPECT_EQ(short_read.boxes[1].size, (Vec3{0.05, 0.05, 0.05}));
  EXPECT_EQ(short_read.main.span.begin, 38u);
  EXPECT_EQ(short_read.main.span.end, 48u);
  EXPECT_EQ(short_read.genes_read, 48u);
}

// with wwd.max_boxes = 3, the root's 5 joints stop after two (3 boxes): the main net is read right
// after the second joint and the reading says it was truncated
TEST(WwdGrammar, JointsPastTheBoxLimitAreNotRead) {
  // the root, 5 joints on it, then two all-zero joints of 24 genes each
  Dna dna = {0, 0, 0, 0, 5};
  dna.resize(dna.size() + 2 * 24, 0);
  // where the main net is read: one layer, one node, a constant 5
  const std::size_t main_at = dna.size();
  dna.insert(dna.end(), {0, 525, 0, 999});

  GrammarSettings settings;
  settings.max_boxes = 3;
  const CreatureGenes c = readCreature(dna, settings);
  EXPECT_TRUE(c.truncated);
  EXPECT_EQ(c.boxes.size(), 3u);
  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(c.joints[0].span.begin, 5u);
  EXPECT_EQ(c.joints[0].span.end, 29u);
  EXPECT_EQ(c.joints[1].span.begin, 29u);
  EXPECT_EQ(c.joints[1].span.end, 53u);
  EXPECT_EQ(c.main.span.begin, main_at);
  EXPECT_EQ(c.genes_read, main_at + 4);
  ASSERT_EQ(c.main.layers.size(), 1u);
  ASSERT_EQ(c.main.layers[0].size(), 1u);
  EXPECT_EQ(c.main.layers[0][0].value, weight(999));

  // a box limit of 1: the root alone, its joints unread
  settings.max_boxes = 1;
  const CreatureGenes root = readCreature(dna, settings);
  EXPECT_TRUE(root.truncated);
  EXPECT_EQ(root.boxes.size(), 1u);
  EXPECT_TRUE(root.joints.empty());
  EXPECT_EQ(root.main.span.begin, 5u);

  // the limit at the seed's 15 reads all five joints, the third from the main net's genes on and
  // the rest over zeros
  const CreatureGenes all = readCreature(dna, GrammarSettings{});
  EXPECT_FALSE(all.truncated);
  EXPECT_EQ(all.boxes.size(), 6u);
  EXPECT_EQ(all.joints.size(), 5u);
}

// a deeper limit: joints on a child box are cut too, and the reading goes on at the right gene
TEST(WwdGrammar, TheBoxLimitCutsJointsAtAnyDepth) {
  // root with 1 joint; that joint's box has 2 joints; the limit allows 3 boxes in all
  Dna dna = {0, 0, 0, 0, 1};
  Dna joint(24, 0);
  joint.back() = 2;  // its box's joint count
  dna.insert(dna.end(), joint.begin(), joint.end());
  dna.insert(dna.end(), 24, 0);  // the second box's first joint
  dna.insert(dna.end(), {0, 525, 0, 999});
  GrammarSettings settings;
  settings.max_boxes = 3;
  const CreatureGenes c = readCreature(dna, settings);
  EXPECT_TRUE(c.truncated);
  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(c.joints[0].parent, 0);
  EXPECT_EQ(c.joints[1].parent, 1);
  EXPECT_EQ(c.joints[1].child, 2);
  EXPECT_EQ(c.joints[0].span.end, 53u);  // its subtree: both joints
  EXPECT_EQ(c.main.span.begin, 53u);
  EXPECT_EQ(c.main.layers.at(0).size(), 1u);
  EXPECT_EQ(c.genes_read, dna.size());
}

// random DNA: exactly the genes the grammar reads, the same for the same key
TEST(WwdGrammar, RandomDnaIsExactlyWhatTheGrammarReads) {
  const GrammarSettings settings;
  for (std::uint64_t k = 0; k < 200; ++k) {
    Rng rng(11, RngPurpose::test, 0, k);
    const Dna dna = randomDna(settings, rng);
    ASSERT_FALSE(dna.empty());
    for (Gene g : dna)
      ASSERT_LT(g, kGeneValues);
    const CreatureGenes c = readCreature(dna, settings);
    ASSERT_EQ(c.genes_read, dna.size()) << k;
    ASSERT_LE(static_cast<int>(c.boxes.size()), settings.max_boxes);
    ASSERT_EQ(c.boxes.size(), c.joints.size() + 1);
  }
  Rng a(11, RngPurpose::test, 0, 5), b(11, RngPurpose::test, 0, 5), c(11, RngPurpose::test, 0, 6);
  const Dna first = randomDna(settings, a);
  EXPECT_EQ(first, randomDna(settings, b));
  EXPECT_NE(first, randomDna(settings, c));
}

// the box limit holds for random DNA too, and some random DNAs reach it
TEST(WwdGrammar, RandomDnaKeepsTheBoxLimit) {
  GrammarSettings settings;
  settings.max_boxes = 4;
  int truncated = 0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    Rng rng(12, RngPurpose::test, 0, k);
    const Dna dna = randomDna(settings, rng);
    const CreatureGenes c = readCreature(dna, settings);
    ASSERT_LE(c.boxes.size(), 4u);
    ASSERT_EQ(c.genes_read, dna.size());
    truncated += c.truncated ? 1 : 0;
  }
  EXPECT_GT(truncated, 0);
}

// writeCreature gives each chooser the smallest gene of its case and each number its gene
TEST(WwdGrammar, WritingGivesTheSmallestChooserOfEachCase) {
  const GrammarSettings settings;
  const Dna written = writeCreature(readCreature(kTwoBoxes, settings), settings);
  const Dna expected = {999, 0,   333, 1,                              // the root, its sensor as 1
                        1,                                             // one joint
                        15,  0,   0,   999, 2,   1, 12, 3,   0, 999,   // subnet: 2 layers, layer 0
                        300, 1,   0,   17,  500,                       // layer 1: the sensor node
                        2,   5,   998, 250,                            // E, screw
                        999, 0,   2,   333, 666, 3,                    // PRE, POST
                        999, 0,   333,                                 // DOF
                        0,   999, 0,   0,   0,                         // box 1, no joints
                        0,   525, 3,   19,  1,   2, 3,  999, 0, 999};  // the main net
  EXPECT_EQ(written, expected);
}

// write then read gives the reading back, for random creatures
TEST(WwdGrammar, WritingThenReadingGivesTheCreatureBack) {
  for (const int max_boxes : {15, 4}) {
    GrammarSettings settings;
    settings.max_boxes = max_boxes;
    for (std::uint64_t k = 0; k < 200; ++k) {
      Rng rng(13, RngPurpose::test, static_cast<std::uint64_t>(max_boxes), k);
      Dna dna = randomDna(settings, rng);
      // some cut short, read over zeros
      if (k % 4 == 3)
        dna.resize(dna.size() / 2);
      const CreatureGenes genes = readCreature(dna, settings);
      const Dna written = writeCreature(genes, settings);
      const CreatureGenes again = readCreature(written, settings);
      SCOPED_TRACE("key " + std::to_string(k) + ", max_boxes " + std::to_string(max_boxes));
      expectSameCreature(genes, again);
      EXPECT_EQ(again.genes_read, written.size());
      EXPECT_FALSE(again.truncated);
      // written DNA is written again unchanged
      ASSERT_EQ(writeCreature(again, settings), written);
      if (HasFailure())
        return;
    }
  }
}

// writeCreature refuses what the grammar cannot read
TEST(WwdGrammar, WritingRefusesWhatNoDnaReads) {
  const GrammarSettings settings;
  const CreatureGenes base = readCreature({}, settings);  // one box, the main net

  // boxes 1 and 2 on the root, box 3 on box 1: depth first, box 3 would be read second
  CreatureGenes out_of_order = base;
  out_of_order.boxes.resize(4, base.boxes[0]);
  out_of_order.joints = {aJoint(0, 1), aJoint(0, 2), aJoint(1, 3)};
  EXPECT_THROW(writeCreature(out_of_order, settings), GenomeError);
  // in depth-first order it writes, and reads back
  CreatureGenes in_order = out_of_order;
  in_order.joints = {aJoint(0, 1), aJoint(1, 2), aJoint(0, 3)};
  const CreatureGenes back = readCreature(writeCreature(in_order, settings), settings);
  ASSERT_EQ(back.joints.size(), 3u);
  EXPECT_EQ(back.joints[1].parent, 1);
  EXPECT_EQ(back.joints[2].parent, 0);

  // a joint on a later box, or not making the next box
  CreatureGenes later = out_of_order;
  later.joints = {aJoint(0, 1), aJoint(3, 2), aJoint(0, 3)};
  EXPECT_THROW(writeCreature(later, settings), GenomeError);
  CreatureGenes skipped = out_of_order;
  skipped.joints = {aJoint(0, 1), aJoint(0, 3), aJoint(0, 2)};
  EXPECT_THROW(writeCreature(skipped, settings), GenomeError);

  // a layer of 10 nodes (most probable 5 gives 1..9), or of none
  CreatureGenes wide = base;
  wide.main.layers[0].resize(10);
  try {
    writeCreature(wide, settings);
    FAIL() << "a layer of 10 nodes was written";
  } catch (const GenomeError& e) {
    EXPECT_NE(std::string(e.what()).find("the main net"), std::string::npos) << e.what();
  }
  wide.main.layers[0].resize(9);
  EXPECT_NO_THROW(writeCreature(wide, settings));
  CreatureGenes empty_layer = base;
  empty_layer.main.layers[0].clear();
  EXPECT_THROW(writeCreature(empty_layer, settings), GenomeError);
  // a subnet layer of 6 (most probable 3 gives 1..5)
  CreatureGenes wide_subnet = in_order;
  wide_subnet.joints[1].subnet.layers[0].resize(6);
  try {
    writeCreature(wide_subnet, settings);
    FAIL() << "a subnet layer of 6 nodes was written";
  } catch (const GenomeError& e) {
    EXPECT_NE(std::string(e.what()).find("joint 1"), std::string::npos) << e.what();
  }
  // five layers
  CreatureGenes deep = base;
  deep.main.layers.resize(5, base.main.layers[0]);
  EXPECT_THROW(writeCreature(deep, settings), GenomeError);

  // more boxes than the limit
  GrammarSettings three;
  three.max_boxes = 3;
  CreatureGenes chain = base;
  chain.boxes.resize(3, base.boxes[0]);
  chain.joints = {aJoint(0, 1), aJoint(1, 2)};
  EXPECT_NO_THROW(writeCreature(chain, three));
  chain.boxes.push_back(base.boxes[0]);
  chain.joints.push_back(aJoint(2, 3));
  EXPECT_THROW(writeCreature(chain, three), GenomeError);
  EXPECT_NO_THROW(writeCreature(chain, settings));

  // a box without its joint, or a joint without its box: joint j makes box j + 1
  CreatureGenes loose_box = base;
  loose_box.boxes.resize(3, base.boxes[0]);
  loose_box.joints = {aJoint(0, 1)};
  EXPECT_THROW(writeCreature(loose_box, settings), GenomeError);
  CreatureGenes loose_joint = base;
  loose_joint.boxes.resize(2, base.boxes[0]);
  loose_joint.joints = {aJoint(0, 1), aJoint(1, 2)};
  EXPECT_THROW(writeCreature(loose_joint, settings), GenomeError);
  CreatureGenes no_boxes = base;
  no_boxes.boxes.clear();
  EXPECT_THROW(writeCreature(no_boxes, settings), GenomeError);

  // six joints on one box (the count gene has cases 0..5)
  CreatureGenes star = base;
  star.boxes.resize(7, base.boxes[0]);
  for (int j = 0; j < 6; ++j)
    star.joints.push_back(aJoint(0, j + 1));
  EXPECT_THROW(writeCreature(star, settings), GenomeError);
  star.boxes.pop_back();
  star.joints.pop_back();
  EXPECT_NO_THROW(writeCreature(star, settings));
}

}  // namespace
}  // namespace cambrian::wwd
