#include "physics/simulation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace cambrian {
namespace {

// a box part at `position` (creature frame)
PartPlan box(Vec3 size, Vec3 position, int parent = -1) {
  PartPlan part;
  part.size = size;
  part.mass = 1000 * size.x * size.y * size.z;
  part.pose.position = position;
  part.parent = parent;
  return part;
}

// one block with a contact sensor
BodyPlan singleBlock() {
  BodyPlan plan;
  plan.parts.push_back(box({0.2, 0.2, 0.2}, {0, 0, 0}));
  plan.sensors.push_back({SensorKind::contact, 0, 0});
  return plan;
}

// a root block and a hinged child on its +x face; effector 0 reads neuron 0 (a constant)
BodyPlan hinged(double command) {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  PartPlan child = box({0.3, 0.1, 0.1}, {0.35, 0, 0}, 0);
  child.joint = JointType::revolute;
  child.pivot_in_parent = {0.2, 0, 0};
  child.pivot_in_child = {-0.15, 0, 0};
  child.joint_limit = {1.0, 1.0, 1.0};
  child.cross_section = 0.01;
  child.connection = 0;
  plan.parts.push_back(child);
  plan.sensors.push_back({SensorKind::joint_angle, 1, 0});
  plan.sensors.push_back({SensorKind::contact, 0, 0});
  plan.sensors.push_back({SensorKind::contact, 1, 0});
  NeuronPlan constant;
  constant.function = NeuronFunction::constant;
  constant.parameter = command;
  plan.neurons.push_back(constant);
  EffectorPlan effector;
  effector.part = 1;
  effector.dof = 0;
  effector.input = {plan.neuronSignal(0), 1.0};
  plan.effectors.push_back(effector);
  return plan;
}

// a dropped block falls, lands and comes to rest on the ground
TEST(Simulation, DroppedBlockComesToRest) {
  BodyPlan plan = singleBlock();
  PhysicsSettings settings;
  Simulation simulation(plan, settings, {10, 0, 0}, 0.5);
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
  EXPECT_EQ(simulation.partContacts()[0], 1);
}

// a creature is born resting on the ground, not above or inside it
TEST(Simulation, BornOnTheGround) {
  BodyPlan plan = hinged(0);
  Simulation simulation(plan, PhysicsSettings{});
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_NEAR(simulation.lowestPoint(), 0.0, 1e-12);
}

// parts that overlap at birth are rejected with a status, not simulated
TEST(Simulation, SelfPenetrationAtBirth) {
  BodyPlan plan = hinged(0);
  PartPlan twin = plan.parts[1];
  plan.parts.push_back(twin);  // a sibling exactly where the first child is
  Simulation simulation(plan, PhysicsSettings{});
  EXPECT_EQ(simulation.status(), EvalStatus::self_penetration);
  EXPECT_NE(simulation.message().find("overlap"), std::string::npos);
  simulation.step(true);
  EXPECT_EQ(simulation.steps(), 0u);
}

// a driven joint moves the child, and the joint-angle sensor reports it
TEST(Simulation, EffectorMovesJoint) {
  BodyPlan plan = hinged(1.0);
  PhysicsSettings settings;
  Simulation simulation(plan, settings);
  for (int s = 0; s < 240; ++s)
    simulation.step(true);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_GT(std::abs(simulation.brain().signals()[0]), 0.05);
}

// a saturated motor drives its joint no faster than the motor speed
TEST(Simulation, SaturatedMotorKeepsToItsSpeed) {
  BodyPlan plan = hinged(1.0);
  PhysicsSettings settings;
  settings.gravity = 0;
  settings.motor_speed = 1.0;
  Simulation simulation(plan, settings);
  double previous = 0;
  for (int s = 0; s < 120; ++s) {
    simulation.step(true);
    double angle = simulation.brain().signals()[0];  // joint angle / limit, limit = 1 rad
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
    BodyPlan plan = hinged(c == 0 ? 1e-4 : 1.0);
    PhysicsSettings settings;
    settings.gravity = 0;
    settings.motor_speed = 1.0;
    Simulation simulation(plan, settings);
    for (int s = 0; s < 120; ++s)
      simulation.step(true);
    ASSERT_EQ(simulation.status(), EvalStatus::ok);
    angle[c] = std::abs(simulation.brain().signals()[0]);
  }
  EXPECT_LT(angle[0], 0.05);
  EXPECT_GT(angle[1], 0.4);
}

// under saturated motors even an absurd strength cannot push a joint past the motor speed,
// so the body stays finite
TEST(Simulation, SaturatedMotorWithAbsurdStrengthStaysFinite) {
  BodyPlan plan = hinged(1.0);
  PhysicsSettings settings;
  settings.strength_per_area = 1e12;
  Simulation simulation(plan, settings);
  for (int s = 0; s < 2400; ++s)
    simulation.step(true);
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
}

// an absurdly strong explicit torque breaks the physics and is caught as a status, not a crash
TEST(Simulation, ExplosionIsCaught) {
  BodyPlan plan = hinged(1.0);
  PhysicsSettings settings;
  settings.actuation = Actuation::torque;
  settings.strength_per_area = 1e12;
  Simulation simulation(plan, settings);
  for (int s = 0; s < 2400 && simulation.status() == EvalStatus::ok; ++s)
    simulation.step(true);
  // the speed monitor sees it before any state turns non-finite
  EXPECT_EQ(simulation.status(), EvalStatus::exploded) << statusName(simulation.status());
  EXPECT_NE(simulation.message().find("physics.max_speed"), std::string::npos)
      << simulation.message();
}

// a non-finite state is caught as non_finite (not exploded) on the step it appears, and
// stepping then stops; NaN gravity makes every part's position NaN after one step
TEST(Simulation, NonFiniteStateIsCaught) {
  BodyPlan plan = hinged(0.5);
  PhysicsSettings settings;
  settings.gravity = std::nan("");
  Simulation simulation(plan, settings);
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
  BodyPlan plan = hinged(0.7);
  std::vector<Transform> first, second;
  for (auto* poses : {&first, &second}) {
    Simulation simulation(plan, PhysicsSettings{});
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

}  // namespace
}  // namespace cambrian
