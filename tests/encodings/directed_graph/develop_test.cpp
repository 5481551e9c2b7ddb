// Tests of develop(): hand-built genomes develop to the expected parts, joints, sensors, neurons
// and effectors; reflection, recursion, terminal-only connections, truncation and clamping.
#include "cambrian/body_plan.hpp"
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/plan_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace cambrian::graph {
namespace {

constexpr double kTol = 1e-12;

// a box node with the given size, joint and recursive limit
PartGene box(Vec3 dimensions, JointType joint = JointType::revolute, int recursive_limit = 1) {
  PartGene node;
  node.dimensions = dimensions;
  node.joint_type = joint;
  node.recursive_limit = static_cast<std::uint8_t>(recursive_limit);
  return node;
}

// a connection from -> to at `position`
ConnectionGene link(int from, int to, Vec3 position, Vec3 orientation = {}, int reflection = 0) {
  ConnectionGene connection;
  connection.from = static_cast<std::uint16_t>(from);
  connection.to = static_cast<std::uint16_t>(to);
  connection.position = position;
  connection.orientation = orientation;
  connection.reflection = static_cast<std::uint8_t>(reflection);
  return connection;
}

// a weighted input
NeuronInput in(SignalSource source, int index, double weight = 1, int slot = 0) {
  NeuronInput input;
  input.source = source;
  input.index = static_cast<std::uint16_t>(index);
  input.slot = static_cast<std::uint16_t>(slot);
  input.weight = weight;
  return input;
}

// a neuron gene
NeuronGene neuron(NeuronFunction function, std::vector<NeuronInput> inputs, double parameter = 0) {
  NeuronGene gene;
  gene.function = function;
  gene.inputs.assign(inputs.begin(), inputs.end());
  gene.parameter = parameter;
  return gene;
}

void expectNear(Vec3 a, Vec3 b, double tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// v mirrored across the planes in `mirror` (bit k: plane k = 0)
Vec3 mirrored(Vec3 v, int mirror) {
  for (int k = 0; k < 3; ++k) {
    if ((mirror >> k) & 1) {
      v[k] = -v[k];
    }
  }
  return v;
}

TEST(Develop, SingleBlockIsOneRootPartWithContactAndPhotoSensors) {
  Genome genome;
  genome.nodes.push_back(box({0.4, 0.3, 0.2}));
  genome.nodes[0].density = 500;
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});

  ASSERT_EQ(plan.parts.size(), 1u);
  EXPECT_EQ(plan.jointCount(), 0);
  EXPECT_FALSE(plan.truncated);
  const PartPlan& root = plan.parts[0];
  EXPECT_EQ(root.parent, -1);
  EXPECT_EQ(root.connection, -1);
  EXPECT_EQ(root.joint, JointType::fixed);
  EXPECT_EQ(root.size, (Vec3{0.4, 0.3, 0.2}));
  EXPECT_NEAR(root.mass, 500 * 0.4 * 0.3 * 0.2, kTol);
  EXPECT_EQ(root.pose.position, (Vec3{0, 0, 0}));
  EXPECT_EQ(root.pose.rotation, (Quat{1, 0, 0, 0}));

  ASSERT_EQ(plan.sensors.size(), 4u);
  EXPECT_EQ(plan.sensors[0].kind, SensorKind::contact);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(plan.sensors[1 + axis].kind, SensorKind::photo);
    EXPECT_EQ(plan.sensors[1 + axis].part, 0);
    EXPECT_EQ(plan.sensors[1 + axis].axis, axis);
  }
  EXPECT_TRUE(plan.neurons.empty());
  EXPECT_TRUE(plan.effectors.empty());
}

TEST(Develop, ChildAttachesOutwardOnThePositiveXFace) {
  Genome genome;
  genome.nodes.push_back(box({1.0, 0.5, 0.5}));
  genome.nodes.push_back(box({0.4, 0.2, 0.3}, JointType::revolute));
  genome.nodes[1].joint_limit = {0.5, 0.6, 0.7};
  genome.connections.push_back(link(0, 1, {1, 0, 0}));
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});

  ASSERT_EQ(plan.parts.size(), 2u);
  const PartPlan& child = plan.parts[1];
  EXPECT_EQ(child.node, 1);
  EXPECT_EQ(child.parent, 0);
  EXPECT_EQ(child.connection, 0);
  EXPECT_EQ(child.depth, 1);
  EXPECT_EQ(child.joint, JointType::revolute);
  EXPECT_EQ(child.joint_limit, (Vec3{0.5, 0.6, 0.7}));
  expectNear(child.pivot_in_parent, {0.5, 0, 0});
  expectNear(child.pivot_in_child, {-0.2, 0, 0});
  expectNear(child.pose.position, {0.7, 0, 0});
  EXPECT_NEAR(child.cross_section, 0.2 * 0.3, kTol);
  EXPECT_FALSE(child.reflected);
  // joint axes: dof 0 about y, dof 1 about z, dof 2 twist about x
  expectNear(child.axes[0], {0, 1, 0});
  expectNear(child.axes[1], {0, 0, 1});
  expectNear(child.axes[2], {1, 0, 0});

  // sensors: root contact, child joint angle and contact, three photo sensors
  ASSERT_EQ(plan.sensors.size(), 6u);
  EXPECT_EQ(plan.sensors[0].kind, SensorKind::contact);
  EXPECT_EQ(plan.sensors[1].kind, SensorKind::joint_angle);
  EXPECT_EQ(plan.sensors[1].part, 1);
  EXPECT_EQ(plan.sensors[1].axis, 0);
  EXPECT_EQ(plan.sensors[2].kind, SensorKind::contact);
  EXPECT_EQ(plan.sensors[2].part, 1);
  EXPECT_EQ(plan.sensors[3].kind, SensorKind::photo);
  expectPlanConsistent(plan, GenomeLimits{});
}

TEST(Develop, AttachmentIsProjectedOnTheDominantFace) {
  Genome genome;
  genome.nodes.push_back(box({1.0, 0.5, 0.4}));
  genome.nodes.push_back(box({0.2, 0.1, 0.1}));
  genome.connections.push_back(link(0, 1, {0.2, -0.7, 0.3}));
  genome.connections.push_back(link(0, 1, {0.5, 0.5, 0.5}));  // tie: lowest axis (x) wins
  genome.connections.push_back(link(0, 1, {0, 0, 0}));        // no direction: +x
  genome.connections.push_back(link(0, 1, {0.1, 0.2, 0.9}));
  genome.connections.push_back(link(0, 1, {-0.9, 0.2, 0.1}));
  // each child is on its own path, so node 1's recursive limit of 1 allows all five
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 6u);

  // -y face: pivot on the face, the child extends along -y
  const PartPlan& a = plan.parts[1];
  expectNear(a.pivot_in_parent, {0.2 * 0.5, -0.25, 0.3 * 0.2});
  expectNear(a.pose.position, Vec3{0.1, -0.25, 0.06} + Vec3{0, -0.1, 0});
  expectNear(rotate(a.pose.rotation, {1, 0, 0}), {0, -1, 0});
  EXPECT_NEAR(a.cross_section, std::min(1.0 * 0.4, 0.1 * 0.1), kTol);
  expectNear(plan.parts[2].pivot_in_parent, {0.5, 0.125, 0.1});
  expectNear(plan.parts[3].pivot_in_parent, {0.5, 0, 0});
  // +z face
  expectNear(plan.parts[4].pivot_in_parent, {0.05, 0.05, 0.2});
  expectNear(rotate(plan.parts[4].pose.rotation, {1, 0, 0}), {0, 0, 1});
  expectNear(plan.parts[4].pose.position, {0.05, 0.05, 0.3});
  // -x face
  expectNear(plan.parts[5].pivot_in_parent, {-0.5, 0.05, 0.02});
  expectNear(rotate(plan.parts[5].pose.rotation, {1, 0, 0}), {-1, 0, 0});
  expectPlanConsistent(plan, GenomeLimits{});
}

TEST(Develop, OrientationRotatesTheChildAfterTheFaceFrame) {
  Genome genome;
  genome.nodes.push_back(box({1.0, 1.0, 1.0}));
  genome.nodes.push_back(box({0.4, 0.2, 0.2}));
  const Vec3 euler{0.1, -0.4, 0.3};
  genome.connections.push_back(link(0, 1, {0.1, 1, 0}, euler));
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 2u);
  const double h = std::sqrt(0.5);
  const Quat expected = Quat{h, 0, 0, h} * quatFromEuler(euler);
  const Quat got = plan.parts[1].parent_to_child;
  // same rotation (quaternions up to sign)
  const double d =
      std::fabs(got.w * expected.w + got.x * expected.x + got.y * expected.y + got.z * expected.z);
  EXPECT_NEAR(d, 1.0, 1e-12);
  expectPlanConsistent(plan, GenomeLimits{});
}

// body with a leg at (0.6, 1, 0) mirrored across x and y, and a foot under every leg
Genome fourLeggedGenome() {
  Genome genome;
  genome.nodes.push_back(box({1.2, 0.6, 0.3}));
  genome.nodes.push_back(box({0.5, 0.15, 0.15}, JointType::universal));
  genome.nodes.push_back(box({0.3, 0.1, 0.2}, JointType::spherical));
  genome.connections.push_back(link(0, 1, {0.6, 1, 0}, {0.2, 0.3, 0.5}, 0b011));
  genome.connections.push_back(link(1, 2, {1, 0.3, -0.5}, {-0.4, 0.7, 0.1}));
  return genome;
}

TEST(Develop, ReflectionMakesMirrorSymmetricLegs) {
  const FlatPlan plan = flatDevelop(fourLeggedGenome(), GenomeLimits{});
  // root, four legs, four feet
  ASSERT_EQ(plan.parts.size(), 9u);
  const Vec3 c = plan.parts[1].pose.position;
  EXPECT_FALSE(plan.parts[1].reflected);
  // copies in order: x mirror, y mirror, both
  const int masks[4] = {0, 1, 2, 3};
  for (int i = 0; i < 4; ++i) {
    const PartPlan& leg = plan.parts[1 + i];
    EXPECT_EQ(leg.node, 1);
    EXPECT_EQ(leg.parent, 0);
    EXPECT_EQ(leg.reflected, masks[i] != 0);
    expectNear(leg.pose.position, mirrored(c, masks[i]));
    expectNear(leg.pivot_in_parent, mirrored(plan.parts[1].pivot_in_parent, masks[i]));
  }
  // the four centres are (+-x, +-y, z) of each other
  expectNear(plan.parts[2].pose.position, {-c.x, c.y, c.z});
  expectNear(plan.parts[3].pose.position, {c.x, -c.y, c.z});
  expectNear(plan.parts[4].pose.position, {-c.x, -c.y, c.z});

  // feet follow their legs as mirror images, down the whole subtree
  for (int i = 0; i < 4; ++i) {
    const PartPlan& foot = plan.parts[5 + i];
    EXPECT_EQ(foot.node, 2);
    EXPECT_EQ(foot.parent, 1 + i);
    expectNear(foot.pose.position, mirrored(plan.parts[5].pose.position, masks[i]));
  }
  expectPlanConsistent(plan, GenomeLimits{});
}

TEST(Develop, MirroredPartsAreGeometricMirrorImagesWithMirroredJointMotion) {
  const FlatPlan plan = flatDevelop(fourLeggedGenome(), GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 9u);
  const int masks[4] = {0, 1, 2, 3};
  for (int chain = 0; chain < 2; ++chain) {
    const PartPlan& original = plan.parts[1 + 4 * chain];
    for (int i = 1; i < 4; ++i) {
      const PartPlan& copy = plan.parts[1 + 4 * chain + i];
      const int mask = masks[i];
      const double det = (mask == 3) ? 1.0 : -1.0;
      // the box occupies the mirrored space: its +x axis (along the limb) is mirrored, and the
      // other two axes span the mirrored plane
      const Vec3 x0 = rotate(original.pose.rotation, {1, 0, 0});
      expectNear(rotate(copy.pose.rotation, {1, 0, 0}), mirrored(x0, mask), 1e-12);
      for (int axis = 1; axis < 3; ++axis) {
        Vec3 unit{};
        unit[axis] = 1;
        const Vec3 v0 = mirrored(rotate(original.pose.rotation, unit), mask);
        const Vec3 v1 = rotate(copy.pose.rotation, unit);
        EXPECT_NEAR(std::fabs(dot(v0, v1)), 1.0, 1e-12);
      }
      // the same command turns the copy the mirrored way: joint axes are pseudovectors
      for (int d = 0; d < 3; ++d) {
        const Vec3 a0 = rotate(original.pose.rotation, original.axes[d]);
        const Vec3 a1 = rotate(copy.pose.rotation, copy.axes[d]);
        expectNear(a1, mirrored(a0, mask) * det, 1e-12);
      }
    }
  }
}

TEST(Develop, ReflectionAcrossAPlaneThroughTheAttachmentMakesNoCopy) {
  Genome genome;
  genome.nodes.push_back(box({1, 1, 1}));
  genome.nodes.push_back(box({0.3, 0.2, 0.2}));
  // y and z components are 0: only the x mirror makes a copy
  genome.connections.push_back(link(0, 1, {1, 0, 0}, {}, 0b111));
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 3u);
  expectNear(plan.parts[1].pose.position, {0.65, 0, 0});
  expectNear(plan.parts[2].pose.position, {-0.65, 0, 0});
  EXPECT_TRUE(plan.parts[2].reflected);
}

TEST(Develop, SelfConnectionRepeatsUpToTheRecursiveLimit) {
  Genome genome;
  genome.nodes.push_back(box({0.3, 0.2, 0.2}, JointType::revolute, 6));
  genome.connections.push_back(link(0, 0, {1, 0, 0}));
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 6u);
  EXPECT_FALSE(plan.truncated);
  for (int i = 1; i < 6; ++i) {
    EXPECT_EQ(plan.parts[i].parent, i - 1);
    EXPECT_EQ(plan.parts[i].depth, i);
    expectNear(plan.parts[i].pose.position, {0.3 * i, 0, 0});
  }
  expectPlanConsistent(plan, GenomeLimits{});
}

TEST(Develop, TerminalOnlyConnectionAppliesAtTheChainEnd) {
  Genome genome;
  genome.nodes.push_back(box({0.3, 0.2, 0.2}, JointType::revolute, 4));
  genome.nodes.push_back(box({0.1, 0.1, 0.1}));
  genome.connections.push_back(link(0, 0, {1, 0, 0}));
  ConnectionGene tail = link(0, 1, {0, 0, 1});
  tail.terminal_only = true;
  genome.connections.push_back(tail);
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 5u);
  int tails = 0;
  for (const PartPlan& part : plan.parts) {
    if (part.node == 1) {
      ++tails;
      EXPECT_EQ(part.parent, 3);
      EXPECT_EQ(plan.parts[part.parent].depth, 3);
    }
  }
  EXPECT_EQ(tails, 1);

  // without the flag every segment gets one
  genome.connections[1].terminal_only = false;
  const FlatPlan every = flatDevelop(genome, GenomeLimits{});
  EXPECT_EQ(every.parts.size(), 8u);
}

TEST(Develop, StopsAtMaxPartsAndSaysSo) {
  Genome genome;
  genome.nodes.push_back(box({0.3, 0.2, 0.2}, JointType::revolute, 6));
  genome.connections.push_back(link(0, 0, {1, 0, 0}));
  GenomeLimits limits;
  limits.max_parts = 4;
  const FlatPlan plan = flatDevelop(genome, limits);
  EXPECT_EQ(plan.parts.size(), 4u);
  EXPECT_TRUE(plan.truncated);
  expectPlanConsistent(plan, limits);

  limits.max_parts = 6;
  EXPECT_FALSE(flatDevelop(genome, limits).truncated);
  limits.max_parts = 1;
  const FlatPlan root_only = flatDevelop(genome, limits);
  EXPECT_EQ(root_only.parts.size(), 1u);
  EXPECT_TRUE(root_only.truncated);
}

TEST(Develop, SizesCompoundScalesAndAreClamped) {
  Genome genome;
  genome.nodes.push_back(box({3.0, 0.01, 0.4}, JointType::revolute, 5));
  genome.connections.push_back(link(0, 0, {1, 0, 0}));
  genome.connections[0].scale = 0.5;
  GenomeLimits limits;
  const FlatPlan plan = flatDevelop(genome, limits);
  ASSERT_EQ(plan.parts.size(), 5u);
  const double expected_x[5] = {1.5, 1.5, 0.75, 0.375, 0.1875};
  const double expected_z[5] = {0.4, 0.2, 0.1, 0.05, 0.05};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(plan.parts[i].size.x, expected_x[i], kTol) << "part " << i;
    EXPECT_NEAR(plan.parts[i].size.y, 0.05, kTol) << "part " << i;
    EXPECT_NEAR(plan.parts[i].size.z, expected_z[i], kTol) << "part " << i;
    EXPECT_NEAR(plan.parts[i].mass, 1000 * plan.parts[i].size.x * 0.05 * plan.parts[i].size.z,
                1e-9);
  }
  expectPlanConsistent(plan, limits);
}

// root with two neurons, a child with one, two brain neurons: every source kind
Genome wiredGenome() {
  Genome genome;
  genome.nodes.push_back(box({0.5, 0.5, 0.5}));
  genome.nodes.push_back(box({0.3, 0.1, 0.1}, JointType::universal));
  genome.connections.push_back(link(0, 1, {1, 0, 0}));
  genome.connections.push_back(link(0, 0, {0, 1, 0}));  // never made: node 0 is at its limit
  genome.connections[0].controller = {true, 0.5, 2.0, 0.3, 0.1};

  using S = SignalSource;
  using F = NeuronFunction;
  genome.nodes[0].neurons.push_back(
      neuron(F::sum, {in(S::local_sensor, 5, 0.5), in(S::child_neuron, 0, 1.5, /*slot=*/2)}));
  genome.nodes[0].neurons.push_back(
      neuron(F::if_positive, {in(S::parent_neuron, 0, 2.0), in(S::brain_neuron, 3),
                              in(S::brain_sensor, 4, -1.0), in(S::constant, 0, 9)}));
  genome.nodes[1].neurons.push_back(
      neuron(F::product, {in(S::parent_neuron, 1, 0.25)}));  // second input missing
  genome.nodes[1].effectors.push_back({in(S::local_neuron, 7, 3.0)});
  genome.nodes[1].effectors.push_back({in(S::local_sensor, 1, -2.0)});
  genome.nodes[1].effectors.push_back({in(S::constant, 0, 0.7)});  // only 2 dof: ignored
  genome.brain.push_back(
      neuron(F::sum, {in(S::local_sensor, 4, 1.0), in(S::local_neuron, 1, 2.0)}));
  genome.brain.push_back(neuron(
      F::max, {in(S::parent_neuron, 1, 1.0), in(S::child_neuron, 2, 1.0), in(S::constant, 0, 4)}));
  genome.brain.push_back(neuron(F::constant, {in(S::constant, 0, 4)}, 0.25));
  genome.brain.push_back(neuron(F::abs, {in(S::child_neuron, 0, 1.0, /*slot=*/1)}));
  return genome;
}

TEST(Develop, NeuronInputsResolveToTheSignalLayout) {
  const FlatPlan plan = flatDevelop(wiredGenome(), GenomeLimits{});
  ASSERT_EQ(plan.parts.size(), 2u);
  // sensors: root contact (0), child joint angles (1, 2), child contact (3), photo (4..6)
  ASSERT_EQ(plan.sensors.size(), 7u);
  EXPECT_EQ(plan.sensors[1].kind, SensorKind::joint_angle);
  EXPECT_EQ(plan.sensors[2].axis, 1);
  EXPECT_EQ(plan.sensors[3].kind, SensorKind::contact);
  EXPECT_EQ(plan.sensors[4].kind, SensorKind::photo);
  // neurons: root 0, 1 (signals 7, 8); child 2 (9); brain 3..6 (10..13)
  ASSERT_EQ(plan.neurons.size(), 7u);
  EXPECT_EQ(plan.neurons[0].part, 0);
  EXPECT_EQ(plan.neurons[2].part, 1);
  EXPECT_EQ(plan.neurons[3].part, -1);
  EXPECT_EQ(plan.signalCount(), 14);

  // root neuron 0: its only sensor (5 mod 1); the child through slot 2 mod 2 = connection 0
  EXPECT_EQ(plan.neurons[0].inputs[0], (Wire{0, 0.5}));
  EXPECT_EQ(plan.neurons[0].inputs[1], (Wire{9, 1.5}));
  EXPECT_EQ(plan.neurons[0].inputs[2], (Wire{-1, 0}));
  // root neuron 1: no parent; brain neuron 3 mod 4 = 3 (signal 13); photo 4 mod 3 = 1 (signal 5)
  EXPECT_EQ(plan.neurons[1].inputs[0], (Wire{-1, 0}));
  EXPECT_EQ(plan.neurons[1].inputs[1], (Wire{13, 1.0}));
  EXPECT_EQ(plan.neurons[1].inputs[2], (Wire{5, -1.0}));
  // child neuron: parent's neuron 1 (signal 8); missing second input is constant 0
  EXPECT_EQ(plan.neurons[2].inputs[0], (Wire{8, 0.25}));
  EXPECT_EQ(plan.neurons[2].inputs[1], (Wire{-1, 0}));
  // brain: any sensor (4 of 7); local neuron = brain neuron 1 (signal 11)
  EXPECT_EQ(plan.neurons[3].inputs[0], (Wire{4, 1.0}));
  EXPECT_EQ(plan.neurons[3].inputs[1], (Wire{11, 2.0}));
  // brain: parent and child read the root's neurons (1 -> 8, 2 mod 2 -> 7); arity 2 drops input 2
  EXPECT_EQ(plan.neurons[4].inputs[0], (Wire{8, 1.0}));
  EXPECT_EQ(plan.neurons[4].inputs[1], (Wire{7, 1.0}));
  EXPECT_EQ(plan.neurons[4].inputs[2], (Wire{-1, 0}));
  // constant has no inputs; its parameter is kept
  EXPECT_EQ(plan.neurons[5].inputs[0], (Wire{-1, 0}));
  EXPECT_EQ(plan.neurons[5].parameter, 0.25);
  EXPECT_EQ(plan.neurons[5].function, NeuronFunction::constant);
  // brain: child_neuron reads the root's neurons whatever the slot
  EXPECT_EQ(plan.neurons[6].inputs[0], (Wire{7, 1.0}));
}

TEST(Develop, ChildNeuronOfAnUnmadeConnectionIsConstantZero) {
  Genome genome = wiredGenome();
  // root neuron 0 reads through slot 1: the self-connection that is never made
  genome.nodes[0].neurons[0].inputs[1].slot = 1;
  const FlatPlan plan = flatDevelop(genome, GenomeLimits{});
  EXPECT_EQ(plan.neurons[0].inputs[1], (Wire{-1, 0}));
  // a leaf part reading its children: none leave node 1
  genome.nodes[1].neurons[0].inputs[0] = in(SignalSource::child_neuron, 0, 1.0);
  EXPECT_EQ(flatDevelop(genome, GenomeLimits{}).neurons[2].inputs[0], (Wire{-1, 0}));
}

TEST(Develop, EffectorsDriveTheDegreesOfFreedomOfNonRootJoints) {
  const FlatPlan plan = flatDevelop(wiredGenome(), GenomeLimits{});
  // universal joint: two degrees of freedom, three effector genes: two effectors
  ASSERT_EQ(plan.effectors.size(), 2u);
  EXPECT_EQ(plan.effectors[0].part, 1);
  EXPECT_EQ(plan.effectors[0].dof, 0);
  EXPECT_EQ(plan.effectors[0].input, (Wire{9, 3.0}));  // local neuron 7 mod 1
  EXPECT_EQ(plan.effectors[1].dof, 1);
  EXPECT_EQ(plan.effectors[1].input, (Wire{2, -2.0}));  // child's sensor 1 of (1, 2, 3)
  const JointControllerGene expected{true, 0.5, 2.0, 0.3, 0.1};
  EXPECT_EQ(plan.effectors[0].oscillator, expected);
  EXPECT_EQ(plan.effectors[1].oscillator, expected);

  // fewer effector genes than degrees of freedom: only those
  Genome genome = wiredGenome();
  genome.nodes[1].joint_type = JointType::spherical;
  genome.nodes[1].effectors.resize(1);
  EXPECT_EQ(flatDevelop(genome, GenomeLimits{}).effectors.size(), 1u);
  // a rigid joint has none
  genome.nodes[1].joint_type = JointType::fixed;
  const FlatPlan rigid = flatDevelop(genome, GenomeLimits{});
  EXPECT_TRUE(rigid.effectors.empty());
  EXPECT_EQ(rigid.sensors.size(), 5u);
}

TEST(Develop, SameGenomeDevelopsIdentically) {
  Genome genome = fourLeggedGenome();
  genome.nodes[1].neurons = wiredGenome().nodes[1].neurons;
  genome.brain = wiredGenome().brain;
  const FlatPlan a = flatDevelop(genome, GenomeLimits{});
  const FlatPlan b = flatDevelop(genome, GenomeLimits{});
  expectSamePlan(a, b);
}

// the same 10,000 random genomes are each valid under the default limits and develop into a
// body within them
TEST(Develop, TenThousandRandomGenomesAreValidAndDevelopWithinLimits) {
  const GenomeLimits limits;
  int truncated = 0, reflected = 0;
  for (std::uint64_t individual = 0; individual < 10000; ++individual) {
    const Genome genome = randomGenome(limits, 2024, individual / 100, individual % 100);
    ASSERT_NO_THROW(validateGenome(genome, limits)) << "individual " << individual;
    FlatPlan plan;
    ASSERT_NO_THROW(plan = flatDevelop(genome, limits)) << "individual " << individual;
    // the full invariant check on a sample keeps the test fast; the cheap checks on all
    ASSERT_GE(plan.parts.size(), 1u);
    ASSERT_LE(static_cast<int>(plan.parts.size()), limits.max_parts);
    for (const NeuronPlan& neuron : plan.neurons) {
      for (const Wire& wire : neuron.inputs) {
        ASSERT_LT(wire.signal, plan.signalCount()) << "individual " << individual;
      }
    }
    for (const FlatEffector& effector : plan.effectors) {
      ASSERT_LT(effector.input.signal, plan.signalCount()) << "individual " << individual;
    }
    for (const PartPlan& part : plan.parts) {
      ASSERT_TRUE(finite(part.pose.position) && finite(part.pose.rotation));
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(part.size[k], limits.min_part_size);
        ASSERT_LE(part.size[k], limits.max_part_size);
      }
      reflected += part.reflected ? 1 : 0;
    }
    truncated += plan.truncated ? 1 : 0;
    if (individual % 10 == 0) {
      expectPlanConsistent(plan, limits);
      if (::testing::Test::HasFailure()) {
        FAIL() << "individual " << individual;
      }
    }
  }
  // the sample exercises the interesting paths
  EXPECT_GT(reflected, 0);
  EXPECT_GT(truncated, 0);
}

// the hand-written creature file jobs/creatures/<name>.genome
Genome creature(const std::string& name) {
  return graphGenome(
      readGenomeFile(std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/" + name + ".genome"));
}

// what one part of a hand-written creature must be, read off its genome file
struct ExpectedPart {
  int node, parent;
  JointType joint;
  double limit;  // every degree of freedom
  Vec3 size;
  bool reflected;
};

// the parts of a plan against a table: node, parent, joint type and its degrees of freedom,
// limits, sizes, mirror flags; and one effector per degree of freedom of each non-root joint
void expectParts(const FlatPlan& plan, const std::vector<ExpectedPart>& expected,
                 const std::string& name) {
  ASSERT_EQ(plan.parts.size(), expected.size()) << name;
  int dofs = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const PartPlan& part = plan.parts[i];
    const ExpectedPart& want = expected[i];
    const std::string where = name + " part " + std::to_string(i);
    EXPECT_EQ(part.node, want.node) << where;
    EXPECT_EQ(part.parent, want.parent) << where;
    EXPECT_EQ(part.joint, want.joint) << where;
    EXPECT_EQ(part.reflected, want.reflected) << where;
    expectNear(part.size, want.size);
    const int part_dofs = degreesOfFreedom(part.joint);
    for (int d = 0; d < part_dofs; ++d)
      EXPECT_DOUBLE_EQ(part.joint_limit[d], want.limit) << where << " dof " << d;
    // the effectors of this part: exactly one per degree of freedom, in order
    std::vector<int> driven;
    for (const FlatEffector& effector : plan.effectors) {
      if (effector.part == static_cast<int>(i))
        driven.push_back(effector.dof);
    }
    std::vector<int> all_dofs;
    for (int d = 0; d < part_dofs; ++d)
      all_dofs.push_back(d);
    EXPECT_EQ(driven, all_dofs) << where;
    dofs += part_dofs;
  }
  EXPECT_EQ(plan.degreesOfFreedom(), dofs) << name;
  EXPECT_EQ(static_cast<int>(plan.effectors.size()), dofs) << name;
  EXPECT_FALSE(plan.truncated) << name;
}

// the hand-written creatures develop into the bodies their files describe
TEST(Develop, HandWrittenCreaturesHaveTheirPartsAndJoints) {
  const GenomeLimits limits;
  const JointType rigid = JointType::fixed, revolute = JointType::revolute,
                  universal = JointType::universal;

  // single_block: one 0.3 m cube; pole: a hinged 0.4 m pole on a 0.5 x 0.5 x 0.1 base
  const FlatPlan block = flatDevelop(creature("single_block"), limits);
  expectParts(block, {{0, -1, rigid, 1, {0.3, 0.3, 0.3}, false}}, "single_block");
  const FlatPlan pole = flatDevelop(creature("pole"), limits);
  expectParts(
      pole,
      {{0, -1, rigid, 1, {0.5, 0.5, 0.1}, false}, {1, 0, revolute, 1.2, {0.4, 0.06, 0.06}, false}},
      "pole");
  // the pole stands on the centre of the base's top face, its own x axis pointing up
  expectNear(pole.parts[1].pivot_in_parent, {0, 0, 0.05});
  expectNear(pole.parts[1].pose.position, {0, 0, 0.05 + 0.2});
  expectNear(rotate(pole.parts[1].pose.rotation, {1, 0, 0}), {0, 0, 1});

  // walker4: a rigid root body and four legs on universal hips (2 degrees of freedom each,
  // lift about the leg's y axis, swing about its z axis), front pair from node 1 and back pair
  // from node 2, the second of each pair the mirror copy
  const FlatPlan walker = flatDevelop(creature("walker4"), limits);
  const Vec3 leg{0.3, 0.1, 0.1};
  expectParts(walker,
              {{0, -1, rigid, 1, {0.6, 0.3, 0.15}, false},
               {1, 0, universal, 0.8, leg, false},
               {1, 0, universal, 0.8, leg, true},
               {2, 0, universal, 0.8, leg, false},
               {2, 0, universal, 0.8, leg, true}},
              "walker4");
  expectNear(walker.parts[1].axes[0], {0, 1, 0});
  expectNear(walker.parts[1].axes[1], {0, 0, 1});
  // hips at 0.6 of the half-length from the centre on the +y and (mirrored) -y side faces
  expectNear(walker.parts[1].pivot_in_parent, {0.18, 0.15, 0});
  expectNear(walker.parts[2].pivot_in_parent, {0.18, -0.15, 0});
  expectNear(walker.parts[3].pivot_in_parent, {-0.18, 0.15, 0});
  expectNear(walker.parts[4].pivot_in_parent, {-0.18, -0.15, 0});
  // mirrored legs sit mirror-symmetric across the body's x-z plane (and front and back pairs
  // across its y-z plane); the legs lie off that plane, so the check means something
  const Vec3 c = walker.parts[1].pose.position;
  EXPECT_GT(c.y, 0.15);
  EXPECT_GT(c.x, 0.1);
  expectNear(walker.parts[2].pose.position, {c.x, -c.y, c.z});
  expectNear(walker.parts[3].pose.position, {-c.x, c.y, c.z});
  expectNear(walker.parts[4].pose.position, {-c.x, -c.y, c.z});
  // the mirror copy's long axis is the original's mirrored across y
  const Vec3 along = rotate(walker.parts[1].pose.rotation, {1, 0, 0});
  expectNear(rotate(walker.parts[2].pose.rotation, {1, 0, 0}), {along.x, -along.y, along.z});

  // snake: one segment node repeated six times, a chain of revolute joints, in line along x
  const FlatPlan snake = flatDevelop(creature("snake"), limits);
  std::vector<ExpectedPart> chain;
  for (int i = 0; i < 6; ++i)
    chain.push_back({0, i - 1, i == 0 ? rigid : revolute, 0.7, {0.25, 0.1, 0.1}, false});
  expectParts(snake, chain, "snake");
  for (int i = 1; i < 6; ++i) {
    EXPECT_EQ(snake.parts[i].depth, i);
    expectNear(snake.parts[i].pose.position, {0.25 * i, 0, 0});
  }

  for (const FlatPlan* plan : {&block, &pole, &walker, &snake})
    expectPlanConsistent(*plan, limits);
}

// Minemonics' model organisms (jobs/creatures/minemonics): the leg's two equal limbs and hinge,
// the snake's chain of six, the pod's four legs on one body, the ragdoll's head, arms and legs;
// every effector driven by a chaotic oscillator, each connection's with its own start
TEST(Develop, MinemonicsModelOrganismsHaveTheirPartsJointsAndChaoticControllers) {
  const GenomeLimits limits;
  const JointType rigid = JointType::fixed, revolute = JointType::revolute,
                  universal = JointType::universal, spherical = JointType::spherical;
  const Vec3 limb{0.5, 0.1, 0.1}, segment{0.3, 0.1, 0.1}, pod_leg{0.3, 0.08, 0.08};
  const FlatPlan leg = flatDevelop(creature("minemonics/leg"), limits);
  expectParts(leg, {{0, -1, rigid, 1.2, limb, false}, {1, 0, revolute, 1.2, limb, false}}, "leg");
  const FlatPlan snake = flatDevelop(creature("minemonics/snake"), limits);
  std::vector<ExpectedPart> chain;
  for (int i = 0; i < 6; ++i)
    chain.push_back({i, i - 1, i == 0 ? rigid : revolute, 1, segment, false});
  expectParts(snake, chain, "snake");
  const FlatPlan pod = flatDevelop(creature("minemonics/pod"), limits);
  std::vector<ExpectedPart> pod_parts{{0, -1, rigid, 1, {0.6, 0.3, 0.15}, false}};
  for (int i = 0; i < 4; ++i)  // each connection's leg, then its flipped copy
    pod_parts.push_back({1, 0, revolute, 0.8, pod_leg, i % 2 == 1});
  expectParts(pod, pod_parts, "pod");
  const FlatPlan ragdoll = flatDevelop(creature("minemonics/ragdoll"), limits);
  EXPECT_EQ(ragdoll.parts.size(), 10u);
  EXPECT_EQ(ragdoll.degreesOfFreedom(), 3 + 2 * 3 + 2 * 2 + 2 + 2);
  int spherical_joints = 0, universal_joints = 0;
  for (const PartPlan& part : ragdoll.parts) {
    spherical_joints += part.joint == spherical;
    universal_joints += part.joint == universal;
  }
  EXPECT_EQ(spherical_joints, 3);  // the neck and the shoulders
  EXPECT_EQ(universal_joints, 2);  // the hips

  for (const char* name : {"leg", "snake", "pod", "ragdoll"}) {
    const Creature creature_plan = develop(creature(std::string("minemonics/") + name), limits);
    const auto* sum = dynamic_cast<const ControllerSumPlan*>(creature_plan.controller.get());
    ASSERT_NE(sum, nullptr) << name;
    EXPECT_EQ(sum->kind(), "network+chaotic") << name;
    const auto* chua = dynamic_cast<const ChuaOscillatorsPlan*>(sum->parts.at(1).get());
    ASSERT_NE(chua, nullptr) << name;
    ASSERT_EQ(chua->oscillators.size(), creature_plan.body.effectors.size()) << name;
    std::vector<ChuaState> starts;
    for (const ChuaOscillator& o : chua->oscillators) {
      EXPECT_TRUE(o.enabled) << name;
      if (std::find(starts.begin(), starts.end(), o.start) == starts.end())
        starts.push_back(o.start);
    }
    // the leg's one hinge, the snake's five, the pod's two pairs of hips, the ragdoll's five
    // connections (a flipped copy is driven by a controller of its connection's gene)
    const std::size_t connections = creature(std::string("minemonics/") + name).connections.size();
    EXPECT_EQ(starts.size(), connections) << name;
  }
  for (const FlatPlan* plan : {&leg, &snake, &pod, &ragdoll})
    expectPlanConsistent(*plan, limits);
}

TEST(Develop, BrokenGenomesAndLimitsThrowNamingTheField) {
  const Genome empty;
  EXPECT_THROW(flatDevelop(empty, GenomeLimits{}), GenomeError);
  Genome genome = fourLeggedGenome();
  genome.connections[1].to = 7;
  try {
    flatDevelop(genome, GenomeLimits{});
    FAIL() << "expected GenomeError";
  } catch (const GenomeError& error) {
    EXPECT_NE(std::string(error.what()).find("connections[1]"), std::string::npos);
  }
  GenomeLimits limits;
  limits.max_parts = 0;
  EXPECT_THROW(flatDevelop(fourLeggedGenome(), limits), ConfigError);
}

// genome.contact_sensors = face: six contact_face sensors (faces 0..5) in place of each part's
// contact sensor, after its joint angles; the photo sensors still last
TEST(Develop, ContactSensorsPerFace) {
  Genome genome = creature("pole");
  GenomeLimits limits;
  limits.contact_sensors = ContactSensors::per_face;
  const Creature creature = develop(genome, limits);
  const std::vector<SensorPlan>& sensors = creature.body.sensors;
  ASSERT_EQ(creature.body.parts.size(), 2u);
  ASSERT_EQ(sensors.size(), 6u + 1u + 6u + 3u);  // root faces; child angle and faces; photo
  for (int face = 0; face < 6; ++face) {
    EXPECT_EQ(sensors[face], (SensorPlan{SensorKind::contact_face, 0, face}));
    EXPECT_EQ(sensors[7 + face], (SensorPlan{SensorKind::contact_face, 1, face}));
  }
  EXPECT_EQ(sensors[6].kind, SensorKind::joint_angle);
  EXPECT_EQ(sensors[13].kind, SensorKind::photo);
  EXPECT_EQ(develop(genome, GenomeLimits{}).body.sensors.size(), 1u + 2u + 3u);
}

// a catapult's arm holds its projectile against the face its position points to, flush with it;
// the release effector comes last, driven by the mechanism's larger-of neuron
TEST(Develop, TheArmHoldsTheProjectile) {
  Genome g;
  g.nodes.push_back(box({0.6, 0.4, 0.2}));
  ProjectileGene projectile;
  projectile.dimensions = {0.1, 0.2, 0.3};
  projectile.density = 500;
  projectile.position = {0.2, -0.5, 0.9};  // the +z face
  g.projectile = projectile;
  GenomeLimits limits;
  limits.catapult = true;
  const Creature creature = develop(g, limits);
  ASSERT_EQ(creature.body.held.size(), 1u);
  const HeldObject& held = creature.body.held[0];
  EXPECT_EQ(held.part, 0);
  EXPECT_EQ(held.size, (Vec3{0.1, 0.2, 0.3}));
  EXPECT_NEAR(held.mass, 500 * 0.1 * 0.2 * 0.3, 1e-12);
  EXPECT_NEAR(held.pose.position.x, 0.2 * 0.3, 1e-12);
  EXPECT_NEAR(held.pose.position.y, -0.5 * 0.2, 1e-12);
  EXPECT_NEAR(held.pose.position.z, 0.1 + 0.15, 1e-12);  // its -z face on the arm's +z face
  ASSERT_FALSE(creature.body.effectors.empty());
  const EffectorPlan& release = creature.body.effectors.back();
  EXPECT_EQ(release.kind, EffectorKind::release);
  EXPECT_EQ(release.part, 0);
  EXPECT_EQ(release.dof, 0);
  // no projectile, no release
  g.projectile.reset();
  limits.catapult = false;
  EXPECT_TRUE(develop(g, limits).body.held.empty());
}

// the plan's sensors are of these kinds, in this order
void expectSensorKinds(const BodyPlan& plan, std::span<const SensorKind> kinds) {
  ASSERT_EQ(plan.sensors.size(), kinds.size());
  for (std::size_t s = 0; s < kinds.size(); ++s)
    EXPECT_EQ(plan.sensors[s].kind, kinds[s]) << s;
}

// photosensors on every part: three more per part, after its contact sensor, each in its own
// part's frame; a part's local_sensor inputs reach them; the creature's three stay last
TEST(Develop, PhotosensorsOnEveryPart) {
  Genome g;
  g.nodes.push_back(box({0.4, 0.4, 0.2}, JointType::fixed));
  g.nodes.push_back(box({0.3, 0.1, 0.1}));
  g.connections.push_back(link(0, 1, {1, 0, 0}));
  GenomeLimits limits;
  const BodyPlan root_only = develop(g, limits).body;
  limits.photosensors = Photosensors::every_part;
  const BodyPlan every = develop(g, limits).body;
  ASSERT_EQ(every.sensors.size(), root_only.sensors.size() + 6);
  // root: contact, photo x3; child: angle, contact, photo x3; the creature's photo x3
  const SensorKind kinds[] = {SensorKind::contact, SensorKind::photo,       SensorKind::photo,
                              SensorKind::photo,   SensorKind::joint_angle, SensorKind::contact,
                              SensorKind::photo,   SensorKind::photo,       SensorKind::photo,
                              SensorKind::photo,   SensorKind::photo,       SensorKind::photo};
  expectSensorKinds(every, kinds);
  EXPECT_EQ(every.sensors[6].part, 1);
  EXPECT_EQ(every.sensors[8].axis, 2);
  EXPECT_EQ(every.sensors[9].part, 0);
}

// a chaotic joint controller develops into the chaotic oscillators after the network (and the
// sine ones when some joint has one), driving its joint's effector amplitude * z + offset from its
// start, with the run's circuit; a joint without one is driven by the network alone
TEST(Develop, ChaoticJointControllersFollowTheNetwork) {
  Genome g;
  g.nodes = {box({0.4, 0.2, 0.2}), box({0.2, 0.2, 0.2})};
  g.nodes[1].effectors.resize(1);  // its input is the constant 0
  g.connections = {link(0, 1, {1, 0, 0}), link(0, 1, {-1, 0, 0})};
  JointControllerGene& chaotic = g.connections[0].controller;
  chaotic.enabled = true;
  chaotic.kind = JointControllerKind::chaotic;
  chaotic.amplitude = 0.25;
  chaotic.offset = 0.1;
  chaotic.chua_start = {0.1, 0.2, 0.4};
  chaotic.chua_speed = 3;
  GenomeLimits limits;
  limits.chua.limited = true;
  const Creature creature = develop(g, limits);
  const auto* sum = dynamic_cast<const ControllerSumPlan*>(creature.controller.get());
  ASSERT_NE(sum, nullptr);
  EXPECT_EQ(sum->kind(), "network+chaotic");
  const auto* chua = dynamic_cast<const ChuaOscillatorsPlan*>(sum->parts.at(1).get());
  ASSERT_NE(chua, nullptr);
  EXPECT_EQ(chua->circuit, limits.chua);
  ASSERT_EQ(chua->oscillators.size(), 2u);
  EXPECT_EQ(chua->oscillators[0], (ChuaOscillator{true, 0.25, 0.1, {0.1, 0.2, 0.4}, 3}));
  EXPECT_FALSE(chua->oscillators[1].enabled);
  auto controller = creature.controller->build(1.0 / 240, creature.body.sensors.size(), 2);
  std::vector<double> sensors(creature.body.sensors.size(), 0.0), drives(2);
  controller->step(sensors, drives);
  EXPECT_DOUBLE_EQ(drives[0], 0.25 * 0.4 + 0.1);
  EXPECT_EQ(drives[1], 0.0);

  // with a sine on the other joint: network, sine, chaotic
  g.connections[1].controller.enabled = true;
  g.connections[1].controller.amplitude = 0.5;
  EXPECT_EQ(develop(g, limits).controller->kind(), "network+sine+chaotic");
}

// chosen photosensors: three on each photosensitive part only (where every_part would put
// them); root and every_part ignore the flag
TEST(Develop, PhotosensorsOnTheChosenParts) {
  Genome g;
  g.nodes.push_back(box({0.4, 0.4, 0.2}, JointType::fixed));
  g.nodes.push_back(box({0.3, 0.1, 0.1}));
  g.connections.push_back(link(0, 1, {1, 0, 0}));
  g.connections.push_back(link(0, 1, {-1, 0, 0}));
  g.nodes[1].photosensitive = true;
  GenomeLimits limits;
  limits.photosensors = Photosensors::chosen;
  const BodyPlan chosen = develop(g, limits).body;
  // root: contact; each child: angle, contact, photo x3; the creature's photo x3
  const SensorKind kinds[] = {SensorKind::contact,     SensorKind::joint_angle, SensorKind::contact,
                              SensorKind::photo,       SensorKind::photo,       SensorKind::photo,
                              SensorKind::joint_angle, SensorKind::contact,     SensorKind::photo,
                              SensorKind::photo,       SensorKind::photo,       SensorKind::photo,
                              SensorKind::photo,       SensorKind::photo};
  expectSensorKinds(chosen, kinds);
  EXPECT_EQ(chosen.sensors[3].part, 1);
  EXPECT_EQ(chosen.sensors[10].part, 2);
  EXPECT_EQ(chosen.sensors[11].part, 0);
  Genome plain = g;
  plain.nodes[1].photosensitive = false;
  for (const Photosensors where : {Photosensors::root, Photosensors::every_part}) {
    limits.photosensors = where;
    const BodyPlan a = develop(g, limits).body, b = develop(plain, limits).body;
    ASSERT_EQ(a.sensors.size(), b.sensors.size());
    for (std::size_t s = 0; s < a.sensors.size(); ++s)
      EXPECT_TRUE(a.sensors[s].kind == b.sensors[s].kind &&
                  a.sensors[s].part == b.sensors[s].part && a.sensors[s].axis == b.sensors[s].axis)
          << s;
  }
}

}  // namespace
}  // namespace cambrian::graph
