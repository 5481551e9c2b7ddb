// Tests of ODE's soft rows in the rigid-body world: the conversion keeps ODE's spring and damper
// at any substep; a resting sphere sinks into the ground by its weight over the spring's
// stiffness, the same at 1, 2 and 4 substeps, and by the slop alone with rigid rows; a soft joint
// gives by its load over the same stiffness; the setting is refused outside the rigid-body
// world. The direct solve (physics.constraint_solver = dantzig) gives the same springs at any
// substep and any iteration count, and is refused without soft rows.
#include "physics/soft_constraints.hpp"

#include "cambrian/error.hpp"

#include "box_part.hpp"
#include "core/settings.hpp"
#include "physics/physics_settings.hpp"
#include "physics/rigid_body_world.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace cambrian {
namespace {

TEST(SoftConstraints, AtItsOwnStepTheRowsAreODEs) {
  const SoftRows same = softRowsAt(0.01, 0.2, 0.01, 0.01);
  EXPECT_DOUBLE_EQ(same.cfm, 0.01);
  EXPECT_DOUBLE_EQ(same.erp, 0.2);
  const SoftRows rigid = softRowsAt(0, 0.3, 0.01, 0.005);
  EXPECT_EQ(rigid.cfm, 0);
  EXPECT_EQ(rigid.erp, 0.3);
}

TEST(SoftConstraints, AtAnySubstepTheSpringAndDamperStay) {
  // ODE: stiffness erp / (h cfm) = 2000 N/m, damping (1 - erp) / cfm = 80 N s/m
  for (double substep : {0.01, 0.005, 0.0025, 0.001}) {
    const SoftRows rows = softRowsAt(0.01, 0.2, 0.01, substep);
    EXPECT_NEAR(rows.erp / (substep * rows.cfm), 2000, 1e-9) << substep;
    EXPECT_NEAR((1 - rows.erp) / rows.cfm, 80, 1e-9) << substep;
  }
}

// `plan` (which the world refers to: keep it) after 3 s in the rigid-body world under gravity
// 10 m/s^2 and ODE's rows of `cfm` (0: rigid) and erp 0.2 at 0.01 s
std::unique_ptr<World> after3s(const BodyPlan& plan, double cfm, int substeps,
                               ConstraintSolver solver = ConstraintSolver::sequential_impulse,
                               int iterations = PhysicsSettings{}.solver_iterations) {
  PhysicsSettings physics;
  physics.world = RigidBodyWorld::kName;
  physics.time_step = 0.01;
  physics.substeps = substeps;
  physics.gravity = 10;
  physics.global_cfm = cfm;
  physics.global_erp = 0.2;
  physics.constraint_solver = solver;
  physics.solver_iterations = iterations;
  auto world = makeWorld(plan, Environment{}, physics, 0.0);
  for (int s = 0; s < 300; ++s)
    world->step({});
  return world;
}

// a 1 kg sphere of radius 0.1 m (the springy organisms' node) resting on the ground: how deep
// it sits
double restingDepth(double cfm, int substeps,
                    ConstraintSolver solver = ConstraintSolver::sequential_impulse) {
  BodyPlan plan;
  PartPlan node;
  node.shape = PartShape::sphere;
  node.size = {0.2, 0.2, 0.2};
  node.mass = 1;
  plan.parts.push_back(node);
  auto world = after3s(plan, cfm, substeps, solver);
  return -world->lowestPoint();
}

TEST(SoftConstraints, ARestingSphereSinksByItsWeightOverTheStiffness) {
  // 10 N on 2000 N/m: 5 mm below the contact slop (1 mm, which no row corrects)
  const double slop = PhysicsSettings{}.contact_slop;
  for (int substeps : {1, 2, 4})
    EXPECT_NEAR(restingDepth(0.01, substeps), slop + 0.005, 2e-4) << substeps << " substeps";
  EXPECT_NEAR(restingDepth(0, 2), slop, 2e-4);
}

// a 1 kg box on top of a 1 kg box resting on the ground, on a hinge held at 0 rad: the joint
// carries the upper box's 10 N
BodyPlan stackedBoxes() {
  BodyPlan plan;
  plan.parts.push_back(test::box({0.2, 0.2, 0.1}, {0, 0, 0}));
  PartPlan upper = test::hingedChild();
  upper.size = {0.2, 0.2, 0.1};
  upper.pose.position = {0, 0, 0.1};
  upper.pivot_in_parent = {0, 0, 0.05};
  upper.pivot_in_child = {0, 0, -0.05};
  upper.joint_limit = {0, 0, 0};
  plan.parts.push_back(upper);
  for (PartPlan& part : plan.parts)
    part.mass = 1;
  return plan;
}

double stackedJointError(double cfm, int substeps, ConstraintSolver solver,
                         int iterations = PhysicsSettings{}.solver_iterations) {
  return after3s(stackedBoxes(), cfm, substeps, solver, iterations)->largestJointError();
}

TEST(SoftConstraints, ASoftJointGivesByItsLoadOverTheStiffness) {
  // 10 N on 2000 N/m: the pivots part by 5 mm
  for (int substeps : {1, 4}) {
    EXPECT_NEAR(stackedJointError(0.01, substeps, ConstraintSolver::sequential_impulse), 0.005,
                2e-4)
        << substeps << " substeps";
    EXPECT_LT(stackedJointError(0, substeps, ConstraintSolver::sequential_impulse), 1e-4)
        << substeps << " substeps";
  }
}

TEST(SoftConstraints, OnlyTheRigidBodyWorldHasThem) {
  SettingsSchema schema;
  PhysicsSettings physics;
  physics.declareSettings(schema);
  schema.set("physics.global_cfm", "0.01");
  EXPECT_THROW(schema.check(), ConfigError);
  schema.set("physics.world", "rigid_bodies");
  EXPECT_NO_THROW(schema.check());
}

TEST(DirectSolve, ARestingSphereSinksAsUnderIterations) {
  const double slop = PhysicsSettings{}.contact_slop;
  for (int substeps : {1, 2, 4})
    EXPECT_NEAR(restingDepth(0.01, substeps, ConstraintSolver::dantzig), slop + 0.005, 2e-4)
        << substeps << " substeps";
}

TEST(DirectSolve, ASoftJointGivesByItsLoadAtAnyIterationCount) {
  // one sweep allowed gives the spring's 5 mm: the direct solve does not iterate (a step it
  // leaves to sequential impulses, which they solve over the same soft rows, is counted)
  for (int substeps : {1, 2, 4, 8})
    EXPECT_NEAR(stackedJointError(0.01, substeps, ConstraintSolver::dantzig, 1), 0.005, 2e-5)
        << substeps << " substeps";
  // at 1 substep no step falls back, and one sweep is fifty, bit for bit; not so iterating
  const BodyPlan plan = stackedBoxes();  // a world keeps a reference to its plan
  auto one = after3s(plan, 0.01, 1, ConstraintSolver::dantzig, 1);
  auto fifty = after3s(plan, 0.01, 1, ConstraintSolver::dantzig, 50);
  EXPECT_EQ(dynamic_cast<const RigidBodyWorld&>(*one).directSolveFallbacks(), 0);
  EXPECT_EQ(one->largestJointError(), fifty->largestJointError());
  EXPECT_EQ(one->partPosition(1).x, fifty->partPosition(1).x);
  EXPECT_NE(stackedJointError(0.01, 1, ConstraintSolver::sequential_impulse, 1),
            stackedJointError(0.01, 1, ConstraintSolver::sequential_impulse, 50));
}

TEST(DirectSolve, OnlyTheRigidBodyWorldWithSoftRowsHasIt) {
  SettingsSchema schema;
  PhysicsSettings physics;
  physics.declareSettings(schema);
  schema.set("physics.constraint_solver", "dantzig");
  EXPECT_THROW(schema.check(), ConfigError);  // the Featherstone world
  schema.set("physics.world", "rigid_bodies");
  EXPECT_THROW(schema.check(), ConfigError);  // rigid rows
  schema.set("physics.global_cfm", "0.01");
  EXPECT_NO_THROW(schema.check());
  EXPECT_THROW(
      {
        schema.set("physics.constraint_solver", "lemke");  // a choice is refused when set
        schema.check();
      },
      ConfigError);
}

}  // namespace
}  // namespace cambrian
