// Tests of the environment kinds: the plane takes the ground's friction and restitution from
// the physics settings; names are distinct.
#include "physics/environment.hpp"

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
