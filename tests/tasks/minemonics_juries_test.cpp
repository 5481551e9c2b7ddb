// Tests of Minemonics' juries on motions computed by hand: a block falling freely (no ground),
// a block resting on the plane and on the hills, a two-part body of which one part touches.
#include "tasks/minemonics_juries.hpp"

#include "physics/box_part.hpp"
#include "physics/hills_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cambrian {
namespace {

// every jury of the juries task but the horizontal distance (DistanceJury's own tests)
struct Juries {
  AverageVelocityJury average;
  IntegralAverageVelocityJury integral;
  MaximumHeightJury highest;
  AverageHeightJury height;
  GroundContactJury quantity{false}, ratio{true};
  TimeOnGroundJury on_ground;
  std::vector<Jury*> all() {
    return {&average, &integral, &highest, &height, &quantity, &ratio, &on_ground};
  }
};

// runs `steps` steps of `simulation` (controller off) with every jury watching
void watch(Simulation& simulation, int steps, const std::vector<Jury*>& juries) {
  for (Jury* jury : juries)
    jury->begin(simulation);
  for (int s = 0; s < steps; ++s) {
    simulation.step(false);
    for (Jury* jury : juries)
      jury->observe(simulation);
  }
}

// free fall without ground: after n steps of dt (each of k substeps of dt / k, semi-implicit
// Euler: speed first, then position) the block has fallen g (dt / k)^2 N (N + 1) / 2, N = n k;
// it never touches anything and is highest where it started (without ground, heights are
// above z = 0, where the plane would be)
TEST(MinemonicsJuries, AFallingBlockOnAStraightPath) {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.2, 0.2, 0.2}, {0, 0, 0}));
  Environment environment;
  environment.ground.kind = Ground::Kind::none;
  environment.gravity = 9.81;
  PhysicsSettings physics;
  Simulation simulation(plan, nullptr, environment, physics, 0);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  Juries j;
  auto& [average, integral, highest, height, quantity, ratio, on_ground] = j;
  const int n = 240;
  const Vec3 start = simulation.centerOfMass();
  watch(simulation, n, j.all());
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  const double sub = physics.time_step / physics.substeps;
  const double big_n = n * physics.substeps;
  const double fallen = 9.81 * sub * sub * big_n * (big_n + 1) / 2;
  EXPECT_NEAR(start.z - simulation.centerOfMass().z, fallen, 1e-9 * fallen);
  const double time = n * physics.time_step, size = 0.2;
  EXPECT_NEAR(average.value(simulation), fallen / time / size, 1e-8);
  EXPECT_NEAR(integral.value(simulation), fallen / time / size, 1e-8);  // a straight path
  EXPECT_NEAR(highest.value(simulation), start.z, 1e-12);               // highest at the start
  EXPECT_EQ(quantity.value(simulation), 0);
  EXPECT_EQ(ratio.value(simulation), 0);
  EXPECT_EQ(on_ground.value(simulation), 0);
  // the mean height over the steps: start minus the mean of the fallen distances, in sizes
  double sum = 0;
  for (int s = 1; s <= n; ++s) {
    const double k = s * physics.substeps;
    sum += start.z - 9.81 * sub * sub * k * (k + 1) / 2;
  }
  EXPECT_NEAR(height.value(simulation), sum / n / size, 1e-8);
}

// a block resting on the plane: still, on the ground all the time, half its height up
TEST(MinemonicsJuries, ABlockAtRestOnThePlane) {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.4, 0.2, 0.1}, {0, 0, 0}));
  Environment environment;
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{}, 0);
  for (int s = 0; s < 240; ++s)
    simulation.step(false);  // comes to rest
  Juries j;
  auto& [average, integral, highest, height, quantity, ratio, on_ground] = j;
  watch(simulation, 480, j.all());
  const double size = std::cbrt(0.4 * 0.2 * 0.1);
  EXPECT_LT(average.value(simulation), 1e-4);
  EXPECT_LT(integral.value(simulation), 1e-3);
  EXPECT_NEAR(highest.value(simulation), 0.05, 2e-3);
  EXPECT_NEAR(height.value(simulation), 0.05 / size, 2e-3 / size);
  EXPECT_EQ(quantity.value(simulation), 1);
  EXPECT_EQ(ratio.value(simulation), 1);
  EXPECT_NEAR(on_ground.value(simulation), 480 * PhysicsSettings{}.time_step, 1e-9);
}

// on the hills heights are taken above the ground under each part, not above z = 0
TEST(MinemonicsJuries, HeightsOnTheHillsAreAboveTheGroundUnderThem) {
  HillsEnvironment hills;
  hills.terrain.height = 2;
  const Environment environment = hills.build(PhysicsSettings{});
  BodyPlan plan;
  plan.parts.push_back(test::box({0.2, 0.2, 0.2}, {5.3, -3.1, 0}));
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{}, 0);
  for (int s = 0; s < 480; ++s)
    simulation.step(false);
  const Vec3 at = simulation.centerOfMass();
  ASSERT_GT(std::abs(environment.ground.heightAt(at.x, at.y)), 0.05);  // not at z = 0
  MaximumHeightJury highest;
  AverageHeightJury height;
  watch(simulation, 10, {&highest, &height});
  EXPECT_NEAR(highest.value(simulation), 0.1, 0.03);  // a slope tilts the block a little
  EXPECT_NEAR(height.value(simulation), 0.1 / 0.2, 0.03 / 0.2);
}

// a body of two parts of which only one lies on the ground: one part of two touched
TEST(MinemonicsJuries, GroundContactsCountThePartsThatTouched) {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.4, 0.4, 0.1}, {0, 0, 0}));
  PartPlan mast = test::box({0.1, 0.1, 0.4}, {0, 0, 0.25}, 0);
  mast.joint = JointType::fixed;
  mast.pivot_in_parent = {0, 0, 0.05};
  mast.pivot_in_child = {0, 0, -0.2};
  mast.connection = 0;
  plan.parts.push_back(mast);
  Environment environment;
  Simulation simulation(plan, nullptr, environment, PhysicsSettings{}, 0);
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  GroundContactJury quantity(false), ratio(true);
  TimeOnGroundJury on_ground;
  watch(simulation, 240, {&quantity, &ratio, &on_ground});
  EXPECT_EQ(quantity.value(simulation), 1);
  EXPECT_EQ(ratio.value(simulation), 0.5);
  EXPECT_GT(on_ground.value(simulation), 0.9);  // down within the first 0.1 s
}

}  // namespace
}  // namespace cambrian
