// Tests of the juries and the walk normalisations.
#include "tasks/juries.hpp"

#include "physics/water_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian {
namespace {

BodyPlan boxes(std::initializer_list<Vec3> sizes) {
  BodyPlan plan;
  double x = 0;
  for (Vec3 size : sizes) {
    PartPlan part;
    part.size = size;
    part.mass = 1000 * size.x * size.y * size.z;
    part.pose.position = {x + size.x / 2, 0, 0};
    x += size.x;
    plan.parts.push_back(part);
  }
  return plan;
}

// Chaumont's coefficients for a single unit cube: C_l = 3, C_s = 6, C_v = 1, k^1
TEST(Juries, ChaumontFactorUnitCube) {
  BodyPlan plan = boxes({{1, 1, 1}});
  EXPECT_DOUBLE_EQ(chaumontFactor(plan, 1.02), 1.0 / 18.0 * 1.02);
}

// scaling a body by s scales C_v / (C_s C_l) by 1, so distances in equal proportion score equal
TEST(Juries, ChaumontFactorScales) {
  BodyPlan small = boxes({{0.1, 0.2, 0.3}, {0.2, 0.1, 0.1}});
  BodyPlan large = boxes({{0.2, 0.4, 0.6}, {0.4, 0.2, 0.2}});
  EXPECT_NEAR(chaumontFactor(large, 1.0) * 1.0, chaumontFactor(small, 1.0) * 1.0, 1e-12);
}

// the volume factor is one over the cube root of the total volume
TEST(Juries, VolumeFactor) {
  BodyPlan plan = boxes({{2, 2, 2}});
  EXPECT_NEAR(volumeFactor(plan), 0.5, 1e-12);
}

// body length is the largest horizontal span
TEST(Juries, BodyLength) {
  BodyPlan plan = boxes({{0.5, 0.2, 0.1}, {0.3, 0.1, 0.1}});
  EXPECT_NEAR(bodyLength(plan), 0.8, 1e-12);
}

// a simulation of `plan` without a controller on the plane, born `height` above it
struct Sim {
  Environment environment;
  Simulation simulation;
  Sim(const BodyPlan& plan, double height)
      : simulation(plan, nullptr, environment, PhysicsSettings{}, height) {}
};

// the height jury keeps the highest the lowest point has been since begin(): a block born
// 0.3 m above the ground scores 0.3 m though it then falls and lands
TEST(Juries, HeightKeepsTheHighestLowestPoint) {
  BodyPlan plan = boxes({{0.2, 0.2, 0.2}});
  plan.sensors.push_back({SensorKind::contact, 0, 0});
  Sim sim(plan, 0.3);
  Simulation& simulation = sim.simulation;
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  HeightJury height;
  height.begin(simulation);
  EXPECT_NEAR(height.value(simulation), 0.3, 1e-12);
  for (int s = 0; s < 240; ++s) {
    simulation.step(false);
    height.observe(simulation);
  }
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  EXPECT_LT(simulation.lowestPoint(), 0.005);  // landed
  EXPECT_NEAR(height.value(simulation), 0.3, 1e-12);
}

// a jury begun on a body at rest on the ground, which then rises, scores the rise: the block
// observed from the moment it lands is at about 0 m, so a jury begun later scores about 0
TEST(Juries, HeightCountsFromBegin) {
  BodyPlan plan = boxes({{0.2, 0.2, 0.2}});
  Sim sim(plan, 0.3);
  Simulation& simulation = sim.simulation;
  for (int s = 0; s < 240; ++s)
    simulation.step(false);
  HeightJury height;
  height.begin(simulation);
  for (int s = 0; s < 240; ++s) {
    simulation.step(false);
    height.observe(simulation);
  }
  EXPECT_LT(height.value(simulation), 0.005);
  EXPECT_GE(height.value(simulation), 0.0);
}

// the distance jury measures the centre of mass's horizontal travel from begin()
TEST(Juries, DistanceIsHorizontalTravelFromBegin) {
  BodyPlan plan = boxes({{0.2, 0.2, 0.2}});
  Sim sim(plan, 0.3);
  DistanceJury distance;
  distance.begin(sim.simulation);
  for (int s = 0; s < 240; ++s) {
    sim.simulation.step(false);
    distance.observe(sim.simulation);
  }
  // it fell 0.3 m straight down: no horizontal travel (contact jitter aside)
  EXPECT_LT(distance.value(sim.simulation), 1e-3);
  EXPECT_STREQ(distance.name(), "distance");
}

// a plate sinking in water (net gravity 1 m/s^2) with a light 10 m straight below it: the
// approach is the depth it sank; the displacement from step 100 on is the depth sunk since
TEST(Juries, ApproachAndDisplacementOfASinkingPlate) {
  BodyPlan plan = boxes({{0.4, 0.4, 0.02}});
  WaterEnvironment water;
  water.net_gravity = 1;
  Environment environment = water.build(PhysicsSettings{});
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{});
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  const Vec3 start = simulation.centerOfMass();
  simulation.moveLight(start - Vec3{0, 0, 10});
  ApproachJury approach;
  DisplacementJury whole("distance"), late("late", 100);
  for (Jury* jury : std::initializer_list<Jury*>{&approach, &whole, &late})
    jury->begin(simulation);
  double z100 = 0;
  for (int s = 1; s <= 240; ++s) {
    simulation.step(false);
    for (Jury* jury : std::initializer_list<Jury*>{&approach, &whole, &late})
      jury->observe(simulation);
    if (s == 100)
      z100 = simulation.centerOfMass().z;
  }
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  const double sunk = start.z - simulation.centerOfMass().z;
  EXPECT_GT(sunk, 0.05);
  EXPECT_NEAR(approach.value(simulation), sunk, 1e-12);
  EXPECT_NEAR(whole.value(simulation), sunk, 1e-12);
  EXPECT_NEAR(late.value(simulation), z100 - simulation.centerOfMass().z, 1e-12);
  EXPECT_STREQ(late.name(), "late");
}

}  // namespace
}  // namespace cambrian
