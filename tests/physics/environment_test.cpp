// Tests of the environment kinds: the plane takes the ground's friction and restitution from
// the physics settings; water; hills (their grid, heights between samples as Bullet
// triangulates them, the highest ground over a rectangle, their settings); names are distinct.
#include "physics/environment.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "physics/hills_environment.hpp"
#include "physics/water_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

// hills: a square grid of fractal heights around the start, the start at z = 0, the ground's
// friction and restitution from the physics settings; every build shares one terrain
TEST(Environment, HillsAreAGridOfHeightsAroundTheStart) {
  PhysicsSettings physics;
  physics.ground_friction = 0.7;
  HillsEnvironment hills;
  hills.size = 10;
  hills.spacing = 0.5;
  Environment environment = hills.build(physics);
  const Ground& ground = environment.ground;
  EXPECT_EQ(ground.kind, Ground::Kind::heightfield);
  EXPECT_EQ(ground.friction, 0.7);
  EXPECT_EQ(ground.heightfield.samples, 21);
  EXPECT_EQ(ground.heightfield.size(), 10);
  ASSERT_EQ(ground.heightfield.heights->size(), 21u * 21u);
  EXPECT_EQ(ground.heightAt(0, 0), 0.0);
  EXPECT_EQ(environment.light, (Vec3{10, 0, ground.heightAt(10, 0)}));  // on the ground there
  EXPECT_EQ(hills.build(physics).ground.heightfield.heights, ground.heightfield.heights);
  // not flat, and another seed is another terrain
  double lowest = 0, highest = 0;
  for (double h : *ground.heightfield.heights) {
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
  }
  EXPECT_GT(highest - lowest, 0.05);
  hills.terrain.seed = 9;
  EXPECT_NE(*hills.build(physics).ground.heightfield.heights, *ground.heightfield.heights);
  // an odd number of samples always, so one lies at the start
  hills.size = 10.2;
  EXPECT_EQ(hills.samples(), 21);
  hills.size = 10.6;
  EXPECT_EQ(hills.samples(), 23);
}

// between samples the ground is Bullet's two triangles per square: (0,0) (0,1) (1,0) and
// (1,0) (0,1) (1,1) in (column, row) steps
TEST(Environment, HeightsBetweenSamplesFollowTheTriangles) {
  Heightfield field;
  field.samples = 3;
  field.spacing = 2;
  // rows of y = -2, 0, 2; columns of x = -2, 0, 2
  field.heights = std::make_shared<const std::vector<double>>(std::vector<double>{0, 1, 2,  //
                                                                                  3, 4, 8,  //
                                                                                  6, 7, 8});
  EXPECT_EQ(field.heightAt(-2, -2), 0);
  EXPECT_EQ(field.heightAt(2, 0), 8);
  EXPECT_EQ(field.heightAt(0, 2), 7);
  // lower-left triangle of the square x in [0, 2], y in [-2, 0]: corners 1, 2 and 4
  EXPECT_DOUBLE_EQ(field.heightAt(0.5, -1.5), 1 + 0.25 * (2 - 1) + 0.25 * (4 - 1));
  // its upper-right triangle: corners 2, 4 and 8 (8 at x = 2, y = 0)
  EXPECT_DOUBLE_EQ(field.heightAt(1.5, -0.5), 8 + 0.25 * (4 - 8) + 0.25 * (2 - 8));
  // on the diagonal both triangles agree
  EXPECT_DOUBLE_EQ(field.heightAt(1, -1), (2 + 4) / 2.0);
  // outside the grid: the edge's
  EXPECT_EQ(field.heightAt(10, 2), 8);
  EXPECT_EQ(field.heightAt(-10, -10), 0);
  // the highest ground over a rectangle bounds every point of it
  EXPECT_GE(field.highestIn(-1, 1, -1, 1), 4);
  EXPECT_EQ(field.highestIn(-2, -1.5, -2, -1.5), 4);  // samples of the one square it touches
  Ground plane;
  EXPECT_EQ(plane.heightAt(3, 4), 0);
  EXPECT_EQ(plane.highestIn(-1, 1, -1, 1), 0);
}

TEST(Environment, TheHighestGroundBoundsEveryPointOfARectangle) {
  HillsEnvironment hills;
  hills.terrain.height = 2;
  const Ground ground = hills.build(PhysicsSettings{}).ground;
  for (double x0 : {-3.3, 0.1, 7.9})
    for (double y0 : {-5.05, 2.6}) {
      const double highest = ground.highestIn(x0, x0 + 1.3, y0, y0 + 0.7);
      for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
          EXPECT_LE(ground.heightAt(x0 + 1.3 * i / 20, y0 + 0.7 * j / 20), highest);
    }
}

TEST(Environment, HillSettingsRefuseBadValues) {
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"environment.hill_spacing", "0"},
                                                        {"environment.hill_spacing", "0.001"},
                                                        {"environment.hill_size", "-1"},
                                                        {"environment.hill_cycle", "nan"},
                                                        {"environment.hill_alpha", "0.5"},
                                                        {"environment.hill_octaves", "0"}}) {
    HillsEnvironment fresh;
    SettingsSchema own;
    fresh.declareSettings(own);
    try {
      own.set(key, value);
      own.check();
      ADD_FAILURE() << key << " = " << value << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
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
