// Tests of the environment kinds: the plane takes the ground's friction and restitution from
// the physics settings; names are distinct.
#include "physics/environment.hpp"

#include "physics/water_environment.hpp"

#include <gtest/gtest.h>

#include <set>

namespace cambrian {
namespace {

TEST(Environment, PlaneTakesTheGroundFromThePhysics) {
  PhysicsSettings physics;
  physics.ground_friction = 0.4;
  physics.restitution = 0.3;
  Environment environment = PlaneEnvironment().build(physics);
  EXPECT_EQ(environment.ground.kind, Ground::Kind::plane);
  EXPECT_EQ(environment.ground.friction, 0.4);
  EXPECT_EQ(environment.ground.restitution, 0.3);
  EXPECT_TRUE(environment.objects.empty());
  EXPECT_EQ(environment.light, (Vec3{10, 0, 0}));
  EXPECT_FALSE(environment.gravity.has_value());  // physics.gravity
  EXPECT_EQ(environment.fluid.viscosity, 0);
}

// water: no ground, the net gravity and the viscosity of its settings (Sims: gravity off)
TEST(Environment, WaterHasNoGroundAndItsOwnGravity) {
  PhysicsSettings physics;
  WaterEnvironment water;
  Environment environment = water.build(physics);
  EXPECT_EQ(environment.ground.kind, Ground::Kind::none);
  EXPECT_EQ(environment.gravity, 0.0);
  EXPECT_EQ(environment.fluid.viscosity, water.viscosity);
  water.viscosity = 40;
  water.net_gravity = 0.5;
  environment = water.build(physics);
  EXPECT_EQ(environment.gravity, 0.5);
  EXPECT_EQ(environment.fluid.viscosity, 40);
}

TEST(Environment, KindsHaveDistinctNames) {
  std::set<std::string> names;
  for (const EnvironmentKind* kind : environmentKinds())
    names.insert(kind->name());
  EXPECT_EQ(names.size(), environmentKinds().size());
  EXPECT_EQ(environmentNames().front(), "plane");
}

}  // namespace
}  // namespace cambrian
