// Walking with Dinosaurs' operators on the DNA: mutation drawing each gene anew with chance 1/n,
// the half turn, and the Mtree crossover of joints (their screw turned half) and nets.
#include "encodings/wwd/operators.hpp"

#include "cambrian/rng.hpp"

#include "brain/layered_network.hpp"
#include "encodings/wwd/develop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace cambrian::wwd {
namespace {

// two boxes (as in grammar_test.cpp): the root [0, 5), joint 0 [5, 38) with its subnet [5, 20)
// and its screw gene at 23, the main net [38, 48)
const Dna kTwoBoxes = {999, 0, 333, 7,   7, 215, 0,   4,   999, 6,  21, 12,  3,   0,   999, 300,
                       1,   0, 17,  500, 2, 5,   998, 250, 999, 0,  8,  333, 666, 3,   999, 0,
                       333, 0, 999, 0,   2, 6,   114, 525, 3,   39, 1,  2,   3,   999, 0,   999};

// genes that differ between two DNAs of one length
int changed(const Dna& a, const Dna& b) {
  int count = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    count += a[i] != b[i] ? 1 : 0;
  return count;
}

// a DNA of `n` genes drawn with `rng`
Dna randomGenes(std::size_t n, Rng& rng) {
  Dna dna(n);
  for (Gene& g : dna)
    g = static_cast<Gene>(rng.below(kGeneValues));
  return dna;
}

// what crossDna must have made of `receiver` and `donor` for `point`: the receiver up to the
// replaced span (zeros where that starts past its end), the donor's span (zeros past its end,
// the screw gene of a joint turned half), the receiver after the span
Dna expectedChild(const Dna& receiver, const Dna& donor, const CrossoverPoint& point,
                  const GrammarSettings& settings) {
  if (point.kind == CrossoverPoint::Kind::none)
    return receiver;
  Dna child;
  for (std::size_t i = 0; i < point.receiver.begin; ++i)
    child.push_back(i < receiver.size() ? receiver[i] : 0);
  std::size_t screw = point.donor.end;  // none
  if (point.kind == CrossoverPoint::Kind::joint) {
    for (const JointGenes& joint : readCreature(donor, settings).joints) {
      if (joint.span.begin == point.donor.begin && joint.span.end == point.donor.end)
        screw = joint.screw_gene;
    }
    EXPECT_NE(screw, point.donor.end) << "no joint of the donor has the span copied";
  }
  for (std::size_t i = point.donor.begin; i < point.donor.end; ++i) {
    const Gene g = i < donor.size() ? donor[i] : 0;
    child.push_back(i == screw ? halfTurn(g) : g);
  }
  for (std::size_t i = point.receiver.end; i < receiver.size(); ++i)
    child.push_back(receiver[i]);
  return child;
}

// whether `span` is one of `genes`' points of kind `kind`: a joint's span, a subnet's, the main
// net's
bool isPoint(const CreatureGenes& genes, CrossoverPoint::Kind kind, GeneSpan span) {
  using Kind = CrossoverPoint::Kind;
  const auto same = [span](GeneSpan s) { return s.begin == span.begin && s.end == span.end; };
  for (const JointGenes& joint : genes.joints) {
    if ((kind == Kind::joint && same(joint.span)) ||
        (kind == Kind::subnet && same(joint.subnet.span)))
      return true;
  }
  return kind == Kind::main_net && same(genes.main.span);
}

// the child develops into a body whose layered network builds
void expectDevelops(const Dna& dna, const GrammarSettings& settings) {
  const Creature creature = developCreature(readCreature(dna, settings), BodySettings{});
  const auto network = std::dynamic_pointer_cast<const LayeredNetworkPlan>(creature.controller);
  ASSERT_TRUE(network);
  EXPECT_NO_THROW(
      network->build(0.01, creature.body.sensors.size(), creature.body.effectors.size()));
}

TEST(WwdOperators, HalfTurnAddsHalfTheGeneValues) {
  EXPECT_EQ(halfTurn(0), 500);
  EXPECT_EQ(halfTurn(250), 750);
  EXPECT_EQ(halfTurn(499), 999);
  EXPECT_EQ(halfTurn(500), 0);
  EXPECT_EQ(halfTurn(700), 200);
  EXPECT_EQ(halfTurn(999), 499);
  for (int g = 0; g < kGeneValues; ++g)
    ASSERT_EQ(halfTurn(halfTurn(static_cast<Gene>(g))), g);
}

// rate 0 is the seed's 1 / n: about one gene of 200 drawn anew per mutation, 999 / 1000 of
// those to another value: 0.999 changed on average (the mean of 2000 has a deviation of 0.022)
TEST(WwdOperators, MutationAtRateZeroDrawsOneGeneInN) {
  Rng genes(1, RngPurpose::test);
  const Dna dna = randomGenes(200, genes);
  Rng rng(2, RngPurpose::test);
  long total = 0;
  int unchanged = 0;
  for (int t = 0; t < 2000; ++t) {
    const Dna child = mutateDna(dna, 0, rng);
    ASSERT_EQ(child.size(), dna.size());
    for (Gene g : child)
      ASSERT_LT(g, kGeneValues);
    const int n = changed(dna, child);
    total += n;
    unchanged += n == 0 ? 1 : 0;
  }
  const double mean = static_cast<double>(total) / 2000;
  EXPECT_GT(mean, 0.9);
  EXPECT_LT(mean, 1.1);
  // no change at all about (1 - 1/200)^200 = 36.7% of the time
  EXPECT_GT(unchanged, 2000 * 0.30);
  EXPECT_LT(unchanged, 2000 * 0.43);
  // a negative rate is the seed's too
  long negative = 0;
  for (int t = 0; t < 2000; ++t)
    negative += changed(dna, mutateDna(dna, -1, rng));
  EXPECT_GT(negative, 1800);
  EXPECT_LT(negative, 2200);
}

// rate 1 draws every gene anew: 999 / 1000 of them change (20 of 20000 expected unchanged);
// rate 0.25 a quarter of them
TEST(WwdOperators, MutationAtARateDrawsThatShareOfGenes) {
  Rng genes(3, RngPurpose::test);
  const Dna dna = randomGenes(200, genes);
  Rng rng(4, RngPurpose::test);
  int kept = 0;
  for (int t = 0; t < 100; ++t) {
    const Dna child = mutateDna(dna, 1, rng);
    for (Gene g : child)
      ASSERT_LT(g, kGeneValues);
    kept += 200 - changed(dna, child);
  }
  EXPECT_GE(kept, 5);
  EXPECT_LE(kept, 40);
  long quarter = 0;
  for (int t = 0; t < 100; ++t)
    quarter += changed(dna, mutateDna(dna, 0.25, rng));
  // 20000 x 0.25 x 0.999 = 4995, deviation 61
  EXPECT_GT(quarter, 4700);
  EXPECT_LT(quarter, 5300);
}

TEST(WwdOperators, MutationLeavesAnEmptyDnaEmpty) {
  Rng rng(5, RngPurpose::test);
  EXPECT_TRUE(mutateDna({}, 0, rng).empty());
  EXPECT_TRUE(mutateDna({}, 1, rng).empty());
  // and a lone gene at rate 0 (1 / 1: always drawn) stays a gene
  for (int t = 0; t < 100; ++t) {
    const Dna child = mutateDna({999}, 0, rng);
    ASSERT_EQ(child.size(), 1u);
    ASSERT_LT(child[0], kGeneValues);
  }
}

// kTwoBoxes crossed with itself: its one joint (a third of the points) is put back on itself
// turned half, the screw gene 250 now 750; a net put on itself changes nothing
TEST(WwdOperators, AJointCrossedOntoItselfIsTurnedHalf) {
  const GrammarSettings settings;
  bool joint = false, net = false;
  for (std::uint64_t k = 0; k < 30; ++k) {
    Rng rng(6, RngPurpose::test, 0, k);
    CrossoverPoint point;
    const Dna child = crossDna(kTwoBoxes, kTwoBoxes, settings, rng, &point);
    if (point.kind == CrossoverPoint::Kind::joint) {
      joint = true;
      EXPECT_EQ(point.receiver.begin, 5u);
      EXPECT_EQ(point.receiver.end, 38u);
      EXPECT_EQ(point.donor.begin, 5u);
      EXPECT_EQ(point.donor.end, 38u);
      Dna expected = kTwoBoxes;
      expected[23] = 750;
      EXPECT_EQ(child, expected);
      const CreatureGenes genes = readCreature(child, settings);
      EXPECT_NEAR(genes.joints.at(0).screw, 1.5 * kPi, 1e-12);
    } else {
      // its one subnet and its main net each have only themselves to meet
      ASSERT_TRUE(point.kind == CrossoverPoint::Kind::subnet ||
                  point.kind == CrossoverPoint::Kind::main_net);
      net = true;
      EXPECT_EQ(point.receiver.begin, point.donor.begin);
      EXPECT_EQ(child, kTwoBoxes);
    }
  }
  EXPECT_TRUE(joint);
  EXPECT_TRUE(net);
}

// random parents: the child is the receiver before and after the replaced span and the donor's
// span between, a joint's screw gene turned half, a net's genes as they were; the child reads
// and develops into a body whose network builds
TEST(WwdOperators, CrossoverPutsOneMtreePointOfTheDonorInTheReceiver) {
  const GrammarSettings settings;
  int joints = 0, nets = 0;
  for (std::uint64_t k = 0; k < 300; ++k) {
    Rng parents(7, RngPurpose::test, 0, k);
    Dna receiver = randomDna(settings, parents);
    Dna donor = randomDna(settings, parents);
    // some parents cut short: their points may lie past their ends
    if (k % 5 == 1)
      receiver.resize(receiver.size() / 3);
    if (k % 5 == 2)
      donor.resize(donor.size() / 3);
    Rng rng(8, RngPurpose::test, 0, k);
    CrossoverPoint point;
    const Dna child = crossDna(receiver, donor, settings, rng, &point);
    SCOPED_TRACE("parents " + std::to_string(k));
    const CreatureGenes to = readCreature(receiver, settings);
    const CreatureGenes from = readCreature(donor, settings);
    if (point.kind == CrossoverPoint::Kind::none) {
      EXPECT_TRUE(from.joints.empty());
      EXPECT_EQ(child, receiver);
      continue;
    }
    joints += point.kind == CrossoverPoint::Kind::joint ? 1 : 0;
    const bool a_net =
        point.kind == CrossoverPoint::Kind::subnet || point.kind == CrossoverPoint::Kind::main_net;
    nets += a_net ? 1 : 0;
    EXPECT_TRUE(isPoint(to, point.kind, point.receiver));
    EXPECT_TRUE(isPoint(from, point.kind, point.donor));
    ASSERT_EQ(child, expectedChild(receiver, donor, point, settings));
    for (Gene g : child)
      ASSERT_LT(g, kGeneValues);
    const CreatureGenes genes = readCreature(child, settings);
    // a net put in place of a net of its own role is read as the donor read it, and the rest in
    // step: the receiver's body, box for box
    if (a_net) {
      ASSERT_EQ(genes.boxes.size(), to.boxes.size());
      for (std::size_t b = 0; b < to.boxes.size(); ++b)
        EXPECT_EQ(genes.boxes[b].size, to.boxes[b].size);
    }
    if (point.kind == CrossoverPoint::Kind::joint) {
      // the child's joint there is the donor's, turned half about its normal
      std::size_t index = 0;
      while (index < to.joints.size() && to.joints[index].span.begin != point.receiver.begin)
        ++index;
      ASSERT_LT(index, to.joints.size());
      const JointGenes* copied = nullptr;
      for (const JointGenes& j : from.joints) {
        if (j.span.begin == point.donor.begin)
          copied = &j;
      }
      ASSERT_NE(copied, nullptr);
      ASSERT_LT(index, genes.joints.size());
      const JointGenes& turned = genes.joints[index];
      EXPECT_EQ(turned.span.begin, point.receiver.begin);
      EXPECT_EQ(turned.screw_gene, point.receiver.begin + copied->screw_gene - point.donor.begin);
      EXPECT_NEAR(turned.screw, std::fmod(copied->screw + kPi, 2 * kPi), 1e-12);
      EXPECT_EQ(turned.effector, copied->effector);
      EXPECT_EQ(turned.limit, copied->limit);
      EXPECT_EQ(turned.pre.side, copied->pre.side);
      EXPECT_EQ(turned.post.side, copied->post.side);
    }
    expectDevelops(child, settings);
    if (HasFailure())
      return;
  }
  EXPECT_GT(joints, 30);
  EXPECT_GT(nets, 30);
}

// the same draws give the same child
TEST(WwdOperators, CrossoverIsAFunctionOfItsDraws) {
  const GrammarSettings settings;
  Rng parents(9, RngPurpose::test);
  const Dna receiver = randomDna(settings, parents);
  const Dna donor = randomDna(settings, parents);
  Rng a(10, RngPurpose::test), b(10, RngPurpose::test);
  for (int t = 0; t < 20; ++t)
    ASSERT_EQ(crossDna(receiver, donor, settings, a), crossDna(receiver, donor, settings, b));
}

// a donor without joints has no joint and no subnet: when the receiver's joint or subnet is picked
// the child is the receiver; its main net (all zeros read past its empty end, 10 genes) may still
// replace the receiver's, copied as explicit zeros
TEST(WwdOperators, ADonorWithoutJointsGivesTheReceiverBackForAJoint) {
  const GrammarSettings settings;
  const Dna donor;  // one box, no joints, the main net [5, 15) all zeros
  bool none = false, net = false;
  for (std::uint64_t k = 0; k < 40; ++k) {
    Rng rng(11, RngPurpose::test, 0, k);
    CrossoverPoint point;
    point.kind = CrossoverPoint::Kind::joint;  // to see it overwritten
    const Dna child = crossDna(kTwoBoxes, donor, settings, rng, &point);
    if (point.kind == CrossoverPoint::Kind::none) {
      none = true;
      EXPECT_EQ(child, kTwoBoxes);
      EXPECT_EQ(point.receiver.size(), 0u);
      EXPECT_EQ(point.donor.size(), 0u);
      continue;
    }
    ASSERT_EQ(point.kind, CrossoverPoint::Kind::main_net);
    net = true;
    EXPECT_EQ(point.receiver.begin, 38u);
    EXPECT_EQ(point.donor.begin, 5u);
    EXPECT_EQ(point.donor.end, 15u);
    Dna expected(kTwoBoxes.begin(),
                 kTwoBoxes.begin() + static_cast<std::ptrdiff_t>(point.receiver.begin));
    expected.resize(expected.size() + 10, 0);
    expected.insert(expected.end(),
                    kTwoBoxes.begin() + static_cast<std::ptrdiff_t>(point.receiver.end),
                    kTwoBoxes.end());
    EXPECT_EQ(child, expected);
    // the main net replaced: 38 genes kept and 10 zeros
    if (point.receiver.begin == 38) {
      EXPECT_EQ(child.size(), 48u);
    }
  }
  EXPECT_TRUE(none);
  EXPECT_TRUE(net);
}

// a donor cut short inside its joint: the joint copied is its genes up to the cut and then the
// zeros read there (DOF, box and count: 8 genes), written out
TEST(WwdOperators, DonorGenesPastItsEndAreCopiedAsZeros) {
  const GrammarSettings settings;
  const Dna donor(kTwoBoxes.begin(), kTwoBoxes.begin() + 30);
  bool joint = false;
  for (std::uint64_t k = 0; k < 30 && !joint; ++k) {
    Rng rng(12, RngPurpose::test, 0, k);
    CrossoverPoint point;
    const Dna child = crossDna(kTwoBoxes, donor, settings, rng, &point);
    if (point.kind != CrossoverPoint::Kind::joint)
      continue;
    joint = true;
    EXPECT_EQ(point.donor.begin, 5u);
    EXPECT_EQ(point.donor.end, 38u);
    Dna expected = kTwoBoxes;
    expected[23] = 750;
    for (std::size_t i = 30; i < 38; ++i)
      expected[i] = 0;
    EXPECT_EQ(child, expected);
    EXPECT_EQ(child.size(), 48u);
    // and it reads as the joint the donor read
    const CreatureGenes genes = readCreature(child, settings);
    EXPECT_EQ(genes.joints.at(0).limit, (Vec3{0, 0, 0}));
    EXPECT_EQ(genes.boxes.at(1).size, (Vec3{0.05, 0.05, 0.05}));
    EXPECT_EQ(genes.main.span.begin, 38u);
    EXPECT_EQ(genes.main.layers.at(0).size(), 1u);  // the receiver's main net
  }
  EXPECT_TRUE(joint);
}

// a receiver cut short: a point past its end is reached through explicit zeros
TEST(WwdOperators, AReceiverCutShortIsPaddedWithZerosUpToThePoint) {
  const GrammarSettings settings;
  const Dna receiver(kTwoBoxes.begin(), kTwoBoxes.begin() + 30);  // main net read at [38, 48)
  bool main = false;
  for (std::uint64_t k = 0; k < 60 && !main; ++k) {
    Rng rng(13, RngPurpose::test, 0, k);
    CrossoverPoint point;
    const Dna child = crossDna(receiver, kTwoBoxes, settings, rng, &point);
    if (point.kind != CrossoverPoint::Kind::main_net)
      continue;
    main = true;
    Dna expected = receiver;
    expected.resize(38, 0);
    expected.insert(expected.end(), kTwoBoxes.begin() + 38, kTwoBoxes.end());
    EXPECT_EQ(child, expected);
    EXPECT_EQ(readCreature(child, settings).main.layers.at(0).at(0).function, LayeredFunction::saw);
  }
  EXPECT_TRUE(main);
}

}  // namespace
}  // namespace cambrian::wwd
