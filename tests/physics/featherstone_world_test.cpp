// Tests of the Featherstone world behind the World interface: every part shape rests where its
// geometry says, prismatic joints slide, closed loops are refused with a clear status, free
// objects of the environment fall and can be read back, materials bounce, held objects are
// carried until their release effector fires, hills are where their heights say, the registry.
#include "physics/featherstone_world.hpp"

#include "cambrian/error.hpp"

#include "physics/hills_environment.hpp"
#include "physics/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace cambrian {
namespace {

// a part of `shape` and `size` at `position`
PartPlan partOf(PartShape shape, Vec3 size, Vec3 position = {}, int parent = -1) {
  PartPlan part;
  part.shape = shape;
  part.size = size;
  part.mass = 1000 * shapeVolume(shape, size);
  part.pose.position = position;
  part.parent = parent;
  return part;
}

// steps a world `steps` times with no commands
void settle(World& world, int steps) {
  for (int s = 0; s < steps; ++s)
    world.step({});
}

// each shape, dropped from 0.3 m, comes to rest with its lowest point on the ground
TEST(FeatherstoneWorld, EveryShapeRestsOnTheGround) {
  struct Case {
    PartShape shape;
    Vec3 size;
    double centre;  // height of the centre at rest
  };
  const Case cases[] = {{PartShape::box, {0.4, 0.3, 0.2}, 0.1},
                        {PartShape::sphere, {0.2, 0.2, 0.2}, 0.1},
                        {PartShape::capsule, {0.5, 0.16, 0.16}, 0.08},
                        {PartShape::cylinder, {0.5, 0.2, 0.2}, 0.1}};
  for (const Case& c : cases) {
    BodyPlan plan;
    plan.parts.push_back(partOf(c.shape, c.size));
    Environment environment;
    PhysicsSettings physics;
    FeatherstoneWorld world(plan, environment, physics, 0.3);
    ASSERT_EQ(world.birthStatus(), EvalStatus::ok) << shapeName(c.shape);
    EXPECT_NEAR(world.lowestPoint(), 0.3, 1e-9) << shapeName(c.shape);
    settle(world, 720);
    EXPECT_NEAR(world.partPosition(0).z, c.centre, 3e-3) << shapeName(c.shape);
    EXPECT_NEAR(world.lowestPoint(), 0.0, 3e-3) << shapeName(c.shape);
    EXPECT_EQ(world.contacts()[0], 1 << 5) << shapeName(c.shape);  // touched on its -z face
  }
}

// a capsule's inertia is a solid capsule's in both worlds (Bullet's own is its bounding box's):
// with no straight middle, a sphere's; the exact sums of a cylinder and two half spheres
TEST(FeatherstoneWorld, ACapsuleHasASolidCapsulesInertia) {
  for (const char* kind : {"featherstone", "rigid_bodies"}) {
    for (const Vec3 size : {Vec3{0.2, 0.2, 0.2}, Vec3{0.8, 0.2, 0.2}}) {
      BodyPlan plan;
      plan.parts.push_back(partOf(PartShape::capsule, size));
      PhysicsSettings physics;
      physics.world = kind;
      auto world = makeWorld(plan, Environment{}, physics, 0.3);
      const double r = 0.1, h = size.x - 0.2, density = 1000;
      const double m_middle = density * kPi * r * r * h;
      const double m_ends = density * 4.0 / 3.0 * kPi * r * r * r;
      const double along = m_middle * r * r / 2 + m_ends * 0.4 * r * r;
      // each half sphere: 83/320 m r^2 about its centre of mass, 3r/8 from its flat face
      const double across = m_middle * (h * h / 12 + r * r / 4) +
                            m_ends * (83.0 / 320.0 * r * r + std::pow(h / 2 + 3 * r / 8, 2));
      const Vec3 inertia = world->partInertia(0);
      EXPECT_NEAR(inertia.x, along, 1e-12 * along) << kind << " " << size.x;
      EXPECT_NEAR(inertia.y, across, 1e-12 * across) << kind << " " << size.x;
      EXPECT_NEAR(inertia.z, across, 1e-12 * across) << kind << " " << size.x;
    }
  }
}

// a prismatic joint slides its part along its axis, within its limit
TEST(FeatherstoneWorld, PrismaticJointSlides) {
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.6, 0.3, 0.1}));
  PartPlan slider = partOf(PartShape::box, {0.2, 0.1, 0.1}, {0.4, 0, 0}, 0);
  slider.joint = JointType::prismatic;
  slider.pivot_in_parent = {0.3, 0, 0};
  slider.pivot_in_child = {-0.1, 0, 0};
  slider.axes[0] = {1, 0, 0};
  slider.joint_limit = {0.05, 0, 0};
  slider.cross_section = 0.01;
  plan.parts.push_back(slider);
  plan.effectors.push_back(EffectorPlan{1, 0});
  Environment environment;
  PhysicsSettings physics;
  physics.gravity = 0;
  physics.motor_speed = 0.5;
  FeatherstoneWorld world(plan, environment, physics, 0.1);
  ASSERT_EQ(world.birthStatus(), EvalStatus::ok) << world.birthMessage();
  const double command[] = {1.0};
  for (int s = 0; s < 240; ++s)
    world.step(command);
  EXPECT_GT(world.jointPosition(1, 0), 0.03);
  EXPECT_LT(world.jointPosition(1, 0), 0.06);
  // the part moved away from the root along x
  EXPECT_GT(world.partPosition(1).x - world.partPosition(0).x, 0.43);
}

// a plan with a closed loop is refused, saying why and what would build it
// the middle degree of freedom of a spherical joint (a virtual link whose parent is virtual too)
// is driven by its motor and held by its limit; with physics.solve_every_dof = false (runs stored
// before it) Bullet never solves its rows: the motor does nothing and explicit torques spin it
// through its limit
TEST(FeatherstoneWorld, EveryDegreeOfFreedomOfASphericalJointIsSolved) {
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.4, 0.2, 0.1}));
  PartPlan ball = partOf(PartShape::box, {0.3, 0.1, 0.1}, {0.35, 0, 0}, 0);
  ball.joint = JointType::spherical;
  ball.axes = {Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}};
  ball.pivot_in_parent = {0.2, 0, 0};
  ball.pivot_in_child = {-0.15, 0, 0};
  ball.joint_limit = {0.5, 0.3, 0.9};
  ball.cross_section = 0.01;
  plan.parts.push_back(ball);
  for (int d = 0; d < 3; ++d)
    plan.effectors.push_back({1, d, EffectorKind::joint});
  Environment weightless;
  weightless.ground.kind = Ground::Kind::none;
  weightless.gravity = 0.0;
  const std::vector<double> middle_only{0, 1, 0};
  for (bool solved : {true, false}) {
    PhysicsSettings physics;
    physics.solve_every_dof = solved;
    FeatherstoneWorld motor(plan, weightless, physics, 0.0);
    for (int s = 0; s < 480; ++s)
      motor.step(middle_only);
    EXPECT_NEAR(motor.jointPosition(1, 1), solved ? 0.3 : 0.0, 0.01) << solved;
    physics.actuation = Actuation::torque;
    FeatherstoneWorld torque(plan, weightless, physics, 0.0);
    for (int s = 0; s < 480; ++s)
      torque.step(middle_only);
    if (solved)
      EXPECT_NEAR(torque.jointPosition(1, 1), 0.3, 0.03);
    else
      EXPECT_GT(torque.jointPosition(1, 1), 10.0);
  }
}

TEST(FeatherstoneWorld, ClosedLoopsAreRefusedClearly) {
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.4, 0.4, 0.1}));
  plan.parts.push_back(partOf(PartShape::box, {0.1, 0.1, 0.1}, {0.25, 0, 0}, 0));
  plan.parts[1].joint = JointType::revolute;
  plan.parts[1].pivot_in_parent = {0.2, 0, 0};
  plan.parts[1].pivot_in_child = {-0.05, 0, 0};
  LoopJoint loop;
  loop.part_a = 0;
  loop.part_b = 1;
  plan.loops.push_back(loop);
  Environment environment;
  FeatherstoneWorld world(plan, environment, PhysicsSettings{}, 0);
  EXPECT_EQ(world.birthStatus(), EvalStatus::invalid_body);
  EXPECT_NE(world.birthMessage().find("closed-loop"), std::string::npos) << world.birthMessage();
  EXPECT_NE(world.birthMessage().find("featherstone"), std::string::npos);
  // the simulation reports it as the creature's status and never steps
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{});
  EXPECT_EQ(simulation.status(), EvalStatus::invalid_body);
  simulation.step(true);
  EXPECT_EQ(simulation.steps(), 0u);
}

// a free object of the environment falls beside the creature and can be read back; a fixed
// one (mass 0) stays put
TEST(FeatherstoneWorld, FreeObjectsFallAndAreReadBack) {
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.2, 0.2, 0.2}));
  Environment environment;
  FreeObject cube;
  cube.name = "cube";
  cube.size = {0.1, 0.1, 0.1};
  cube.mass = 0.5;
  cube.pose.position = {1, 0, 0.5};
  environment.objects.push_back(cube);
  FreeObject post = cube;
  post.name = "post";
  post.mass = 0;
  post.pose.position = {-1, 0, 0.5};
  environment.objects.push_back(post);
  FeatherstoneWorld world(plan, environment, PhysicsSettings{}, 0);
  ASSERT_EQ(world.birthStatus(), EvalStatus::ok);
  settle(world, 480);
  EXPECT_NEAR(world.objectPose(0).position.z, 0.05, 3e-3);
  EXPECT_NEAR(world.objectPose(0).position.x, 1.0, 1e-3);
  EXPECT_EQ(world.objectPose(1).position, (Vec3{-1, 0, 0.5}));
  // the creature is not touched by either
  EXPECT_NEAR(world.partPosition(0).x, 0.0, 1e-3);
}

// lowest and highest ground in the square of half side `half` around (x, y)
std::pair<double, double> groundAround(const Ground& ground, double x, double y, double half) {
  double low = ground.heightAt(x, y), high = low;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      double h = ground.heightAt(x + half * i / 4, y + half * j / 4);
      low = std::min(low, h);
      high = std::max(high, h);
    }
  return {low, high};
}

// a small box born anywhere on the hills is born above them and comes to rest on the terrain
// where Heightfield::heightAt says it is (Bullet's heightfield placed, scaled and triangulated
// as the environment describes it)
TEST(FeatherstoneWorld, ABoxComesToRestOnTheHillsWhereTheirHeightsSay) {
  HillsEnvironment hills;
  hills.terrain.height = 2;  // hills of about a metre
  const Environment environment = hills.build(PhysicsSettings{});
  const Ground& ground = environment.ground;
  const Vec3 places[] = {{0, 0, 0}, {3, -7, 0}, {-6, 2.2, 0}, {8.3, 8.1, 0}, {-12, -1, 0}};
  for (const Vec3& place : places) {
    BodyPlan plan;
    plan.parts.push_back(partOf(PartShape::box, {0.1, 0.1, 0.1}, place));
    FeatherstoneWorld world(plan, environment, PhysicsSettings{}, 0.05);
    ASSERT_EQ(world.birthStatus(), EvalStatus::ok);
    const double under =
        ground.highestIn(place.x - 0.05, place.x + 0.05, place.y - 0.05, place.y + 0.05);
    EXPECT_NEAR(world.lowestPoint(), under + 0.05, 1e-9) << place.x << "," << place.y;
    settle(world, 720);
    const Vec3 at = world.partPosition(0);
    const auto [low, high] = groundAround(ground, at.x, at.y, 0.08);
    EXPECT_GE(world.lowestPoint(), low - 3e-3) << place.x << "," << place.y;
    EXPECT_LE(world.lowestPoint(), high + 3e-3) << place.x << "," << place.y;
    EXPECT_NE(world.contacts()[0], 0) << place.x << "," << place.y;  // it touches the ground
  }
  // the terrain is not flat where the boxes stood: the test tells places apart
  EXPECT_GT(std::abs(ground.heightAt(3, -7) - ground.heightAt(-7, 3)), 0.05);
}

// a free object of the environment is placed as high above the hills as it would be above the
// plane, and falls onto them
TEST(FeatherstoneWorld, FreeObjectsStandOnTheHills) {
  HillsEnvironment hills;
  hills.terrain.height = 2;
  Environment environment = hills.build(PhysicsSettings{});
  FreeObject cube;
  cube.size = {0.1, 0.1, 0.1};
  cube.mass = 0.5;
  cube.pose.position = {4, 5, 0.05};  // resting on a plane
  environment.objects.push_back(cube);
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.2, 0.2, 0.2}));
  FeatherstoneWorld world(plan, environment, PhysicsSettings{}, 0);
  ASSERT_EQ(world.birthStatus(), EvalStatus::ok);
  EXPECT_NEAR(world.objectPose(0).position.z,
              0.05 + environment.ground.highestIn(3.95, 4.05, 4.95, 5.05), 1e-9);
  settle(world, 720);
  const Vec3 at = world.objectPose(0).position;
  const auto [low, high] = groundAround(environment.ground, at.x, at.y, 0.08);
  EXPECT_GE(at.z - 0.05, low - 0.02);
  EXPECT_LE(at.z - 0.05, high + 3e-3);
}

// hills of height 0 are a plane: a box rests at half its height
TEST(FeatherstoneWorld, FlatHillsAreAPlane) {
  HillsEnvironment hills;
  hills.terrain.height = 0;
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.4, 0.3, 0.2}, {1.3, -0.4, 0}));
  FeatherstoneWorld world(plan, hills.build(PhysicsSettings{}), PhysicsSettings{}, 0.3);
  ASSERT_EQ(world.birthStatus(), EvalStatus::ok);
  settle(world, 720);
  EXPECT_NEAR(world.partPosition(0).z, 0.1, 3e-3);
  EXPECT_NEAR(world.partPosition(0).x, 1.3, 1e-3);
}

// a part's material sets its bounce: restitution 1 on a restitution-1 ground bounces back up
TEST(FeatherstoneWorld, MaterialsSetTheBounce) {
  double peaks[2] = {0, 0};
  for (int bouncy = 0; bouncy < 2; ++bouncy) {
    BodyPlan plan;
    plan.parts.push_back(partOf(PartShape::sphere, {0.2, 0.2, 0.2}));
    plan.parts[0].material.restitution = bouncy ? 0.9 : 0.0;
    Environment environment;
    environment.ground.restitution = 1.0;
    FeatherstoneWorld world(plan, environment, PhysicsSettings{}, 0.5);
    bool landed = false;
    for (int s = 0; s < 480; ++s) {
      world.step({});
      double z = world.lowestPoint();
      landed = landed || z < 0.01;
      if (landed)
        peaks[bouncy] = std::max(peaks[bouncy], z);
    }
  }
  EXPECT_LT(peaks[0], 0.02);
  EXPECT_GT(peaks[1], 0.15);
}

TEST(World, RegistryAndUnknownNames) {
  EXPECT_EQ(worldNames().front(), "featherstone");
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {0.2, 0.2, 0.2}));
  Environment environment;
  PhysicsSettings physics;
  EXPECT_EQ(makeWorld(plan, environment, physics)->birthStatus(), EvalStatus::ok);
  physics.world = "mujoco";
  EXPECT_THROW(makeWorld(plan, environment, physics), ConfigError);
}

// a wide slab holding a 0.1 m block against the middle of its +x face, with its release effector
BodyPlan slabHolding() {
  BodyPlan plan;
  plan.parts.push_back(partOf(PartShape::box, {1.0, 1.0, 0.2}));
  HeldObject held;
  held.size = {0.1, 0.1, 0.1};
  held.mass = 1;
  held.pose.position = {0.55, 0, 0};
  plan.held.push_back(held);
  plan.effectors.push_back(EffectorPlan{0, 0, EffectorKind::release});
  return plan;
}

// the block stays where the slab holds it, above the ground, until the command passes 0.5; then
// it falls to the ground beside the slab; the energy counts it
TEST(FeatherstoneWorld, AHeldObjectIsCarriedUntilReleased) {
  const BodyPlan plan = slabHolding();
  Environment environment;
  PhysicsSettings physics;
  FeatherstoneWorld world(plan, environment, physics, 0.0);
  ASSERT_EQ(world.birthStatus(), EvalStatus::ok) << world.birthMessage();
  const std::vector<double> hold{0.5}, let_go{0.9};
  for (int s = 0; s < 240; ++s)
    world.step(hold);
  EXPECT_FALSE(world.released(0));
  const Transform slab = world.partPose(0);
  const Vec3 in_slab = world.heldPose(0).position - slab.position;
  EXPECT_NEAR(in_slab.x, 0.55, 2e-3);
  EXPECT_NEAR(in_slab.z, 0.0, 2e-3);
  EXPECT_NEAR(world.heldPose(0).position.z, 0.1, 3e-3);  // held at the slab's mid-height

  world.step(let_go);
  EXPECT_TRUE(world.released(0));
  for (int s = 0; s < 240; ++s)
    world.step(hold);  // a smaller command later changes nothing
  EXPECT_TRUE(world.released(0));
  EXPECT_NEAR(world.heldPose(0).position.z, 0.05, 3e-3);  // on the ground
  EXPECT_NEAR(world.heldPose(0).position.x, 0.55, 0.02);  // straight down
  // at rest: m g z of the slab and of the block
  EXPECT_NEAR(world.mechanicalEnergy(),
              200 * 9.81 * world.partPosition(0).z + 1 * 9.81 * world.heldPose(0).position.z, 0.05);
}

// a held object overlapping another part at birth is a self-penetration naming it
TEST(FeatherstoneWorld, AHeldObjectInsideAPartIsRefused) {
  BodyPlan plan = slabHolding();
  PartPlan leg = partOf(PartShape::box, {0.2, 0.2, 0.2}, {0.6, 0, 0}, 0);
  leg.pivot_in_parent = {0.5, 0, 0};
  leg.pivot_in_child = {-0.1, 0, 0};
  plan.parts.push_back(leg);
  Environment environment;
  PhysicsSettings physics;
  FeatherstoneWorld world(plan, environment, physics, 0.0);
  EXPECT_EQ(world.birthStatus(), EvalStatus::self_penetration);
  EXPECT_NE(world.birthMessage().find("held object 0 and part 1"), std::string::npos)
      << world.birthMessage();
}

}  // namespace
}  // namespace cambrian
