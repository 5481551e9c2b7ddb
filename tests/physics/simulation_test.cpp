// Tests of a creature in a world: birth, rest, actuation, the monitors, determinism.
#include "physics/simulation.hpp"

#include "brain/neural_network.hpp"
#include "physics/box_part.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace cambrian {
namespace {

using test::box;

// a body and the network that drives it
struct TestCreature {
  BodyPlan plan;
  std::shared_ptr<NeuralNetworkPlan> network = std::make_shared<NeuralNetworkPlan>();
};

// a creature in a world on the plane
struct Sim {
  Environment environment;
  Simulation simulation;
  Sim(const TestCreature& c, const PhysicsSettings& settings, double birth_height = 0)
      : simulation(c.plan, c.network.get(), environment, settings, birth_height) {}
};

// one block with a contact sensor
TestCreature singleBlock() {
  TestCreature creature;
  BodyPlan& plan = creature.plan;
  plan.parts.push_back(box({0.2, 0.2, 0.2}, {0, 0, 0}));
  plan.sensors.push_back({SensorKind::contact, 0, 0});
  creature.network->sensor_count = 1;
  return creature;
}

// a root block and a hinged child on its +x face (sensors: joint angle, two contacts);
// effector 0 reads neuron 0 (a constant)
TestCreature hinged(double command) {
  TestCreature creature;
  BodyPlan& plan = creature.plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  plan.parts.push_back(test::hingedChild());
  plan.sensors.push_back({SensorKind::joint_angle, 1, 0});
  plan.sensors.push_back({SensorKind::contact, 0, 0});
  plan.sensors.push_back({SensorKind::contact, 1, 0});
  NeuronPlan constant;
  constant.function = NeuronFunction::constant;
  constant.parameter = command;
  creature.network->sensor_count = plan.sensors.size();
  creature.network->neurons.push_back(constant);
  plan.effectors.push_back(EffectorPlan{1, 0});
  creature.network->effector_inputs.push_back({creature.network->neuronSignal(0), 1.0});
  return creature;
}

// a dropped block falls, lands and comes to rest on the ground
TEST(Simulation, DroppedBlockComesToRest) {
  TestCreature creature = singleBlock();
  PhysicsSettings settings;
  Sim sim(creature, settings, 0.5);
  Simulation& simulation = sim.simulation;
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_NEAR(simulation.lowestPoint(), 0.5, 1e-9);
  for (int s = 0; s < 480; ++s)
    simulation.step(false);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  Vec3 before = simulation.centerOfMass();
  for (int s = 0; s < 240; ++s)
    simulation.step(false);
  Vec3 after = simulation.centerOfMass();
  EXPECT_NEAR(simulation.lowestPoint(), 0.0, 2e-3);
  EXPECT_NEAR(after.z, 0.1, 2e-3);
  EXPECT_LT(norm(after - before), 1e-4);
  EXPECT_EQ(simulation.sensors()[0], 1.0);  // the contact sensor
}

// a creature is born resting on the ground, not above or inside it
TEST(Simulation, BornOnTheGround) {
  TestCreature creature = hinged(0);
  Sim sim(creature, PhysicsSettings{});
  Simulation& simulation = sim.simulation;
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_NEAR(simulation.lowestPoint(), 0.0, 1e-12);
}

// parts that overlap at birth are rejected with a status, not simulated
TEST(Simulation, SelfPenetrationAtBirth) {
  TestCreature creature = hinged(0);
  PartPlan twin = creature.plan.parts[1];
  creature.plan.parts.push_back(twin);  // a sibling exactly where the first child is
  Sim sim(creature, PhysicsSettings{});
  Simulation& simulation = sim.simulation;
  EXPECT_EQ(simulation.status(), EvalStatus::self_penetration);
  EXPECT_NE(simulation.message().find("overlap"), std::string::npos);
  simulation.step(true);
  EXPECT_EQ(simulation.steps(), 0u);
}

// a driven joint moves the child, and the joint-angle sensor reports it
TEST(Simulation, EffectorMovesJoint) {
  TestCreature creature = hinged(1.0);
  PhysicsSettings settings;
  Sim sim(creature, settings);
  Simulation& simulation = sim.simulation;
  for (int s = 0; s < 240; ++s)
    simulation.step(true);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_GT(std::abs(simulation.sensors()[0]), 0.05);
}

// a saturated motor drives its joint no faster than the motor speed
TEST(Simulation, SaturatedMotorKeepsToItsSpeed) {
  TestCreature creature = hinged(1.0);
  PhysicsSettings settings;
  settings.gravity = 0;
  settings.motor_speed = 1.0;
  Sim sim(creature, settings);
  Simulation& simulation = sim.simulation;
  double previous = 0;
  for (int s = 0; s < 120; ++s) {
    simulation.step(true);
    double angle = simulation.sensors()[0];  // joint angle / limit, limit = 1 rad
    EXPECT_LE(std::abs(angle - previous), 1.02 * settings.motor_speed * settings.time_step)
        << "step " << s;
    previous = angle;
  }
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_GT(std::abs(previous), 0.4);  // it did move, close to 0.5 s at 1 rad/s
}

// a saturated motor's torque is bounded by |command| * strength: without gravity, a weak
// command barely turns the limb in half a second, a full one reaches the motor speed
TEST(Simulation, SaturatedMotorTorqueFollowsTheCommand) {
  std::array<double, 2> angle{};
  for (int c = 0; c < 2; ++c) {
    TestCreature creature = hinged(c == 0 ? 1e-4 : 1.0);
    PhysicsSettings settings;
    settings.gravity = 0;
    settings.motor_speed = 1.0;
    Sim sim(creature, settings);
    Simulation& simulation = sim.simulation;
    for (int s = 0; s < 120; ++s)
      simulation.step(true);
    ASSERT_EQ(simulation.status(), EvalStatus::ok);
    angle[c] = std::abs(simulation.sensors()[0]);
  }
  EXPECT_LT(angle[0], 0.05);
  EXPECT_GT(angle[1], 0.4);
}

// under saturated motors even an absurd strength cannot push a joint past the motor speed,
// so the body stays finite
TEST(Simulation, SaturatedMotorWithAbsurdStrengthStaysFinite) {
  TestCreature creature = hinged(1.0);
  PhysicsSettings settings;
  settings.strength_per_area = 1e12;
  Sim sim(creature, settings);
  Simulation& simulation = sim.simulation;
  for (int s = 0; s < 2400; ++s)
    simulation.step(true);
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
}

// an absurdly strong explicit torque breaks the physics and is caught as a status, not a crash:
// with the joint held to Bullet's old speed clamp (100 rad/s) by the energy watch, by the speed
// monitor when the watch is off, and by the speed monitor at the first step with the clamp out of
// reach (the default)
TEST(Simulation, ExplosionIsCaught) {
  TestCreature creature = hinged(1.0);
  PhysicsSettings settings;
  settings.actuation = Actuation::torque;
  settings.strength_per_area = 1e12;
  Sim unclamped(creature, settings);
  unclamped.simulation.step(true);
  EXPECT_EQ(unclamped.simulation.status(), EvalStatus::exploded);
  EXPECT_NE(unclamped.simulation.message().find("physics.max_speed"), std::string::npos)
      << unclamped.simulation.message();
  settings.joint_speed_clamp = 100;
  Sim watched(creature, settings);
  for (int s = 0; s < 2400 && watched.simulation.status() == EvalStatus::ok; ++s)
    watched.simulation.step(true);
  EXPECT_EQ(watched.simulation.status(), EvalStatus::exploded);
  EXPECT_NE(watched.simulation.message().find("physics.max_energy_gain"), std::string::npos)
      << watched.simulation.message();
  settings.max_energy_gain = 0;
  Sim sim(creature, settings);
  Simulation& simulation = sim.simulation;
  for (int s = 0; s < 2400 && simulation.status() == EvalStatus::ok; ++s)
    simulation.step(true);
  // the speed monitor sees it before any state turns non-finite
  EXPECT_EQ(simulation.status(), EvalStatus::exploded) << statusName(simulation.status());
  EXPECT_NE(simulation.message().find("physics.max_speed"), std::string::npos)
      << simulation.message();
}

// a joint turning faster than physics.max_joint_speed ends the evaluation as exploded (Minemonics'
// discard), naming the joint; below the limit nothing happens. The saturated motor drives the
// hinge towards physics.motor_speed = 10 rad/s until the joint limit stops it.
TEST(Simulation, AJointFasterThanMaxJointSpeedHasExploded) {
  TestCreature creature = hinged(1.0);
  PhysicsSettings settings;
  settings.strength_per_area = 1e6;
  settings.motor_speed = 10;
  settings.max_joint_speed = 11;
  Sim calm(creature, settings);
  double fastest = 0;
  for (int s = 0; s < 240; ++s) {
    calm.simulation.step(true);
    fastest = std::max(fastest, calm.simulation.world().fastestJoint().speed);
  }
  EXPECT_EQ(calm.simulation.status(), EvalStatus::ok) << calm.simulation.message();
  EXPECT_GT(fastest, 5);
  EXPECT_LE(fastest, 11);
  EXPECT_EQ(calm.simulation.world().fastestJoint().part, 1);

  settings.max_joint_speed = 5;
  Sim fast(creature, settings);
  for (int s = 0; s < 240 && fast.simulation.status() == EvalStatus::ok; ++s)
    fast.simulation.step(true);
  EXPECT_EQ(fast.simulation.status(), EvalStatus::exploded);
  EXPECT_NE(fast.simulation.message().find("the joint of part 1 (degree of freedom 0)"),
            std::string::npos)
      << fast.simulation.message();
  EXPECT_NE(fast.simulation.message().find("physics.max_joint_speed 5"), std::string::npos)
      << fast.simulation.message();
}

// a non-finite state is caught as non_finite (not exploded) on the step it appears, and
// stepping then stops; NaN gravity makes every part's position NaN after one step
TEST(Simulation, NonFiniteStateIsCaught) {
  TestCreature creature = hinged(0.5);
  PhysicsSettings settings;
  settings.gravity = std::nan("");
  Sim sim(creature, settings);
  Simulation& simulation = sim.simulation;
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  simulation.step(true);
  EXPECT_EQ(simulation.status(), EvalStatus::non_finite) << simulation.message();
  EXPECT_EQ(simulation.message(), "part 0 has a non-finite position");
  EXPECT_FALSE(std::isfinite(simulation.centerOfMass().z));
  simulation.step(true);
  EXPECT_EQ(simulation.steps(), 1u);
}

// the same plan simulated twice in one process gives bit-identical states
TEST(Simulation, Deterministic) {
  TestCreature creature = hinged(0.7);
  std::vector<Transform> first, second;
  for (auto* poses : {&first, &second}) {
    Sim sim(creature, PhysicsSettings{});
    Simulation& simulation = sim.simulation;
    for (int s = 0; s < 500; ++s)
      simulation.step(true);
    simulation.partPoses(*poses);
  }
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].position, second[i].position);
    EXPECT_EQ(first[i].rotation, second[i].rotation);
  }
}

// the controller's drives become commands clamped to [-1, 1]; off, nothing is commanded
TEST(Simulation, DrivesAreClampedIntoCommands) {
  TestCreature creature = hinged(7.5);
  Sim sim(creature, PhysicsSettings{});
  Simulation& simulation = sim.simulation;
  simulation.step(false);
  EXPECT_EQ(simulation.commands()[0], 0.0);
  simulation.step(true);
  EXPECT_EQ(simulation.commands()[0], 1.0);
  ASSERT_NE(simulation.controller(), nullptr);
}

// a creature without a controller lives, its joints undriven
TEST(Simulation, NoControllerDrivesNothing) {
  TestCreature creature = hinged(1.0);
  Environment environment;
  Simulation simulation(creature.plan, nullptr, environment, PhysicsSettings{});
  for (int s = 0; s < 120; ++s)
    simulation.step(true);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_EQ(simulation.controller(), nullptr);
  EXPECT_LT(std::abs(simulation.sensors()[0]), 0.05);
}

// the photosensors point at the environment's light
TEST(Simulation, PhotosensorsPointAtTheLight) {
  TestCreature creature = singleBlock();
  creature.plan.sensors.push_back({SensorKind::photo, 0, 0});
  creature.plan.sensors.push_back({SensorKind::photo, 0, 1});
  creature.network->sensor_count = 3;
  Environment environment;
  environment.light = {0, 10, 0.1};
  Simulation simulation(creature.plan, creature.network.get(), environment, PhysicsSettings{});
  simulation.step(false);
  EXPECT_NEAR(simulation.sensors()[1], 0.0, 1e-6);
  EXPECT_NEAR(simulation.sensors()[2], 1.0, 1e-3);
}

// a block resting on the ground: its contact sensor reads 1, and of its six face sensors only
// the bottom face (-z, face 5) reads 1, the others -1; a block lying on its +x face reads face 0
TEST(Simulation, ContactSensorsPerFaceSeeTheTouchingFace) {
  for (const bool on_side : {false, true}) {
    BodyPlan plan;
    plan.parts.push_back(box({0.3, 0.2, 0.1}, {0, 0, 0}));
    if (on_side)
      plan.parts[0].pose.rotation = quatFromEuler({0, kPi / 2, 0});  // +x points down
    plan.sensors.push_back({SensorKind::contact, 0, 0});
    for (int face = 0; face < 6; ++face)
      plan.sensors.push_back({SensorKind::contact_face, 0, face});
    Environment environment;
    Simulation simulation(plan, nullptr, environment, PhysicsSettings{});
    ASSERT_EQ(simulation.status(), EvalStatus::ok);
    for (int s = 0; s < 60; ++s)
      simulation.step(false);
    simulation.step(false);
    const std::vector<double>& seen = simulation.sensors();
    EXPECT_EQ(seen[0], 1.0);
    const int touching = on_side ? 0 : 5;
    for (int face = 0; face < 6; ++face)
      EXPECT_EQ(seen[1 + face], face == touching ? 1.0 : -1.0) << "face " << face;
  }
}

// each photosensor sees the light's direction in its own part's frame, and follows the light
// when it moves: a root turned 90 degrees about z (its x axis along world y) and a child
// turned 90 degrees about y, in a world without gravity so nothing moves
TEST(Simulation, PhotosensorsSeeTheLightFromTheirPart) {
  BodyPlan plan;
  plan.parts.push_back(box({0.2, 0.2, 0.2}, {0, 0, 0}));
  plan.parts[0].pose.rotation = quatFromEuler({0, 0, kPi / 2});
  PartPlan child = box({0.1, 0.1, 0.1}, {0, 0.15, 0}, 0);  // fixed to the root's +x face
  child.pose.rotation = quatFromEuler({0, kPi / 2, 0});
  child.parent_to_child = conjugate(plan.parts[0].pose.rotation) * child.pose.rotation;
  child.pivot_in_parent = {0.1, 0, 0};
  child.pivot_in_child = {0, -0.05, 0};
  plan.parts.push_back(child);
  for (int part : {0, 1})
    for (int axis : {0, 1, 2})
      plan.sensors.push_back({SensorKind::photo, part, axis});
  PhysicsSettings physics;
  Environment environment;
  environment.gravity = 0;
  Simulation simulation(plan, nullptr, environment, physics);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  const Vec3 root = simulation.world().partPosition(0);
  const Vec3 other = simulation.world().partPosition(1);

  // straight along world +y from the root: the root's own +x
  simulation.moveLight(root + Vec3{0, 5, 0});
  simulation.step(false);
  const std::vector<double>& seen = simulation.sensors();
  EXPECT_NEAR(seen[0], 1, 1e-12);
  EXPECT_NEAR(seen[1], 0, 1e-12);
  EXPECT_NEAR(seen[2], 0, 1e-12);

  // 3 m along -x and 4 m up: (-0.6, 0, 0.8) in the world, (0, 0.6, 0.8) in the root's frame
  simulation.moveLight(root + Vec3{-3, 0, 4});
  simulation.step(false);
  EXPECT_NEAR(seen[0], 0, 1e-12);
  EXPECT_NEAR(seen[1], 0.6, 1e-12);
  EXPECT_NEAR(seen[2], 0.8, 1e-12);

  // the child (pitched 90 degrees: its x axis along world -z) sees a light straight above it
  // along its own -x
  simulation.moveLight(other + Vec3{0, 0, 2});
  simulation.step(false);
  EXPECT_NEAR(seen[3], -1, 1e-12);
  EXPECT_NEAR(seen[4], 0, 1e-12);
  EXPECT_NEAR(seen[5], 0, 1e-12);
}

}  // namespace
}  // namespace cambrian

namespace cambrian {
namespace {

// a block on a vertical slider falls onto a block fixed beside it on the same root: one hit
// between the creature's own parts, over a limit of 0 per second and within one of 5
TEST(Simulation, PartsHittingEachOtherTooOftenGiveSelfContact) {
  BodyPlan plan;
  plan.parts.push_back(test::box({1, 1, 0.1}, {0, 0, 0}));
  PartPlan falling = test::box({0.2, 0.2, 0.2}, {0.3, 0, 0.55}, 0);
  falling.joint = JointType::prismatic;
  falling.axes = {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  falling.pivot_in_parent = {0.3, 0, 0.55};
  falling.joint_limit = {1, 0, 0};
  plan.parts.push_back(falling);
  PartPlan fixed = test::box({0.2, 0.2, 0.2}, {0.3, 0, 0.15}, 0);
  fixed.pivot_in_parent = {0.3, 0, 0.15};
  plan.parts.push_back(fixed);
  PhysicsSettings physics;
  physics.world = "rigid_bodies";
  physics.max_contact_rate = 0;
  Simulation strict(plan, nullptr, Environment{}, physics);
  ASSERT_EQ(strict.status(), EvalStatus::ok) << strict.message();
  for (int s = 0; s < 300; ++s)
    strict.step(false);
  EXPECT_EQ(strict.status(), EvalStatus::self_contact);
  EXPECT_NE(strict.message().find("hit each other 1 times"), std::string::npos) << strict.message();
  physics.max_contact_rate = 5;
  Simulation lenient(plan, nullptr, Environment{}, physics);
  for (int s = 0; s < 300; ++s)
    lenient.step(false);
  EXPECT_EQ(lenient.status(), EvalStatus::ok) << lenient.message();
}

// a hinged body flapping its child up and down at 2 Hz, in `world`
TestCreature flapping() {
  TestCreature creature = hinged(1.0);
  creature.plan.parts[1].axes = {Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}};
  creature.network->neurons[0].function = NeuronFunction::oscillate_wave;
  creature.network->neurons[0].parameter = 2;
  return creature;
}

// how far the centre of mass moves horizontally in `steps` steps
double horizontalTravel(Simulation& simulation, int steps) {
  const Vec3 start = simulation.centerOfMass();
  for (int s = 0; s < steps; ++s)
    simulation.step(true);
  const Vec3 end = simulation.centerOfMass();
  return std::hypot(end.x - start.x, end.y - start.y);
}

// Walking with Dinosaurs' relaxation needs a frictionless ground and the friction back after it:
// flapping on a frictionless ground the body's centre of mass stays over its place (nothing
// pushes it sideways) — exactly in the rigid-body world, within the Featherstone integrator's
// momentum drift (physics.momentum_correction's note: 7 mm in 4 s here) — and with the ground's
// friction given back it travels, in both worlds
TEST(Simulation, TheGroundsFrictionIsSwitchedOffAndBack) {
  for (const auto& [world, drift] :
       {std::pair{"featherstone", 0.02}, std::pair{"rigid_bodies", 1e-9}}) {
    SCOPED_TRACE(world);
    PhysicsSettings settings;
    settings.world = world;
    const TestCreature creature = flapping();
    Sim frictionless(creature, settings);
    frictionless.simulation.setGroundFriction(0);
    const double sliding = horizontalTravel(frictionless.simulation, 960);
    Sim gripping(creature, settings);
    gripping.simulation.setGroundFriction(0);
    horizontalTravel(gripping.simulation, 240);
    gripping.simulation.setGroundFriction(settings.ground_friction);
    const double walking = horizontalTravel(gripping.simulation, 720);
    ASSERT_EQ(frictionless.simulation.status(), EvalStatus::ok);
    ASSERT_EQ(gripping.simulation.status(), EvalStatus::ok);
    EXPECT_LT(sliding, drift);
    EXPECT_GT(walking, 3 * sliding);
    EXPECT_GT(walking, 0.02);
  }
}

// a body's height: its highest point above its lowest, boxes turned included
TEST(Simulation, HeightIsFromTheLowestPointToTheHighest) {
  BodyPlan plan;
  plan.parts.push_back(box({0.2, 0.2, 1.5}, {0, 0, 0}));
  PartPlan on_top = box({0.2, 0.2, 0.2}, {0, 0, 0.85}, 0);
  on_top.pivot_in_parent = {0, 0, 0.75};
  on_top.pivot_in_child = {0, 0, -0.1};
  plan.parts.push_back(on_top);
  const Environment environment;
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{});
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  EXPECT_NEAR(simulation.height(), 1.7, 1e-9);
}

// dismemberment, in both worlds: a joint carrying more than physics.joint_breaking x its
// strength breaks and the evaluation ends dismembered, naming the part; a strong enough joint,
// or no breaking, holds the same load
TEST(Simulation, AJointCarryingMoreThanItsBreakingLoadBreaks) {
  for (const char* world : {"rigid_bodies", "featherstone"}) {
    SCOPED_TRACE(world);
    // a 1 m cube standing on the ground, a child on a ball joint held out level from the top of
    // its +x face by the limits
    BodyPlan plan;
    plan.parts.push_back(box({1.0, 1.0, 1.0}, {0, 0, 0}));
    PartPlan child = test::hingedChild();
    child.joint = JointType::spherical;
    child.pose.position = {0.65, 0, 0.45};
    child.pivot_in_parent = {0.5, 0, 0.45};
    child.joint_limit = {0.01, 0.01, 0.01};
    plan.parts.push_back(child);
    PhysicsSettings physics;
    physics.world = world;
    physics.joint_breaking = 1.05;
    // the limit holds the child's weight, 3 kg x 9.81 m/s^2 x 0.15 m = 4.4 N m, at a 0.002 N m
    // joint
    plan.parts[1].strength = 0.002;
    const Environment environment;
    Simulation weak(plan, nullptr, environment, physics);
    ASSERT_EQ(weak.status(), EvalStatus::ok) << weak.message();
    for (int s = 0; s < 240 && weak.status() == EvalStatus::ok; ++s)
      weak.step(false);
    EXPECT_EQ(weak.status(), EvalStatus::dismembered);
    EXPECT_NE(weak.message().find("the joint of part 1"), std::string::npos) << weak.message();
    EXPECT_NE(weak.message().find("physics.joint_breaking"), std::string::npos) << weak.message();
    // 1000 N m holds it
    plan.parts[1].strength = 1000;
    Simulation strong(plan, nullptr, environment, physics);
    for (int s = 0; s < 240; ++s)
      strong.step(false);
    EXPECT_EQ(strong.status(), EvalStatus::ok) << strong.message();
    // without breaking the weak joint holds too
    plan.parts[1].strength = 0.002;
    physics.joint_breaking = 0;
    Simulation unbreakable(plan, nullptr, environment, physics);
    for (int s = 0; s < 240; ++s)
      unbreakable.step(false);
    EXPECT_EQ(unbreakable.status(), EvalStatus::ok) << unbreakable.message();
  }
}

}  // namespace
}  // namespace cambrian
