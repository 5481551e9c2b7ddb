// Tests of the constrained rigid-body world against the Featherstone world: the same plan gives
// the same masses, inertias, poses, joint axes and limits; joint coordinates mean the same chain
// of rotations in both; motors and torques turn the same way; a closed loop holds; a passive body
// rests; a held object is carried until released; the same run gives the same bits.
#include "physics/rigid_body_world.hpp"

#include "box_part.hpp"
#include "physics/featherstone_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace cambrian {
namespace {

using test::box;

// the develop step's joint axes: y, z, x (twist)
constexpr std::array<Vec3, 3> kAxes{Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}};

// a limb along x from a root: a hinge, a universal joint and a spherical joint in a chain off the
// root's +x face, a slider off its -x face; an effector on every degree of freedom
BodyPlan limb() {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  plan.parts.push_back(test::hingedChild());
  const JointType chain[] = {JointType::universal, JointType::spherical};
  for (int k = 0; k < 2; ++k) {
    PartPlan part = box({0.3, 0.1, 0.1}, {0.65 + 0.3 * k, 0, 0}, k + 1);
    part.joint = chain[k];
    part.pivot_in_parent = {0.15, 0, 0};
    part.pivot_in_child = {-0.15, 0, 0};
    part.joint_limit = {0.8, 0.6, 0.7};
    part.cross_section = 0.01;
    plan.parts.push_back(part);
  }
  PartPlan slider = box({0.2, 0.1, 0.1}, {-0.3, 0, 0}, 0);
  slider.joint = JointType::prismatic;
  slider.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  slider.pivot_in_parent = {-0.2, 0, 0};
  slider.pivot_in_child = {0.1, 0, 0};
  slider.joint_limit = {0.05, 0, 0};
  slider.cross_section = 0.01;
  plan.parts.push_back(slider);
  for (std::size_t i = 1; i < plan.parts.size(); ++i) {
    if (plan.parts[i].joint != JointType::prismatic)
      plan.parts[i].axes = kAxes;
    for (int d = 0; d < degreesOfFreedom(plan.parts[i].joint); ++d)
      plan.effectors.push_back({static_cast<int>(i), d, EffectorKind::joint});
  }
  return plan;
}

std::unique_ptr<World> build(const std::string& kind, const BodyPlan& plan,
                             const Environment& environment, const PhysicsSettings& physics,
                             double height = 0) {
  PhysicsSettings chosen = physics;
  chosen.world = kind;
  return makeWorld(plan, environment, chosen, height);
}

Environment weightless() {
  Environment environment;
  environment.ground.kind = Ground::Kind::none;
  environment.gravity = 0.0;
  return environment;
}

double distance(Vec3 a, Vec3 b) {
  return norm(a - b);
}

// a rotation by `angle` about the unit `axis`
Quat about(Vec3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), axis.x * s, axis.y * s, axis.z * s};
}

const char* const kWorlds[] = {FeatherstoneWorld::kName, RigidBodyWorld::kName};

TEST(RigidBodyWorld, IsRegistered) {
  EXPECT_NE(worldNamesText().find("rigid_bodies"), std::string::npos);
}

// masses, inertias, poses at birth, joint axes and the lowest point agree with Featherstone's
TEST(RigidBodyWorld, BuildsTheSameMorphologyAsFeatherstone) {
  const BodyPlan plan = limb();
  const Environment environment;
  const PhysicsSettings physics;
  auto multibody = build(FeatherstoneWorld::kName, plan, environment, physics, 0.2);
  auto rigid = build(RigidBodyWorld::kName, plan, environment, physics, 0.2);
  ASSERT_EQ(rigid->birthStatus(), EvalStatus::ok) << rigid->birthMessage();
  EXPECT_NEAR(rigid->lowestPoint(), multibody->lowestPoint(), 1e-12);
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const int part = static_cast<int>(i);
    EXPECT_NEAR(rigid->partMass(part), multibody->partMass(part), 1e-12) << part;
    EXPECT_NEAR(rigid->partMass(part), plan.parts[i].mass, 1e-12) << part;
    EXPECT_LT(distance(rigid->partInertia(part), multibody->partInertia(part)), 1e-12) << part;
    EXPECT_LT(distance(rigid->partPosition(part), multibody->partPosition(part)), 1e-12) << part;
    for (int d = 0; d < 3; ++d) {
      EXPECT_LT(distance(rigid->jointAxis(part, d), multibody->jointAxis(part, d)), 1e-12)
          << part << " " << d;
      EXPECT_NEAR(rigid->jointPosition(part, d), 0, 1e-12);
    }
  }
  EXPECT_NEAR(rigid->mechanicalEnergy(), multibody->mechanicalEnergy(),
              1e-9 + 0.25 * multibody->mechanicalEnergy());  // Featherstone's virtual links
}

// after the joints have moved, each world's joint coordinates compose its parts' rotations the
// same way: child = parent x parent_to_child x R(axis 0, q0) x R(axis 1, q1) x R(axis 2, q2);
// the first axis is fixed in the parent, the last in the child
TEST(RigidBodyWorld, JointCoordinatesAreTheFeatherstoneChain) {
  const BodyPlan plan = limb();
  const Environment environment = weightless();
  const PhysicsSettings physics;
  const std::vector<double> commands{0.6, -0.5, 0.4, 0.3, -0.6, 0.5, 0.2};
  for (const char* kind : kWorlds) {
    // (the constraints of the rigid bodies are soft: their joints give by a little)
    const double tolerance = kind == std::string(RigidBodyWorld::kName) ? 1e-3 : 1e-6;
    auto world = build(kind, plan, environment, physics);
    for (int s = 0; s < 30; ++s)
      world->step(commands);
    for (std::size_t i = 1; i < plan.parts.size(); ++i) {
      const PartPlan& part = plan.parts[i];
      if (part.joint == JointType::prismatic)
        continue;
      const int p = static_cast<int>(i);
      Quat predicted = world->partPose(part.parent).rotation * part.parent_to_child;
      for (int d = 0; d < degreesOfFreedom(part.joint); ++d)
        predicted = predicted * about(part.axes[d], world->jointPosition(p, d));
      const Quat actual = world->partPose(p).rotation;
      const double alignment = std::abs(predicted.w * actual.w + predicted.x * actual.x +
                                        predicted.y * actual.y + predicted.z * actual.z);
      EXPECT_GT(alignment, 1 - tolerance) << kind << " part " << p;
      EXPECT_GT(std::abs(world->jointPosition(p, 0)), 0.05) << kind << " part " << p;
      const Quat parent_frame = world->partPose(part.parent).rotation * part.parent_to_child;
      EXPECT_LT(distance(world->jointAxis(p, 0), rotate(parent_frame, part.axes[0])), tolerance)
          << kind << " part " << p;
      const int last = degreesOfFreedom(part.joint) - 1;
      EXPECT_LT(distance(world->jointAxis(p, last), rotate(actual, part.axes[last])), tolerance)
          << kind << " part " << p;
    }
  }
}

// full commands one way, then the other: motors take every degree of freedom to its limit in both
// worlds (the spherical joint's middle one too: physics.solve_every_dof); explicit torques turn
// each the same way, past half its limit
TEST(RigidBodyWorld, MotorsAndTorquesDriveEveryJointToItsLimits) {
  const BodyPlan plan = limb();
  const Environment environment = weightless();
  for (Actuation actuation : {Actuation::saturated_motor, Actuation::torque}) {
    PhysicsSettings physics;
    physics.actuation = actuation;
    for (const char* kind : kWorlds) {
      auto world = build(kind, plan, environment, physics);
      for (double sign : {1.0, -1.0}) {
        const std::vector<double> commands(plan.effectors.size(), sign);
        for (int s = 0; s < 480; ++s)
          world->step(commands);
        for (const EffectorPlan& effector : plan.effectors) {
          const PartPlan& part = plan.parts[effector.part];
          const double limit = part.joint_limit[effector.dof];
          const double at = world->jointPosition(effector.part, effector.dof);
          const std::string what =
              std::string(kind) + (actuation == Actuation::torque ? " torque" : " motor") +
              " part " + std::to_string(effector.part) + " dof " + std::to_string(effector.dof);
          if (actuation == Actuation::saturated_motor)
            EXPECT_NEAR(at, sign * limit, 0.06 * limit) << what;
          else
            EXPECT_GT(sign * at, 0.5 * limit) << what;
          // (a constant explicit torque settles past the limit where the limit's position
          // correction balances it: 13 % for the Featherstone spherical joint's twist)
          EXPECT_LT(std::abs(at), (actuation == Actuation::torque ? 1.15 : 1.06) * limit) << what;
        }
      }
    }
  }
}

// a parallelogram of four bars on the ground, its fourth hinge a loop joint: Featherstone
// refuses it; here, without gravity, the loop's two pivots stay together while a motor shears
// the frame
BodyPlan parallelogram() {
  BodyPlan plan;
  plan.parts.push_back(box({1.0, 0.1, 0.1}, {0, 0, 0}));
  auto bar = [&](Vec3 size, Vec3 at, int parent, Vec3 in_parent, Vec3 in_child) {
    PartPlan part = box(size, at, parent);
    part.joint = JointType::revolute;
    part.axes = {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
    part.pivot_in_parent = in_parent;
    part.pivot_in_child = in_child;
    part.joint_limit = {1.0, 0, 0};
    part.cross_section = 0.01;
    plan.parts.push_back(part);
  };
  bar({0.1, 0.6, 0.1}, {-0.45, 0.35, 0}, 0, {-0.45, 0.05, 0}, {0, -0.3, 0});
  bar({1.0, 0.1, 0.1}, {0, 0.7, 0}, 1, {0, 0.3, 0}, {-0.45, -0.05, 0});
  bar({0.1, 0.6, 0.1}, {0.45, 0.35, 0}, 2, {0.45, -0.05, 0}, {0, 0.3, 0});
  LoopJoint loop;
  loop.part_a = 0;
  loop.part_b = 3;
  loop.joint = JointType::revolute;
  loop.pivot_in_a = {0.45, 0.05, 0};
  loop.pivot_in_b = {0, -0.3, 0};
  loop.axes = {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  loop.joint_limit = {1.0, 0, 0};
  plan.loops.push_back(loop);
  plan.effectors.push_back({1, 0, EffectorKind::joint});
  return plan;
}

TEST(RigidBodyWorld, AClosedLoopHoldsWhileTheFrameMoves) {
  const BodyPlan plan = parallelogram();
  const Environment environment = weightless();
  const PhysicsSettings physics;
  auto multibody = build(FeatherstoneWorld::kName, plan, environment, physics);
  EXPECT_EQ(multibody->birthStatus(), EvalStatus::invalid_body);
  auto world = build(RigidBodyWorld::kName, plan, environment, physics);
  ASSERT_EQ(world->birthStatus(), EvalStatus::ok) << world->birthMessage();
  const LoopJoint& loop = plan.loops[0];
  double widest = 0;
  for (int s = 0; s < 480; ++s) {
    world->step(std::vector<double>{0.5});
    const Vec3 a = apply(world->partPose(0), loop.pivot_in_a);
    const Vec3 b = apply(world->partPose(3), loop.pivot_in_b);
    widest = std::max(widest, distance(a, b));
  }
  EXPECT_LT(widest, 2e-3);
  // the frame sheared: both uprights turned alike (a parallelogram)
  EXPECT_GT(world->jointPosition(1, 0), 0.3);
  EXPECT_NEAR(world->partPose(1).rotation.z, world->partPose(3).rotation.z, 0.02);
}

// the joint error is the widest gap between the two pivots of a joint that turns about a point;
// a slider's frames (and a fixed joint's) are not watched
TEST(RigidBodyWorld, TheJointErrorIsTheWidestGapOfATurningJoint) {
  BodyPlan plan = parallelogram();
  plan.loops[0].pivot_in_b = {0, -0.2, 0};  // 0.1 m from its pivot on part 0 at birth
  auto world = build(RigidBodyWorld::kName, plan, weightless(), PhysicsSettings{});
  ASSERT_EQ(world->birthStatus(), EvalStatus::ok) << world->birthMessage();
  EXPECT_NEAR(world->largestJointError(), 0.1, 1e-9);
  for (JointType unwatched : {JointType::prismatic, JointType::fixed}) {
    plan.loops[0].joint = unwatched;
    auto other = build(RigidBodyWorld::kName, plan, weightless(), PhysicsSettings{});
    ASSERT_EQ(other->birthStatus(), EvalStatus::ok) << other->birthMessage();
    EXPECT_LT(other->largestJointError(), 1e-9) << jointName(unwatched);
  }
}

// a loop joint naming a part the body lacks is refused with a message
TEST(RigidBodyWorld, ALoopJointToNoPartIsRefused) {
  BodyPlan plan = parallelogram();
  plan.loops[0].part_b = 9;
  auto world = build(RigidBodyWorld::kName, plan, Environment{}, PhysicsSettings{});
  EXPECT_EQ(world->birthStatus(), EvalStatus::invalid_body);
  EXPECT_NE(world->birthMessage().find("parts 0 and 9"), std::string::npos);
}

// the limb dropped on the ground comes to rest and stays: no motion from nothing (the soft
// constraints leave a jitter of a few hundredths of a rad/s in the spherical joint's twist)
TEST(RigidBodyWorld, APassiveBodyRests) {
  const BodyPlan plan = limb();
  auto world = build(RigidBodyWorld::kName, plan, Environment{}, PhysicsSettings{}, 0.05);
  for (int s = 0; s < 480; ++s)
    world->step({});
  const Vec3 settled = world->partPosition(0);
  EXPECT_NEAR(world->lowestPoint(), 0, 3e-3);
  for (int s = 0; s < 2400; ++s)
    world->step({});
  EXPECT_LT(distance(world->partPosition(0), settled), 2e-3);
  const JointSpeed fastest = world->fastestJoint();
  EXPECT_LT(fastest.speed, 0.05) << "part " << fastest.part << " dof " << fastest.dof;
}

// a block held beside a slab stays there until the release command, then falls beside it
TEST(RigidBodyWorld, AHeldObjectIsCarriedUntilReleased) {
  BodyPlan plan;
  plan.parts.push_back(box({1.0, 1.0, 0.2}, {0, 0, 0}));
  HeldObject held;
  held.size = {0.1, 0.1, 0.1};
  held.mass = 1;
  held.pose.position = {0.55, 0, 0};
  plan.held.push_back(held);
  plan.effectors.push_back(EffectorPlan{0, 0, EffectorKind::release});
  auto world = build(RigidBodyWorld::kName, plan, Environment{}, PhysicsSettings{});
  ASSERT_EQ(world->birthStatus(), EvalStatus::ok) << world->birthMessage();
  for (int s = 0; s < 240; ++s)
    world->step(std::vector<double>{0.5});
  EXPECT_FALSE(world->released(0));
  EXPECT_NEAR(world->heldPose(0).position.z, 0.1, 3e-3);
  world->step(std::vector<double>{0.9});
  EXPECT_TRUE(world->released(0));
  for (int s = 0; s < 240; ++s)
    world->step(std::vector<double>{0.5});
  EXPECT_NEAR(world->heldPose(0).position.z, 0.05, 3e-3);
  EXPECT_NEAR(world->heldPose(0).position.x, 0.55, 0.02);
}

// parts overlapping at birth are refused as in the Featherstone world
TEST(RigidBodyWorld, OverlappingPartsAreRefused) {
  BodyPlan plan = limb();
  PartPlan inside = box({0.1, 0.1, 0.1}, {0, 0, 0}, 0);
  inside.pivot_in_parent = {0, 0, 0.05};
  inside.pivot_in_child = {0, 0, 0.05};
  plan.parts.push_back(inside);                                 // a neighbour of the root: allowed
  plan.parts.push_back(box({0.1, 0.1, 0.1}, {0.35, 0, 0}, 5));  // inside part 1
  plan.parts.back().pivot_in_parent = {0.35, 0, 0};
  plan.parts.back().pivot_in_child = {0, 0, 0};
  auto world = build(RigidBodyWorld::kName, plan, Environment{}, PhysicsSettings{});
  EXPECT_EQ(world->birthStatus(), EvalStatus::self_penetration);
  EXPECT_NE(world->birthMessage().find("parts 1 and 6"), std::string::npos)
      << world->birthMessage();
}

// the same run twice: the same bits
TEST(RigidBodyWorld, TheSameRunGivesTheSameBits) {
  const BodyPlan plan = limb();
  std::vector<Transform> poses[2];
  for (auto& end : poses) {
    auto world = build(RigidBodyWorld::kName, plan, Environment{}, PhysicsSettings{}, 0.1);
    for (int s = 0; s < 240; ++s)
      world->step(std::vector<double>(plan.effectors.size(), s % 60 < 30 ? 1.0 : -0.7));
    for (std::size_t i = 0; i < plan.parts.size(); ++i)
      end.push_back(world->partPose(static_cast<int>(i)));
  }
  for (std::size_t i = 0; i < poses[0].size(); ++i) {
    EXPECT_EQ(poses[0][i].position.x, poses[1][i].position.x);
    EXPECT_EQ(poses[0][i].position.z, poses[1][i].position.z);
    EXPECT_EQ(poses[0][i].rotation.w, poses[1][i].rotation.w);
  }
}

}  // namespace
}  // namespace cambrian

namespace cambrian {
namespace {

// a joint's own damping (PartPlan::joint_damping) replaces the world's: two equal hinged limbs,
// one damped by its own 2 N m s / rad, the other by the world's 0, pushed alike without gravity;
// after the push the damped one's speed decays while the other's stays
TEST(RigidBodyWorld, AJointsOwnDampingReplacesTheWorlds) {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.4, 0.2, 0.1}, {0, 0, 0}));
  PartPlan damped = test::hingedChild();
  damped.axes = kAxes;
  damped.joint_limit = {3, 3, 3};
  damped.joint_damping = {2, 2, 2};
  PartPlan free = damped;
  free.joint_damping = {-1, -1, -1};
  free.pose.position = {-0.35, 0, 0};
  free.pivot_in_parent = {-0.2, 0, 0};
  free.parent_to_child = {0, 0, 0, 1};
  plan.parts.push_back(damped);
  plan.parts.push_back(free);
  plan.effectors = {{1, 0, EffectorKind::joint}, {2, 0, EffectorKind::joint}};
  PhysicsSettings physics;
  physics.actuation = Actuation::torque;
  physics.joint_damping = 0;
  for (bool implicit : {true, false}) {
    physics.implicit_damping = implicit;
    for (const char* kind : kWorlds) {
      auto world = build(kind, plan, weightless(), physics);
      const std::vector<double> push{0.2, 0.2}, rest{0, 0};
      for (int s = 0; s < 24; ++s)
        world->step(push);
      const double damped_at = world->jointPosition(1, 0), free_at = world->jointPosition(2, 0);
      for (int s = 0; s < 120; ++s)
        world->step(rest);
      const double damped_turn = std::abs(world->jointPosition(1, 0) - damped_at);
      const double free_turn = std::abs(world->jointPosition(2, 0) - free_at);
      const std::string what = std::string(kind) + (implicit ? " implicit" : " explicit");
      EXPECT_GT(free_turn, 0.05) << what;
      EXPECT_LT(damped_turn, 0.5 * free_turn) << what;
    }
  }
}

}  // namespace
}  // namespace cambrian

namespace cambrian {
namespace {

// a torque command is a generalised force on its joint coordinate alone: with constant commands
// u_d, no gravity, damping or limits, the kinetic energy gained is the work sum_d u_d T q_d (T the
// joint's strength), in both worlds. A spherical joint driven on its first two coordinates and
// bent far in the middle one shows it: pushed along the Euler axes instead of their duals, the
// rigid-body world's limb gained 6 % more energy than that work, and its undriven twist turned
// the other way from the Featherstone world's.
TEST(RigidBodyWorld, TorquesAreGeneralisedForcesOnTheirCoordinates) {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.4, 0.2, 0.2}, {0, 0, 0}));
  PartPlan limb = test::hingedChild();
  limb.joint = JointType::spherical;
  limb.axes = kAxes;
  limb.joint_limit = {3, 1.5, 3};
  plan.parts.push_back(limb);
  for (int d = 0; d < 3; ++d)
    plan.effectors.push_back({1, d, EffectorKind::joint});
  PhysicsSettings physics;
  physics.actuation = Actuation::torque;
  physics.joint_damping = 0;
  const double strength = physics.strength_per_area * limb.cross_section;
  const std::vector<double> commands{0.02, 0.05, 0};
  std::vector<double> twist;
  for (const char* kind : kWorlds) {
    auto world = build(kind, plan, weightless(), physics);
    double work = 0;
    int steps = 0;
    while (std::abs(world->jointPosition(1, 1)) < 1.1 && steps < 2000) {
      world->step(commands);
      ++steps;
      work = 0;
      for (int d = 0; d < 3; ++d)
        work += commands[static_cast<std::size_t>(d)] * strength * world->jointPosition(1, d);
    }
    ASSERT_LT(steps, 2000) << kind;
    for (int d : {0, 2})
      EXPECT_LT(std::abs(world->jointPosition(1, d)), 2.8) << kind << " dof " << d;
    EXPECT_NEAR(world->mechanicalEnergy(), work, 0.03 * work) << kind << " after " << steps;
    twist.push_back(world->jointPosition(1, 2));
  }
  EXPECT_LT(twist[0], -0.1);  // Featherstone's
  EXPECT_LT(twist[1], -0.1);
}

}  // namespace
}  // namespace cambrian
