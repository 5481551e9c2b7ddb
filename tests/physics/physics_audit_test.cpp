// Tests of the physics audits on hand-made bodies: a body at rest stays at rest, a passive body
// whose parts fall onto each other gains no energy, and the energy watch sees what it should.
#include "physics/physics_audit.hpp"

#include "physics/box_part.hpp"
#include "physics/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian {
namespace {

using test::box;

// a plank on the ground with a passive hinged flap at its +x end
BodyPlan hingedPlank() {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  PartPlan flap = box({0.3, 0.1, 0.1}, {0.35, 0, 0}, 0);
  flap.joint = JointType::revolute;
  flap.pivot_in_parent = {0.2, 0, 0};
  flap.pivot_in_child = {-0.15, 0, 0};
  flap.joint_limit = {1.0, 1.0, 1.0};
  plan.parts.push_back(flap);
  return plan;
}

// a plank with two boards hinged on its top face at either end, each leaning `lean` rad towards
// the other: they fall, meet above the plank's middle and hold each other up (an A-frame) when
// parts collide; without self-collision they pass through each other
BodyPlan leaningBoards(double lean) {
  BodyPlan plan;
  plan.parts.push_back(box({0.6, 0.2, 0.1}, {0, 0, 0}));
  for (double side : {-1.0, 1.0}) {
    double angle = -side * lean;  // about +y: the left board (side -1) leans towards +x
    PartPlan board = box({0.05, 0.2, 0.4}, {}, 0);
    board.joint = JointType::revolute;
    board.parent_to_child = quatFromEuler({0, angle, 0});
    board.pose.rotation = board.parent_to_child;
    board.pivot_in_parent = {side * 0.25, 0, 0.05};
    board.pivot_in_child = {0, 0, -0.2};
    board.pose.position = board.pivot_in_parent - rotate(board.pose.rotation, board.pivot_in_child);
    board.axes[0] = {0, 1, 0};
    board.joint_limit = {1.3, 1.3, 1.3};
    plan.parts.push_back(board);
  }
  return plan;
}

// a passive body run for `seconds`
struct Passive {
  Environment environment;
  Simulation simulation;
  Passive(const BodyPlan& plan, const PhysicsSettings& physics, double seconds)
      : simulation(plan, nullptr, environment, physics) {
    for (long s = 0; s < std::lround(seconds / physics.time_step); ++s)
      simulation.step(false);
  }
};

// a single block comes to rest at once and does not move afterwards
TEST(PhysicsAudit, BlockAtRestStaysAtRest) {
  BodyPlan plan;
  plan.parts.push_back(box({0.2, 0.3, 0.1}, {0, 0, 0}));
  RestAudit audit = auditRest(plan, Environment{}, PhysicsSettings{}, AuditSettings{});
  ASSERT_EQ(audit.status, EvalStatus::ok) << audit.message;
  EXPECT_TRUE(audit.at_rest);
  EXPECT_LT(audit.rest_time, 1.0);
  EXPECT_LT(audit.creep, 1e-6);
  EXPECT_LT(std::abs(audit.rise), 1e-6);
  EXPECT_LT(audit.unexplained, 1e-3 * audit.energy_scale);
}

// a jointed passive body settles and then stays where it is: under 1 mm in 10 s
TEST(PhysicsAudit, HingedBodyAtRestStaysAtRest) {
  RestAudit audit = auditRest(hingedPlank(), Environment{}, PhysicsSettings{}, AuditSettings{});
  ASSERT_EQ(audit.status, EvalStatus::ok) << audit.message;
  EXPECT_TRUE(audit.at_rest);
  EXPECT_LT(audit.creep, 1e-3);
  EXPECT_LT(audit.unexplained, 0.01 * audit.energy_scale);
}

// the boards meet and hold each other up when parts collide, and pass through each other when
// they do not; the collision makes no energy (the energy audit of a self-colliding body)
TEST(PhysicsAudit, SelfCollidingBodyGainsNoEnergy) {
  PhysicsSettings touching, passing;
  passing.self_collision = false;
  Passive with(leaningBoards(0.3), touching, 5.0);
  Passive without(leaningBoards(0.3), passing, 5.0);
  ASSERT_EQ(with.simulation.status(), EvalStatus::ok) << with.simulation.message();
  ASSERT_EQ(without.simulation.status(), EvalStatus::ok) << without.simulation.message();

  // held up: the boards' centres stay high (0.26 m: leaning about 0.6 rad on the pivots 0.1 m up);
  // passing through each other they fall flat (0.09 m)
  double held = with.simulation.world().partPosition(1).z;
  double fallen = without.simulation.world().partPosition(1).z;
  EXPECT_GT(held, 0.17);
  EXPECT_LT(fallen, 0.15);

  // energy: what gravity explains, within 1 % of weight x length, in both
  EXPECT_LT(with.simulation.unexplainedEnergy(), 0.01 * with.simulation.energyScale());
  EXPECT_LT(without.simulation.unexplainedEnergy(), 0.01 * without.simulation.energyScale());
  EXPECT_GT(with.simulation.energyScale(), 0);
}

// a plank with a light flap (4 cm, 64 g) hanging on a hinge over its end, limits wide open
BodyPlan plankWithLightFlap() {
  BodyPlan plan;
  plan.parts.push_back(box({0.4, 0.2, 0.1}, {0, 0, 0}));
  PartPlan flap = box({0.04, 0.04, 0.04}, {0.22, 0, 0}, 0);
  flap.joint = JointType::revolute;
  flap.axes[0] = {0, 1, 0};
  flap.pivot_in_parent = {0.2, 0, 0};
  flap.pivot_in_child = {-0.02, 0, 0};
  flap.joint_limit = {3.0, 3.0, 3.0};
  plan.parts.push_back(flap);
  return plan;
}

// joint damping stiff for a light limb (damping x Bullet step / the limb's inertia well above 2):
// as an explicit torque from the speed before the step it reverses the limb's speed and grows
// it, each step, until the energy watch ends the body; solved implicitly it only takes energy
// out: the flap sinks slowly, held back by the damping
TEST(PhysicsAudit, StiffDampingOnALightLimbTakesEnergyOut) {
  PhysicsSettings implicit;
  implicit.joint_damping = 2;
  PhysicsSettings explicit_torque = implicit;
  explicit_torque.implicit_damping = false;
  Passive explicit_run(plankWithLightFlap(), explicit_torque, 3.0);
  EXPECT_EQ(explicit_run.simulation.status(), EvalStatus::exploded)
      << explicit_run.simulation.message();

  Passive implicit_run(plankWithLightFlap(), implicit, 3.0);
  ASSERT_EQ(implicit_run.simulation.status(), EvalStatus::ok) << implicit_run.simulation.message();
  EXPECT_LT(implicit_run.simulation.unexplainedEnergy(),
            1e-3 * implicit_run.simulation.energyScale());
  EXPECT_LT(implicit_run.simulation.fastestPartSpeed(), 0.01);
}

// where damping x step is small against the limb's inertia the two models are the same physics:
// a leaning board falling against a stiff damper, at 2 kHz
TEST(PhysicsAudit, ImplicitAndExplicitDampingAgreeAtAFineStep) {
  PhysicsSettings implicit;
  implicit.joint_damping = 2;
  implicit.time_step = 0.0005;
  implicit.substeps = 1;
  implicit.self_collision = false;  // the boards pass each other: each falls on its own
  PhysicsSettings explicit_torque = implicit;
  explicit_torque.implicit_damping = false;
  Passive with_implicit(leaningBoards(0.3), implicit, 0.5);
  Passive with_explicit(leaningBoards(0.3), explicit_torque, 0.5);
  const double angle = with_implicit.simulation.world().jointPosition(1, 0);
  EXPECT_GT(std::abs(angle), 0.05);  // the board has fallen some way, held back by the damper
  EXPECT_NEAR(angle, with_explicit.simulation.world().jointPosition(1, 0), 0.01 * std::abs(angle));
}

// a body at rest: its energy is its weight times the height of its centre, none of it unexplained
TEST(PhysicsAudit, EnergyAtRestIsWeightTimesHeight) {
  PhysicsSettings physics;
  physics.max_energy_gain = 0;  // watched, not enforced
  Passive resting(hingedPlank(), physics, 2.0);
  EXPECT_LT(resting.simulation.unexplainedEnergy(), 1e-3 * resting.simulation.energyScale());

  // the same body in the same world, its mechanical energy read through the world
  const World& world = resting.simulation.world();
  double mass = 0;
  for (const PartPlan& part : hingedPlank().parts)
    mass += part.mass;
  // at rest: all potential, m g z of the centres (the plank and flap lie 0.05 m up)
  EXPECT_NEAR(world.mechanicalEnergy(), mass * physics.gravity * 0.05, 0.01 * mass);
  EXPECT_EQ(world.effectorWorkBound(), 0.0);
}

// the audit of a driven body: a hinged flap flapping under its motor gains no unexplained energy
TEST(PhysicsAudit, DrivenBodyEnergyIsExplained) {
  BodyPlan plan = hingedPlank();
  plan.effectors.push_back(EffectorPlan{1, 0});
  // a controller whose command flips sign every half second
  struct Flip : ControllerPlan {
    struct Run : Controller {
      double time_step, time = 0;
      explicit Run(double dt) : time_step(dt) {}
      void step(std::span<const double>, std::span<double> drives) override {
        time += time_step;
        drives[0] = std::fmod(time, 1.0) < 0.5 ? 1.0 : -1.0;
      }
      void reset() override { time = 0; }
    };
    std::string kind() const override { return "flip"; }
    std::unique_ptr<Controller> build(double dt, std::size_t, std::size_t) const override {
      return std::make_unique<Run>(dt);
    }
  };
  Flip controller;
  AuditSettings settings;
  settings.driven = 5;
  DrivenAudit audit = auditDriven(plan, &controller, Environment{}, PhysicsSettings{}, settings);
  ASSERT_EQ(audit.status, EvalStatus::ok) << audit.message;
  EXPECT_LT(audit.unexplained, 0.05 * audit.energy_scale);
}

}  // namespace
}  // namespace cambrian
