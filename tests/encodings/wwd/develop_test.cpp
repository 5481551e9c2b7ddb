// A Walking with Dinosaurs creature as a body and its layered network: boxes meeting face to face,
// the screw, the joints, sensors and muscles, the inputs resolved over the layers, and a passive
// creature at rest in Bullet's world.
#include "encodings/wwd/develop.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "brain/layered_network.hpp"
#include "physics/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace cambrian::wwd {
namespace {

void expectNear(Vec3 a, Vec3 b, double tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// the rotation by `angle` about unit axis `axis`
Quat turn(Vec3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * axis.x, s * axis.y, s * axis.z};
}

NodeGenes constant(double value) {
  NodeGenes node;
  node.function = LayeredFunction::constant;
  node.value = value;
  return node;
}

NodeGenes function(LayeredFunction f, std::vector<Gene> inputs) {
  NodeGenes node;
  node.function = f;
  node.input_count = static_cast<int>(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    node.inputs[i] = inputs[i];
    node.weights[i] = 0.5 + static_cast<double>(i);
  }
  return node;
}

// a net of one layer of `n` constants of `value`
NetGenes constants(std::size_t n, double value) {
  NetGenes net;
  net.layers.push_back(std::vector<NodeGenes>(n, constant(value)));
  return net;
}

// a root of `root` and a child of `child` on joint `joint`, every node a constant 0
CreatureGenes twoBoxes(BoxGenes root, BoxGenes child, FacePoint pre, FacePoint post,
                       double screw = 0) {
  CreatureGenes genes;
  genes.boxes = {root, child};
  JointGenes joint;
  joint.parent = 0;
  joint.child = 1;
  joint.subnet = constants(3, 0);
  joint.effector = {0, 1, 2};
  joint.screw = screw;
  joint.pre = pre;
  joint.post = post;
  joint.limit = {0.1, 0.2, 0.3};
  genes.joints = {joint};
  genes.main = constants(2, 0);
  return genes;
}

const BoxGenes kRoot{{0.4, 0.2, 0.1}, true};
const BoxGenes kChild{{0.3, 0.1, 0.2}, false};
const FacePoint kPre{0, 0.5, -0.5};  // +x face: (0.2, 0.05, -0.025) on the root
const FacePoint kPost{3, 0.2, 0.4};  // -y face: (0.06, -0.05, 0.02) on the child

std::shared_ptr<const LayeredNetworkPlan> networkOf(const Creature& creature) {
  return std::dynamic_pointer_cast<const LayeredNetworkPlan>(creature.controller);
}

// face points: face `side` at (u, v) in half-sides of the next axis and the one after
TEST(WwdBody, FaceFramesLieOnTheFaces) {
  const FaceFrame pre = faceFrame(kRoot.size, kPre);
  EXPECT_EQ(pre.axis, 0);
  expectNear(pre.point, {0.2, 0.05, -0.025}, 1e-15, "PRE point");
  EXPECT_EQ(pre.normal, (Vec3{1, 0, 0}));
  const FaceFrame post = faceFrame(kChild.size, kPost);
  EXPECT_EQ(post.axis, 1);
  expectNear(post.point, {0.06, -0.05, 0.02}, 1e-15, "POST point");
  EXPECT_EQ(post.normal, (Vec3{0, -1, 0}));
  const FaceFrame bottom = faceFrame({1, 2, 3}, {5, -1, 1});
  EXPECT_EQ(bottom.axis, 2);
  expectNear(bottom.point, {-0.5, 1, -1.5}, 1e-15, "-z face point");
  EXPECT_EQ(bottom.normal, (Vec3{0, 0, -1}));
}

// the child's POST point sits on the parent's PRE point and its POST normal points against the
// PRE normal, for every pair of faces and any screw
TEST(WwdBody, TheChildsPostFaceMeetsTheParentsPreFace) {
  for (int pre_side = 0; pre_side < 6; ++pre_side) {
    for (int post_side = 0; post_side < 6; ++post_side) {
      for (double screw : {0.0, kPi / 2, 1.3, kPi}) {
        const FacePoint pre{pre_side, 0.3, -0.7}, post{post_side, -0.2, 0.9};
        const Creature creature = developCreature(twoBoxes(kRoot, kChild, pre, post, screw), {});
        ASSERT_EQ(creature.body.parts.size(), 2u);
        const PartPlan& root = creature.body.parts[0];
        const PartPlan& child = creature.body.parts[1];
        const std::string what = "PRE side " + std::to_string(pre_side) + ", POST side " +
                                 std::to_string(post_side) + ", screw " + std::to_string(screw);
        const FaceFrame p = faceFrame(root.size, pre);
        const FaceFrame q = faceFrame(child.size, post);
        expectNear(apply(child.pose, q.point), apply(root.pose, p.point), 1e-12, what);
        expectNear(rotate(child.pose.rotation, q.normal), -rotate(root.pose.rotation, p.normal),
                   1e-12, what);
        // the joint's frame: its pivots, and the child's frame in the parent's
        EXPECT_EQ(child.pivot_in_parent, p.point) << what;
        EXPECT_EQ(child.pivot_in_child, q.point) << what;
        const Quat r = child.parent_to_child;
        EXPECT_NEAR(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z, 1, 1e-12) << what;
        expectNear(rotate(r, q.normal), -p.normal, 1e-12, what);
        for (const Vec3 v : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
          expectNear(rotate(child.pose.rotation, v), rotate(root.pose.rotation, rotate(r, v)),
                     1e-12, what);
        if (HasFailure())
          return;
      }
    }
  }
}

// the screw turns the child about the PRE normal: by a quarter for 90 degrees. Unscrewed, the -y
// POST face onto the +x PRE face is a quarter turn about -z: x -> -y, y -> x, z -> z; then a
// quarter about +x: x -> -z, y -> x, z -> -y
TEST(WwdBody, TheScrewTurnsTheChildAboutThePreNormal) {
  const Creature plain = developCreature(twoBoxes(kRoot, kChild, kPre, kPost, 0), {});
  const Creature quarter = developCreature(twoBoxes(kRoot, kChild, kPre, kPost, kPi / 2), {});
  const Quat r0 = plain.body.parts[1].pose.rotation;
  const Quat r90 = quarter.body.parts[1].pose.rotation;
  expectNear(rotate(r0, {1, 0, 0}), {0, -1, 0}, 1e-12, "unscrewed x");
  expectNear(rotate(r0, {0, 1, 0}), {1, 0, 0}, 1e-12, "unscrewed y");
  expectNear(rotate(r0, {0, 0, 1}), {0, 0, 1}, 1e-12, "unscrewed z");
  expectNear(rotate(r90, {1, 0, 0}), {0, 0, -1}, 1e-12, "screwed x");
  expectNear(rotate(r90, {0, 1, 0}), {1, 0, 0}, 1e-12, "screwed y");
  expectNear(rotate(r90, {0, 0, 1}), {0, -1, 0}, 1e-12, "screwed z");
  // the child's centre: the PRE point (0.2, 0.05, -0.025) less the turned POST point
  expectNear(quarter.body.parts[1].pose.position,
             Vec3{0.2, 0.05, -0.025} - rotate(r90, {0.06, -0.05, 0.02}), 1e-12, "centre");
  expectNear(quarter.body.parts[1].pose.position, {0.25, 0.07, 0.035}, 1e-12, "centre");
  // for any faces: the screwed rotation is the unscrewed one turned about the PRE normal
  for (int pre_side = 0; pre_side < 6; ++pre_side) {
    for (int post_side = 0; post_side < 6; ++post_side) {
      const FacePoint pre{pre_side, 0, 0}, post{post_side, 0, 0};
      const Quat a =
          developCreature(twoBoxes(kRoot, kChild, pre, post, 0), {}).body.parts[1].pose.rotation;
      const Quat b =
          developCreature(twoBoxes(kRoot, kChild, pre, post, 0.7), {}).body.parts[1].pose.rotation;
      const Vec3 normal = faceFrame(kRoot.size, pre).normal;
      for (const Vec3 v : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        expectNear(rotate(b, v), rotate(turn(normal, 0.7), rotate(a, v)), 1e-12,
                   "sides " + std::to_string(pre_side) + " " + std::to_string(post_side));
    }
  }
}

// a chain of three boxes: poses compose through the parents (box 2's POST point on box 1's PRE
// point in the creature frame), depths count
TEST(WwdBody, PosesComposeDownAChain) {
  CreatureGenes genes = twoBoxes(kRoot, kChild, kPre, kPost, 0.4);
  JointGenes second = genes.joints[0];
  second.parent = 1;
  second.child = 2;
  second.pre = {4, -0.3, 0.6};
  second.post = {1, 0.1, -0.8};
  second.screw = 2.1;
  genes.joints.push_back(second);
  genes.boxes.push_back({{0.15, 0.25, 0.35}, true});
  const Creature creature = developCreature(genes, {});
  ASSERT_EQ(creature.body.parts.size(), 3u);
  const PartPlan& middle = creature.body.parts[1];
  const PartPlan& end = creature.body.parts[2];
  EXPECT_EQ(end.parent, 1);
  EXPECT_EQ(end.connection, 1);
  EXPECT_EQ(end.depth, 2);
  EXPECT_EQ(middle.depth, 1);
  expectNear(apply(end.pose, faceFrame(end.size, second.post).point),
             apply(middle.pose, faceFrame(middle.size, second.pre).point), 1e-12, "chain point");
  expectNear(rotate(end.pose.rotation, faceFrame(end.size, second.post).normal),
             -rotate(middle.pose.rotation, faceFrame(middle.size, second.pre).normal), 1e-12,
             "chain normal");
}

// the joint: spherical, its limits the genes', its axes the POST face's two in-plane axes then its
// normal, right-handed; strength from the smaller face; mass from the volume
TEST(WwdBody, JointsAreSphericalWithTheirLimitsAndStrength) {
  const Creature creature = developCreature(twoBoxes(kRoot, kChild, kPre, kPost), {});
  const PartPlan& root = creature.body.parts[0];
  const PartPlan& child = creature.body.parts[1];
  EXPECT_EQ(root.parent, -1);
  EXPECT_EQ(root.node, 0);
  EXPECT_EQ(child.node, 1);
  EXPECT_EQ(child.parent, 0);
  EXPECT_EQ(child.connection, 0);
  EXPECT_EQ(child.joint, JointType::spherical);
  EXPECT_EQ(child.joint_limit, (Vec3{0.1, 0.2, 0.3}));
  // POST on the -y face: axes z, x, then the normal y
  EXPECT_EQ(child.axes[0], (Vec3{0, 0, 1}));
  EXPECT_EQ(child.axes[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(child.axes[2], (Vec3{0, 1, 0}));
  // the +x face of the root is 0.2 x 0.1 = 0.02 m^2, the -y face of the child 0.2 x 0.3 = 0.06
  EXPECT_DOUBLE_EQ(child.cross_section, 0.02);
  EXPECT_DOUBLE_EQ(child.strength, 2000 * 0.02);
  EXPECT_DOUBLE_EQ(root.mass, 1000 * 0.4 * 0.2 * 0.1);
  EXPECT_DOUBLE_EQ(child.mass, 1000 * 0.3 * 0.1 * 0.2);
  EXPECT_EQ(child.shape, PartShape::box);
  EXPECT_EQ(child.size, kChild.size);

  // other settings, and the child's face the smaller one
  BodySettings settings;
  settings.density = 250;
  settings.friction = 0.3;
  settings.strength_per_area = 10;
  const Creature other = developCreature(twoBoxes(kRoot, kChild, {4, 0, 0}, {0, 0, 0}), settings);
  // the root's +z face 0.4 x 0.2 = 0.08, the child's +x face 0.1 x 0.2 = 0.02
  EXPECT_DOUBLE_EQ(other.body.parts[1].cross_section, 0.02);
  EXPECT_DOUBLE_EQ(other.body.parts[1].strength, 10 * 0.02);
  EXPECT_DOUBLE_EQ(other.body.parts[1].mass, 250 * 0.3 * 0.1 * 0.2);
  EXPECT_EQ(other.body.parts[0].material.density, 250);
  EXPECT_EQ(other.body.parts[1].material.friction, 0.3);
  EXPECT_EQ(other.body.parts[1].axes[2], (Vec3{1, 0, 0}));

  // every face: axes right-handed, the third the face's normal axis
  for (int side = 0; side < 6; ++side) {
    const Creature c = developCreature(twoBoxes(kRoot, kChild, kPre, {side, 0, 0}), {});
    const auto& axes = c.body.parts[1].axes;
    EXPECT_EQ(cross(axes[0], axes[1]), axes[2]) << side;
    Vec3 normal_axis;
    normal_axis[side / 2] = 1;
    EXPECT_EQ(axes[2], normal_axis) << side;
  }
}

// sensors: a box's pressure sensor, then its joint's three angles; three muscles a joint
TEST(WwdBody, SensorsAndEffectorsFollowTheBoxes) {
  CreatureGenes genes = twoBoxes(kRoot, {{0.3, 0.1, 0.2}, true}, kPre, kPost);
  JointGenes second = genes.joints[0];
  second.child = 2;
  genes.joints.push_back(second);
  genes.boxes.push_back({{0.1, 0.1, 0.1}, false});
  const Creature creature = developCreature(genes, {});
  const std::vector<SensorPlan> sensors = {
      {SensorKind::contact, 0, 0},     {SensorKind::contact, 1, 0},
      {SensorKind::joint_angle, 1, 0}, {SensorKind::joint_angle, 1, 1},
      {SensorKind::joint_angle, 1, 2}, {SensorKind::joint_angle, 2, 0},
      {SensorKind::joint_angle, 2, 1}, {SensorKind::joint_angle, 2, 2}};
  EXPECT_EQ(creature.body.sensors, sensors);
  const std::vector<EffectorPlan> effectors = {
      {1, 0, EffectorKind::joint}, {1, 1, EffectorKind::joint}, {1, 2, EffectorKind::joint},
      {2, 0, EffectorKind::joint}, {2, 1, EffectorKind::joint}, {2, 2, EffectorKind::joint}};
  EXPECT_EQ(creature.body.effectors, effectors);
  EXPECT_FALSE(creature.body.truncated);
  genes.truncated = true;
  EXPECT_TRUE(developCreature(genes, {}).body.truncated);
}

// the controller: the main net over the sensors, a subnet and three muscles per joint, the
// muscles as strong as the joint, their nodes the effector genes modulo the subnet's last layer
TEST(WwdBody, TheNetworkHasASubnetAndMusclesPerJoint) {
  CreatureGenes genes = twoBoxes(kRoot, kChild, kPre, kPost);
  genes.joints[0].effector = {4, 5, 998};
  // the main net: a sensor node reading gene 6 (sensor 6 % 4 = 2), a sum of inputs 5 and 2 (5 % 4
  // = 1 and 2); then a product of node genes 3 and 4 (3 % 2 = 1, 4 % 2 = 0)
  genes.main.layers = {
      {function(LayeredFunction::sensor, {6}), function(LayeredFunction::sum, {5, 2})},
      {function(LayeredFunction::product, {3, 4})}};
  // the subnet: over the main net's one output
  genes.joints[0].subnet.layers = {{function(LayeredFunction::sine, {7})},
                                   std::vector<NodeGenes>(3, constant(1))};
  const Creature creature = developCreature(genes, {});
  const auto network = networkOf(creature);
  ASSERT_TRUE(network);
  EXPECT_EQ(network->kind(), "layered");
  EXPECT_EQ(network->sensor_count, 4u);  // the root's pressure, the joint's three angles
  ASSERT_EQ(network->subnets.size(), 1u);
  ASSERT_EQ(network->joints.size(), 1u);
  EXPECT_EQ(network->joints[0].subnet, 0);
  EXPECT_EQ(network->joints[0].nodes, (std::array<int, 3>{1, 2, 2}));
  EXPECT_DOUBLE_EQ(network->joints[0].strength, creature.body.parts[1].strength);
  EXPECT_DOUBLE_EQ(network->joints[0].strength, 40);

  const LayeredNode& sensor = network->main.layers[0][0];
  EXPECT_EQ(sensor.function, LayeredFunction::sensor);
  EXPECT_EQ(sensor.input_count, 1);
  EXPECT_EQ(sensor.inputs[0].index, 2);
  const LayeredNode& sum = network->main.layers[0][1];
  EXPECT_EQ(sum.input_count, 2);
  EXPECT_EQ(sum.inputs[0].index, 1);
  EXPECT_EQ(sum.inputs[1].index, 2);
  EXPECT_EQ(sum.inputs[0].weight, 0.5);
  EXPECT_EQ(sum.inputs[1].weight, 1.5);
  const LayeredNode& product = network->main.layers[1][0];
  EXPECT_EQ(product.inputs[0].index, 1);
  EXPECT_EQ(product.inputs[1].index, 0);
  const LayeredNode& sine = network->subnets[0].layers[0][0];
  EXPECT_EQ(sine.input_count, 1);
  EXPECT_EQ(sine.inputs[0].index, 0);  // 7 % 1
  EXPECT_EQ(network->subnets[0].layers[1][2], (LayeredNode{LayeredFunction::constant, 1, 0, {}}));
  EXPECT_EQ(network->neuronCount(), 2 + 1 + 1 + 3);
  EXPECT_NO_THROW(network->build(0.01, 4, 3));
  EXPECT_THROW(network->build(0.01, 3, 3), Error);
}

// no sensors: the main net's first layer has nothing to read — its nodes keep their functions
// without inputs, its sensor nodes become constant 0; later layers read the layer before
TEST(WwdBody, WithoutSensorsTheFirstLayerReadsNothing) {
  CreatureGenes genes;
  genes.boxes = {{{0.1, 0.1, 0.1}, false}};
  genes.main.layers = {
      {function(LayeredFunction::sum, {3, 4}), function(LayeredFunction::sensor, {1}), constant(2)},
      {function(LayeredFunction::maximum, {4, 5, 6})}};
  const Creature creature = developCreature(genes, {});
  EXPECT_TRUE(creature.body.sensors.empty());
  EXPECT_TRUE(creature.body.effectors.empty());
  const auto network = networkOf(creature);
  ASSERT_TRUE(network);
  EXPECT_EQ(network->sensor_count, 0u);
  EXPECT_TRUE(network->subnets.empty());
  const auto& first = network->main.layers[0];
  EXPECT_EQ(first[0].function, LayeredFunction::sum);
  EXPECT_EQ(first[0].input_count, 0);
  EXPECT_EQ(first[1].function, LayeredFunction::constant);
  EXPECT_EQ(first[1].value, 0);
  EXPECT_EQ(first[1].input_count, 0);
  EXPECT_EQ(first[2].value, 2);
  const LayeredNode& maximum = network->main.layers[1][0];
  EXPECT_EQ(maximum.input_count, 3);
  EXPECT_EQ(maximum.inputs[0].index, 1);  // 4 % 3
  EXPECT_EQ(maximum.inputs[1].index, 2);
  EXPECT_EQ(maximum.inputs[2].index, 0);
  EXPECT_NO_THROW(network->build(0.01, 0, 0));
}

// random creatures: every index the network reads lies inside its layer, the sensors or the
// subnet's last layer, and the network builds for the body
TEST(WwdBody, EveryInputOfARandomCreatureIsInRange) {
  const GrammarSettings grammar;
  int with_sensor_nodes = 0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    Rng rng(21, RngPurpose::test, 0, k);
    const CreatureGenes genes = readCreature(randomDna(grammar, rng), grammar);
    const Creature creature = developCreature(genes, {});
    SCOPED_TRACE("creature " + std::to_string(k));
    ASSERT_EQ(creature.body.parts.size(), genes.boxes.size());
    ASSERT_EQ(creature.body.effectors.size(), 3 * genes.joints.size());
    const auto network = networkOf(creature);
    ASSERT_TRUE(network);
    const std::size_t sensors = creature.body.sensors.size();
    ASSERT_EQ(network->sensor_count, sensors);
    ASSERT_EQ(network->subnets.size(), genes.joints.size());
    const auto check = [&](const LayeredNet& net, std::size_t first_previous) {
      std::size_t previous = first_previous;
      for (const auto& layer : net.layers) {
        ASSERT_FALSE(layer.empty());
        for (const LayeredNode& node : layer) {
          if (node.function == LayeredFunction::sensor) {
            ++with_sensor_nodes;
            ASSERT_EQ(node.input_count, 1);
            ASSERT_LT(static_cast<std::size_t>(node.inputs[0].index), sensors);
            continue;
          }
          for (int i = 0; i < node.input_count; ++i) {
            ASSERT_GE(node.inputs[static_cast<std::size_t>(i)].index, 0);
            ASSERT_LT(static_cast<std::size_t>(node.inputs[static_cast<std::size_t>(i)].index),
                      previous);
          }
        }
        previous = layer.size();
      }
    };
    check(network->main, sensors);
    for (std::size_t j = 0; j < network->subnets.size(); ++j) {
      check(network->subnets[j], network->main.layers.back().size());
      ASSERT_EQ(network->joints[j].subnet, static_cast<int>(j));
      for (int node : network->joints[j].nodes)
        ASSERT_LT(static_cast<std::size_t>(node), network->subnets[j].layers.back().size());
      ASSERT_EQ(network->joints[j].strength, creature.body.parts[j + 1].strength);
    }
    ASSERT_NO_THROW(network->build(0.01, sensors, creature.body.effectors.size()));
  }
  EXPECT_GT(with_sensor_nodes, 0);
}

// two 0.4 x 0.4 x 0.1 m slabs side by side, the second on the first's +x face, all constant 0
CreatureGenes restingSlabs(double drive) {
  const BoxGenes slab{{0.4, 0.4, 0.1}, true};
  CreatureGenes genes = twoBoxes(slab, slab, {0, 0, 0}, {1, 0, 0});
  genes.joints[0].limit = {0.5, 0.5, 0.5};
  genes.joints[0].subnet = constants(3, drive);
  return genes;
}

PhysicsSettings wwdPhysics() {
  PhysicsSettings physics;
  physics.self_collision = false;  // "the boxes will not collide with each other"
  return physics;
}

// a passive creature on the ground comes to rest where it was born
TEST(WwdBody, APassiveCreatureRestsOnTheGround) {
  const Creature creature = developCreature(restingSlabs(0), {});
  EXPECT_EQ(creature.body.parts[1].pose.position, (Vec3{0.4, 0, 0}));
  Simulation simulation(creature.body, creature.controller.get(), Environment{}, wwdPhysics());
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  simulation.step(true);
  const Vec3 start = simulation.centerOfMass();
  for (int s = 0; s < 1200; ++s)  // 5 s
    simulation.step(true);
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  const Vec3 moved = simulation.centerOfMass() - start;
  EXPECT_LT(std::hypot(moved.x, moved.y), 1e-3);
  EXPECT_LT(std::abs(moved.z), 1e-3);
  EXPECT_LT(simulation.fastestPartSpeed(), 1e-3);
  EXPECT_LT(simulation.lowestPoint(), 2e-3);
  for (double command : simulation.commands())
    EXPECT_EQ(command, 0);
  // both slabs touch the ground: their pressure sensors say so
  ASSERT_EQ(simulation.sensors().size(), 5u);
  EXPECT_EQ(simulation.sensors()[0], 1.0);
  EXPECT_EQ(simulation.sensors()[1], 1.0);
}

// the network drives the joint: constant subnet nodes of 5 N m against a strength of 2000 x 0.04
// = 80 N m are commands of 5 / 80, and in zero gravity they turn the joint
TEST(WwdBody, TheSubnetDrivesItsJoint) {
  const Creature creature = developCreature(restingSlabs(5), {});
  Environment space;
  space.ground.kind = Ground::Kind::none;
  space.gravity = 0.0;
  Simulation simulation(creature.body, creature.controller.get(), space, wwdPhysics());
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  for (int s = 0; s < 240; ++s)  // 1 s
    simulation.step(true);
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  ASSERT_EQ(simulation.commands().size(), 3u);
  for (double command : simulation.commands())
    EXPECT_DOUBLE_EQ(command, 5.0 / 80);
  double turned = 0;
  for (std::size_t s = 2; s < 5; ++s)  // the joint's three angle sensors
    turned = std::max(turned, std::abs(simulation.sensors()[s]));
  EXPECT_GT(turned, 0.1);
}

}  // namespace
}  // namespace cambrian::wwd
