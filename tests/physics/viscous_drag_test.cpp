// Tests of Sims' viscous drag: the coefficients against hand-computed values and against a brute
// sum over the faces, the step-limited drag that never reverses a motion, and the water world: a
// plate falling at its terminal speed, a passive body at rest, no swimming without water.
#include "physics/viscous_drag.hpp"

#include "physics/box_part.hpp"
#include "physics/simulation.hpp"
#include "physics/water_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace cambrian {
namespace {

using test::box;

// a 0.4 x 0.2 x 0.1 m box in viscosity 100: faces of 0.02, 0.04 and 0.08 m^2
TEST(ViscousDrag, BoxByHand) {
  DragCoefficients drag = viscousDrag(PartShape::box, {0.4, 0.2, 0.1}, 100);
  EXPECT_NEAR(drag.linear.x, 4, 1e-12);  // 2 x 100 x 0.02
  EXPECT_NEAR(drag.linear.y, 8, 1e-12);
  EXPECT_NEAR(drag.linear.z, 16, 1e-12);
  // 2 x 100 / 3 x (0.04 x 0.05^2 + 0.08 x 0.1^2), (0.02 x 0.05^2 + 0.08 x 0.2^2), …
  EXPECT_NEAR(drag.angular.x, 0.06, 1e-12);
  EXPECT_NEAR(drag.angular.y, 200.0 / 3 * 0.00325, 1e-12);
  EXPECT_NEAR(drag.angular.z, 0.12, 1e-12);
}

// Sims' law summed point by point: force density -viscosity (v_p . n) n on a surface
struct Brute {
  Vec3 force, torque;
  void add(Vec3 point, Vec3 normal, double area, double viscosity, Vec3 v, Vec3 w) {
    Vec3 velocity = v + cross(w, point);
    Vec3 f = normal * (-viscosity * dot(velocity, normal) * area);
    force = force + f;
    torque = torque + cross(point, f);
  }
};

void expectMatches(const DragCoefficients& drag, const Brute& brute, Vec3 v, Vec3 w,
                   double tolerance) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(brute.force[i], -drag.linear[i] * v[i], tolerance) << "force " << i;
    EXPECT_NEAR(brute.torque[i], -drag.angular[i] * w[i], tolerance) << "torque " << i;
  }
}

// the closed form is the exact sum over the six faces of a moving, turning box
TEST(ViscousDrag, BoxMatchesTheSumOverItsFaces) {
  const Vec3 size{0.5, 0.3, 0.12}, v{0.7, -1.1, 0.4}, w{2.0, -0.5, 1.3};
  const double viscosity = 80;
  const int n = 200;
  Brute brute;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const double da = size[a] / n, db = size[b] / n;
    for (double sign : {-1.0, 1.0}) {
      Vec3 normal;
      normal[axis] = sign;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          Vec3 point;
          point[axis] = sign * size[axis] / 2;
          point[a] = -size[a] / 2 + (i + 0.5) * da;
          point[b] = -size[b] / 2 + (j + 0.5) * db;
          brute.add(point, normal, da * db, viscosity, v, w);
        }
      }
    }
  }
  expectMatches(viscousDrag(PartShape::box, size, viscosity), brute, v, w, 1e-4);
}

// the same for a cylinder along x: its side and its two end discs
TEST(ViscousDrag, CylinderMatchesTheSumOverItsSurface) {
  const Vec3 size{0.6, 0.2, 0.2}, v{0.3, 0.8, -0.5}, w{1.5, 0.9, -2.2};
  const double viscosity = 50, r = 0.1, length = 0.6;
  const int n = 400;
  Brute brute;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * 2 * kPi / n;
    const Vec3 normal{0, std::cos(theta), std::sin(theta)};
    for (int j = 0; j < n; ++j) {
      const double x = -length / 2 + (j + 0.5) * length / n;
      brute.add(Vec3{x, 0, 0} + normal * r, normal, r * 2 * kPi / n * length / n, viscosity, v, w);
      const double rho = (j + 0.5) * r / n;  // the end discs, in rings
      for (double sign : {-1.0, 1.0}) {
        const Vec3 point{sign * length / 2, rho * std::cos(theta), rho * std::sin(theta)};
        brute.add(point, {sign, 0, 0}, rho * (r / n) * (2 * kPi / n), viscosity, v, w);
      }
    }
  }
  expectMatches(viscousDrag(PartShape::cylinder, size, viscosity), brute, v, w, 1e-4);
}

// a sphere resists translation by viscosity 4/3 pi r^2 and turning not at all
TEST(ViscousDrag, SphereByHand) {
  DragCoefficients drag = viscousDrag(PartShape::sphere, {0.2, 0.2, 0.2}, 30);
  EXPECT_NEAR(drag.linear.y, 30 * 4.0 / 3.0 * kPi * 0.01, 1e-12);
  EXPECT_EQ(drag.angular, (Vec3{0, 0, 0}));
}

// over a short step the drag is Sims' force; over a long one it stops a free body exactly at its
// decayed speed, never past zero
TEST(ViscousDrag, OverAStepItOnlySlows) {
  DragCoefficients drag{{10, 10, 10}, {1, 1, 1}};
  const double mass = 2, step = 1e-6;
  Wrench small = dragOverStep(drag, mass, {0.1, 0.1, 0.1}, {1, -2, 0}, {0, 0, 3}, step);
  EXPECT_NEAR(small.force.x, -10, 1e-4);
  EXPECT_NEAR(small.force.y, 20, 2e-4);
  EXPECT_NEAR(small.torque.z, -3, 1e-4);
  const double long_step = 10;  // c step / mass = 50
  Wrench large = dragOverStep(drag, mass, {0.1, 0.1, 0.1}, {1, 0, 0}, {0, 0, 3}, long_step);
  const double v_after = 1 + large.force.x * long_step / mass;
  const double w_after = 3 + large.torque.z * long_step / 0.1;
  EXPECT_GE(v_after, 0);
  EXPECT_NEAR(v_after, std::exp(-50.0), 1e-15);
  EXPECT_GE(w_after, 0);
}

// a creature in water (viscosity, net gravity)
struct InWater {
  Environment environment;
  Simulation simulation;
  InWater(const BodyPlan& plan, double viscosity, double net_gravity,
          const PhysicsSettings& physics = PhysicsSettings{})
      : environment(water(viscosity, net_gravity)),
        simulation(plan, nullptr, environment, physics) {}
  static Environment water(double viscosity, double net_gravity) {
    WaterEnvironment kind;
    kind.viscosity = viscosity;
    kind.net_gravity = net_gravity;
    return kind.build(PhysicsSettings{});
  }
};

// a flat plate sinking under 1 m/s^2 of net gravity reaches its terminal speed m g / c, with c
// the step-limited drag of its two large faces (Sims' 2 viscosity A, less c dt / 2m)
TEST(ViscousDrag, APlateSinksAtItsTerminalSpeed) {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.4, 0.02}, {0, 0, 0}));
  const double viscosity = 100, g = 1, mass = plan.parts[0].mass;  // 3.2 kg
  InWater water(plan, viscosity, g);
  Simulation& simulation = water.simulation;
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  for (int s = 0; s < 480; ++s)  // 2 s, 20 time constants
    simulation.step(false);
  const double z0 = simulation.centerOfMass().z;
  simulation.step(false);
  ASSERT_EQ(simulation.status(), EvalStatus::ok);
  const double speed = (z0 - simulation.centerOfMass().z) / simulation.timeStep();
  const double c = 2 * viscosity * 0.16, substep = simulation.timeStep() / 2;
  const double c_step = mass * -std::expm1(-c * substep / mass) / substep;
  EXPECT_NEAR(speed, mass * g / c_step, 1e-9);
  EXPECT_NEAR(speed, mass * g / c, 0.011 * mass * g / c);  // Sims' 0.1 m/s within 1.1 %
}

// two hinged boxes at rest in water without gravity: nothing moves, to the bit
TEST(ViscousDrag, APassiveBodyInWaterStaysExactlyAtRest) {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  plan.parts.push_back(test::hingedChild());
  InWater water(plan, 100, 0);
  const Vec3 start = water.simulation.centerOfMass();
  for (int s = 0; s < 1200; ++s)
    water.simulation.step(false);
  EXPECT_EQ(water.simulation.status(), EvalStatus::ok);
  EXPECT_EQ(water.simulation.centerOfMass(), start);
}

}  // namespace
}  // namespace cambrian
