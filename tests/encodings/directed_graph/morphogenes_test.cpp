// Tests of Minemonics' morphogenes in the directed-graph genome: capsules and materials, joint
// anchors, flip and mirror copies, segment shrink; their byte and text forms, validation, and
// random genomes and mutation with and without genome.morphogenes.
#include "cambrian/body_plan.hpp"
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/operators.hpp"
#include "encodings/directed_graph/plan_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cambrian::graph {
namespace {

// a revolute box node of `size`
PartGene part(Vec3 size) {
  PartGene node;
  node.dimensions = size;
  node.joint_type = JointType::revolute;
  return node;
}

// a connection from -> to at `position` on the parent
ConnectionGene link(int from, int to, Vec3 position) {
  ConnectionGene c;
  c.from = static_cast<std::uint16_t>(from);
  c.to = static_cast<std::uint16_t>(to);
  c.position = position;
  return c;
}

// a root box with one child through one connection
Genome parentAndChild(PartGene child, ConnectionGene connection) {
  Genome genome;
  genome.nodes = {part({0.6, 0.4, 0.3}), child};
  genome.connections = {connection};
  return genome;
}

void expectNear(Vec3 a, Vec3 b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// a point of `p` in the parent's frame
Vec3 inParent(const PartPlan& parent, Vec3 world) {
  return rotate(conjugate(parent.pose.rotation), world - parent.pose.position);
}

// a genome with every morphogene field away from its default
Genome morphogeneGenome() {
  PartGene body = part({0.6, 0.4, 0.3});
  body.shape = PartShape::capsule;
  body.friction = 0.7;
  body.restitution = 0.25;
  body.segment_shrink = 0.5;
  PartGene leg = part({0.4, 0.1, 0.1});
  leg.anchor = {0.2, -1, 0.1};
  leg.friction = 1.6;
  leg.joint_damping = {0.1, 0.2, 0.3};
  Genome genome;
  genome.nodes = {body, leg, part({0.3, 0.2, 0.2})};
  ConnectionGene hip = link(0, 1, {0.1, 1, 0.2});
  hip.flip = true;
  hip.mirror = true;
  genome.connections = {hip, link(1, 2, {1, 0, 0})};
  return genome;
}

TEST(Morphogenes, ACapsuleHasACapsulesMassAndThePartsMaterial) {
  PartGene child = part({0.5, 0.2, 0.2});
  child.shape = PartShape::capsule;
  child.friction = 0.6;
  child.restitution = 0.3;
  child.density = 900;
  const FlatPlan plan = flatDevelop(parentAndChild(child, link(0, 1, {1, 0, 0})), GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 2u);
  const PartPlan& capsule = plan.parts[1];
  EXPECT_EQ(capsule.shape, PartShape::capsule);
  const double r = 0.1, middle = 0.5 - 2 * r;
  EXPECT_NEAR(capsule.mass, 900 * (kPi * r * r * middle + 4.0 / 3.0 * kPi * r * r * r), 1e-12);
  EXPECT_EQ(capsule.material.friction, 0.6);
  EXPECT_EQ(capsule.material.restitution, 0.3);
  EXPECT_EQ(capsule.material.density, 900);
  EXPECT_EQ(capsule.joint_damping, (Vec3{-1, -1, -1}));  // the world's
  // its tip (the default anchor, -x) touches the centre of the parent's +x face
  const Vec3 tip = apply(capsule.pose, {-0.25, 0, 0});
  expectNear(inParent(plan.parts[0], tip), {0.3, 0, 0});
  // Sims' boxes keep the world's material
  EXPECT_EQ(plan.parts[0].material.friction, 1.0);
  EXPECT_EQ(plan.parts[0].material.restitution, -1.0);
  expectPlanConsistent(plan, GenomeLimits{});
}

TEST(Morphogenes, TheAnchorIsThePointOfTheChildThatMeetsTheParentFacingIt) {
  // the child meets the parent's +y face with its own -y face: turned a quarter turn, it
  // stands on the face with its x axis along the parent's
  PartGene child = part({0.5, 0.2, 0.1});
  child.anchor = {0, -1, 0};
  const FlatPlan plan = flatDevelop(parentAndChild(child, link(0, 1, {1, 0, 0})), GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 2u);
  const PartPlan& c = plan.parts[1];
  expectNear(c.pivot_in_child, {0, -0.1, 0});
  // the anchor's outward normal points back into the parent (-x of the parent)
  expectNear(rotate(c.parent_to_child, {0, -1, 0}), {-1, 0, 0});
  // so the child lies outside the parent, its centre half its height beyond the face
  expectNear(inParent(plan.parts[0], c.pose.position), {0.3 + 0.1, 0, 0});
  // the joint turns about the attachment frame's axes: the twist is along the face normal
  expectNear(rotate(c.parent_to_child, c.axes[2]), {1, 0, 0});
  expectPlanConsistent(plan, GenomeLimits{});

  // a capsule anchored on its side meets the parent with its side
  child.shape = PartShape::capsule;
  child.anchor = {0, 0, 1};
  const FlatPlan side = flatDevelop(parentAndChild(child, link(0, 1, {1, 0, 0})), GenomeLimits{});
  expectNear(side.parts[1].pivot_in_child, {0, 0, 0.1});
  expectNear(inParent(side.parts[0], side.parts[1].pose.position), {0.3 + 0.1, 0, 0});
  expectPlanConsistent(side, GenomeLimits{});
}

TEST(Morphogenes, FlipAddsACopyTurnedAboutTheParentsAxis) {
  ConnectionGene c = link(0, 1, {0.4, 1, 0.5});
  c.flip = true;
  const FlatPlan plan = flatDevelop(parentAndChild(part({0.3, 0.1, 0.1}), c), GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 3u);
  const PartPlan &original = plan.parts[1], &flipped = plan.parts[2];
  EXPECT_FALSE(original.reflected);
  EXPECT_TRUE(flipped.reflected);
  const Vec3 a = inParent(plan.parts[0], original.pose.position);
  const Vec3 b = inParent(plan.parts[0], flipped.pose.position);
  expectNear(b, {a.x, -a.y, -a.z});
  expectNear(flipped.pivot_in_parent, {0.12, -0.2, -0.075});
  // a rotation, not a mirror image: every axis turned the same half turn, joint axes too
  for (const Vec3 axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    const Vec3 u = rotate(original.parent_to_child, axis);
    expectNear(rotate(flipped.parent_to_child, axis), {u.x, -u.y, -u.z});
  }
  for (int d = 0; d < 3; ++d) {
    const Vec3 u = rotate(original.parent_to_child, original.axes[d]);
    expectNear(rotate(flipped.parent_to_child, flipped.axes[d]), {u.x, -u.y, -u.z});
  }
  expectPlanConsistent(plan, GenomeLimits{});

  // on the parent's x axis a half turn about it would put the copy inside the first
  const FlatPlan on_axis = flatDevelop(parentAndChild(part({0.3, 0.1, 0.1}),
                                                      [] {
                                                        ConnectionGene end = link(0, 1, {1, 0, 0});
                                                        end.flip = true;
                                                        return end;
                                                      }()),
                                       GenomeLimits{});
  EXPECT_EQ(on_axis.parts.size(), 2u);
}

TEST(Morphogenes, MirrorAddsTheMirrorImageThroughTheParentsCentre) {
  // an anchor on the leg's own -x face, and one on its -y face (the leg turned to face the body)
  for (const Vec3 anchor : {Vec3{-1, 0.3, 0}, Vec3{0.3, -1, 0.2}}) {
    PartGene leg = part({0.3, 0.1, 0.15});
    leg.anchor = anchor;
    ConnectionGene c = link(0, 1, {0.4, 1, 0.5});
    c.mirror = true;
    c.orientation = {0.3, -0.2, 0.5};
    const FlatPlan plan = flatDevelop(parentAndChild(leg, c), GenomeLimits{});
    ASSERT_EQ(plan.parts.size(), 3u);
    const PartPlan &original = plan.parts[1], &image = plan.parts[2];
    EXPECT_TRUE(image.reflected);
    expectNear(inParent(plan.parts[0], image.pose.position),
               inParent(plan.parts[0], original.pose.position) * -1.0);
    // every point of the copy is the mirror image of one of the original: corners map to corners
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 local{(corner & 1 ? 0.15 : -0.15), (corner & 2 ? 0.05 : -0.05),
                       (corner & 4 ? 0.075 : -0.075)};
      const Vec3 p = inParent(plan.parts[0], apply(original.pose, local)) * -1.0;
      bool found = false;
      for (int other = 0; other < 8; ++other) {
        const Vec3 q{(other & 1 ? 0.15 : -0.15), (other & 2 ? 0.05 : -0.05),
                     (other & 4 ? 0.075 : -0.075)};
        found = found || norm(inParent(plan.parts[0], apply(image.pose, q)) - p) < 1e-12;
      }
      EXPECT_TRUE(found) << "corner " << corner;
    }
    // the same command turns the copy the mirrored way (joint axes are pseudovectors)
    for (int d = 0; d < 3; ++d) {
      const Vec3 a = rotate(original.parent_to_child, original.axes[d]);
      expectNear(rotate(image.parent_to_child, image.axes[d]), a);
    }
    expectPlanConsistent(plan, GenomeLimits{});
  }
}

TEST(Morphogenes, SegmentShrinkScalesEveryPartBranchedFromThePart) {
  Genome genome;
  PartGene body = part({0.6, 0.4, 0.4});
  body.segment_shrink = 0.5;
  PartGene limb = part({0.4, 0.4, 0.4});
  limb.recursive_limit = 3;
  limb.segment_shrink = 0.8;
  genome.nodes = {body, limb};
  genome.connections = {link(0, 1, {1, 0, 0}), link(1, 1, {1, 0, 0})};
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 4u);
  EXPECT_NEAR(plan.parts[0].size.x, 0.6, 1e-15);
  EXPECT_NEAR(plan.parts[1].size.x, 0.4 * 0.5, 1e-15);
  EXPECT_NEAR(plan.parts[2].size.x, 0.4 * 0.5 * 0.8, 1e-15);
  EXPECT_NEAR(plan.parts[3].size.x, 0.4 * 0.5 * 0.8 * 0.8, 1e-15);
}

TEST(Morphogenes, FieldsSurviveTheByteAndTextForms) {
  const Genome genome = morphogeneGenome();
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  EXPECT_EQ(plan.parts[1].joint_damping, (Vec3{0.1, 0.2, 0.3}));
  ASSERT_TRUE(hasMorphogeneFields(genome));
  const std::vector<std::uint8_t> bytes = serializeGenome(genome);
  EXPECT_EQ(bytes[4], 4);  // the version that carries them
  EXPECT_EQ(deserializeGenome(bytes.data(), bytes.size()), genome);
  const std::string text = genomeToText(genome);
  for (const char* word : {"shape capsule", "friction 0.7", "restitution 0.25", "anchor 0.2 -1 0.1",
                           "shrink 0.5", "damping 0.1 0.2 0.3", "flip", "mirror"}) {
    EXPECT_NE(text.find(word), std::string::npos) << word << " in\n" << text;
  }
  EXPECT_EQ(parseGenomeText(text), genome);

  // a genome without them keeps the oldest bytes and its text
  Genome sims = genome;
  for (PartGene& node : sims.nodes) {
    const PartGene defaults;
    node.shape = defaults.shape;
    node.friction = defaults.friction;
    node.restitution = defaults.restitution;
    node.anchor = defaults.anchor;
    node.segment_shrink = defaults.segment_shrink;
    node.joint_damping = defaults.joint_damping;
  }
  sims.connections[0].flip = sims.connections[0].mirror = false;
  EXPECT_FALSE(hasMorphogeneFields(sims));
  EXPECT_EQ(serializeGenome(sims)[4], 1);
  EXPECT_EQ(genomeToText(sims).find("friction"), std::string::npos);

  // every truncation of the version-4 bytes is refused
  for (std::size_t size = 0; size < bytes.size(); ++size)
    EXPECT_THROW(deserializeGenome(bytes.data(), size), InputError) << size;
}

TEST(Morphogenes, ValidationNamesTheFieldAndItsSetting) {
  const GenomeLimits limits;
  auto message = [&limits](Genome genome) {
    try {
      validateGenome(genome, limits);
    } catch (const GenomeError& e) {
      return std::string(e.what());
    }
    return std::string("valid");
  };
  EXPECT_EQ(message(morphogeneGenome()), "valid");
  Genome g = morphogeneGenome();
  g.nodes[1].friction = 5;
  EXPECT_EQ(message(g), "node 1: friction = 5 is above genome.max_friction 2");
  g = morphogeneGenome();
  g.nodes[0].restitution = 1.5;
  EXPECT_EQ(message(g), "node 0: restitution = 1.5 is above genome.max_restitution 1");
  g = morphogeneGenome();
  g.nodes[2].anchor.z = -2;
  EXPECT_EQ(message(g), "node 2: anchor.z = -2 is below the minimum -1");
  g = morphogeneGenome();
  g.nodes[0].segment_shrink = 0.1;
  EXPECT_EQ(message(g), "node 0: segment_shrink = 0.1 is below genome.min_shrink 0.34");
  g = morphogeneGenome();
  g.nodes[1].joint_damping.y = 0.9;
  EXPECT_EQ(message(g), "node 1: joint_damping.y = 0.9 is above genome.max_joint_damping 0.5");
  g = morphogeneGenome();
  g.nodes[0].shape = PartShape::sphere;
  EXPECT_NE(message(g).find("node 0: shape"), std::string::npos) << message(g);
}

TEST(Morphogenes, RandomGenomesDrawThemOnlyWhenAskedAndStayValid) {
  GenomeLimits sims;
  GenomeLimits minemonics;
  minemonics.morphogenes = true;
  int capsules = 0, flips = 0, mirrors = 0, anchored = 0, shrunk = 0, damped = 0, genomes_with = 0;
  for (std::uint64_t individual = 0; individual < 300; ++individual) {
    const Genome plain = randomGenome(sims, 7, 0, individual);
    EXPECT_FALSE(hasMorphogeneFields(plain)) << individual;
    const Genome genome = randomGenome(minemonics, 7, 0, individual);
    ASSERT_NO_THROW(validateGenome(genome, minemonics)) << individual;
    genomes_with += hasMorphogeneFields(genome);
    for (const PartGene& node : genome.nodes) {
      capsules += node.shape == PartShape::capsule;
      anchored += node.anchor != PartGene{}.anchor;
      shrunk += node.segment_shrink != 1;
      damped += node.joint_damping.x >= minemonics.min_joint_damping;
      EXPECT_GE(node.friction, minemonics.min_friction);
      EXPECT_LE(node.friction, minemonics.max_friction);
    }
    for (const ConnectionGene& c : genome.connections) {
      flips += c.flip;
      mirrors += c.mirror;
    }
    const FlatPlan plan = flatDevelop(genome, minemonics);
    expectPlanConsistent(plan, minemonics);
  }
  EXPECT_EQ(genomes_with, 300);
  EXPECT_GT(capsules, 100);
  EXPECT_GT(flips, 50);
  EXPECT_GT(mirrors, 50);
  EXPECT_GT(anchored, 200);
  EXPECT_GT(shrunk, 200);
  EXPECT_EQ(damped, shrunk);
}

TEST(Morphogenes, MutationChangesThemOnlyWhenAskedAndKeepsThemInRange) {
  GenomeLimits minemonics;
  minemonics.morphogenes = true;
  MutationSettings settings;
  settings.parameter_rate = 0.5;
  const Genome start = morphogeneGenome();
  int changed = 0;
  for (std::uint64_t i = 0; i < 50; ++i) {
    Rng rng(11, RngPurpose::test, i, 0);
    const Genome genome = mutate(start, minemonics, settings, rng);
    ASSERT_NO_THROW(validateGenome(genome, minemonics)) << i;
    for (std::size_t n = 0; n < std::min(genome.nodes.size(), start.nodes.size()); ++n) {
      changed += genome.nodes[n].friction != start.nodes[n].friction ||
                 genome.nodes[n].anchor != start.nodes[n].anchor ||
                 genome.nodes[n].segment_shrink != start.nodes[n].segment_shrink;
    }
    // without genome.morphogenes a Sims genome never gains one
    Rng plain_rng(11, RngPurpose::test, i, 0);
    const Genome plain =
        mutate(randomGenome(GenomeLimits{}, 3, 0, i), GenomeLimits{}, settings, plain_rng);
    EXPECT_FALSE(hasMorphogeneFields(plain)) << i;
  }
  EXPECT_GT(changed, 25);
}

}  // namespace
}  // namespace cambrian::graph
