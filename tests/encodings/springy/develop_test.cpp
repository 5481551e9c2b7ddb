// The springy organism as a body (Algorithms B.1 and B.2) and in Bullet's rigid-body world: the
// thesis' worked examples of bodies and proxies, a muscle following its sinusoid, rods keeping
// their lengths, a passive organism at rest, tubes that touch and tubes that do not.
#include "encodings/springy/develop.hpp"

#include "organisms.hpp"
#include "physics/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian::springy {
namespace {

using test::node;
using test::tube;

// the thesis' world (Table 4.1, Table 4.2): step 0.01 s, gravity 10, no bounce, rigid bodies
PhysicsSettings thesisPhysics() {
  PhysicsSettings physics;
  physics.world = "rigid_bodies";
  physics.time_step = 0.01;
  physics.gravity = 10;
  physics.restitution = 0;
  physics.max_speed = 100;
  return physics;
}

// the same with the thesis' soft rows, "CFM (global) 0.01" with ODE's default ERP 0.2: every
// joint, motor and contact row a spring of 2000 N/m and a damper of 80 N s/m
PhysicsSettings softThesisPhysics() {
  PhysicsSettings physics = thesisPhysics();
  physics.global_cfm = 0.01;
  physics.global_erp = 0.2;
  return physics;
}

// a triangle of three muscles a-b, b-c, c-a
Organism triangle() {
  Organism o;
  o.nodes = {node("a", 0, 0, 0.1), node("b", 1, 0, 0.1), node("c", 0.5, 0.8, 0.1)};
  o.tubes = {tube("ab", 0, 1, TubeKind::muscle), tube("bc", 1, 2, TubeKind::muscle),
             tube("ca", 2, 0, TubeKind::muscle)};
  for (Tube& t : o.tubes)
    t.muscle.rest_length = initialLength(o, t);
  return o;
}

double distance(const Simulation& simulation, int part_a, int part_b) {
  std::vector<Transform> poses;
  simulation.partPoses(poses);
  return norm(poses[static_cast<std::size_t>(part_a)].position -
              poses[static_cast<std::size_t>(part_b)].position);
}

// the part that is node n's main body
int mainBody(const BodyPlan& plan, int n) {
  for (std::size_t i = 0; i < plan.parts.size(); ++i)
    if (plan.parts[i].node == n && plan.parts[i].solid)
      return static_cast<int>(i);
  return -1;
}

// the thesis' worked examples: two nodes and a muscle, 2 main bodies and no proxy; a triangle of
// muscles, 3 main bodies, 3 proxies on 3 universal joints, each node's 1 kg split 0.5 + 0.5
TEST(SpringyBody, AlgorithmB1MakesTheThesisBodiesAndProxies) {
  const BodyCounts pair = countBodies(test::screenshotMuscle());
  EXPECT_EQ(pair.main_bodies, 2);
  EXPECT_EQ(pair.proxies, 0);
  EXPECT_EQ(pair.sliders, 1);
  const BodyCounts counts = countBodies(triangle());
  EXPECT_EQ(counts.main_bodies, 3);
  EXPECT_EQ(counts.proxies, 3);
  EXPECT_EQ(counts.universal_joints, 3);
  EXPECT_EQ(counts.sliders, 3);
  const Creature creature = developOrganism(triangle(), BodySettings{});
  ASSERT_EQ(creature.body.parts.size(), 6u);
  for (const PartPlan& part : creature.body.parts)
    EXPECT_DOUBLE_EQ(part.mass, 0.5);
  EXPECT_DOUBLE_EQ(creature.body.totalMass(), 3.0);
  // every slider in the tree, one effector each; a rod-free triangle closes one loop
  EXPECT_EQ(creature.body.effectors.size(), 3u);
  for (const EffectorPlan& effector : creature.body.effectors)
    EXPECT_EQ(creature.body.parts[static_cast<std::size_t>(effector.part)].joint,
              JointType::prismatic);
  EXPECT_EQ(creature.body.jointCount(), 6);
  // a pyramid: rods between main bodies, the muscles at the apex through proxies
  const BodyCounts pyramid = countBodies(test::pyramid());
  EXPECT_EQ(pyramid.fixed_joints, 3);
  EXPECT_EQ(pyramid.proxies, 2 + 3);  // the apex's second and third muscle, each corner's muscle
}

// a lone muscle in zero gravity follows L_r + A sin(2 pi f t + phi) (the Fig. A.5 muscle), to
// a micrometre with rigid rows, to a centimetre with the thesis' soft ones
double loneMuscleError(const PhysicsSettings& physics) {
  const Organism organism = test::screenshotMuscle();
  const Creature creature = developOrganism(organism, BodySettings{});
  Environment environment;
  environment.ground.kind = Ground::Kind::none;
  environment.gravity = 0.0;
  Simulation simulation(creature.body, creature.controller.get(), environment, physics);
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  double worst = 0;
  for (int s = 0; s < 500; ++s) {
    simulation.step(true);
    const double expected = muscleLength(organism.tubes[0].muscle, 1.04, simulation.time());
    worst = std::max(worst, std::abs(distance(simulation, 0, 1) - expected));
  }
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  return worst;
}

TEST(SpringyBody, AMuscleFollowsItsSinusoid) {
  const double rigid = loneMuscleError(thesisPhysics());
  EXPECT_LT(rigid, 1e-6) << rigid;  // within a micrometre over 5 s
  // under the thesis' soft rows the motor is a damper (its row mixes in cfm / step of its
  // impulse): the muscle, at up to 2.4 m/s, lags its sinusoid by millimetres
  const double soft = loneMuscleError(softThesisPhysics());
  EXPECT_LT(soft, 1e-2) << soft;
  EXPECT_GT(soft, 1e-4) << soft;
}

// a pyramid whose muscles move: the rods keep their lengths, the muscles follow their
// sinusoids, and nothing comes apart, on the ground under gravity
struct TubeErrors {
  double rod = 0, muscle = 0;
};
TubeErrors pyramidTubeErrors(const PhysicsSettings& thesis) {
  Organism organism = test::pyramid();
  for (Tube& t : organism.tubes) {
    if (t.kind == TubeKind::muscle)
      t.muscle = {initialLength(organism, t), 0.1, 1.0, FirstMove::lengthen};
  }
  const Creature creature = developOrganism(organism, BodySettings{});
  PhysicsSettings physics = thesis;
  physics.max_joint_error = 0.1;
  Simulation simulation(creature.body, creature.controller.get(), Environment{}, physics);
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  double rod_error = 0, muscle_error = 0;
  const int top = mainBody(creature.body, 3);
  for (int s = 0; s < 500; ++s) {
    simulation.step(true);
    for (int k = 0; k < 3; ++k)
      rod_error = std::max(rod_error, std::abs(distance(simulation, mainBody(creature.body, k),
                                                        mainBody(creature.body, (k + 1) % 3)) -
                                               1.0));
    const Tube& m = organism.tubes[3];
    muscle_error = std::max(
        muscle_error,
        std::abs(distance(simulation, top, mainBody(creature.body, 0)) -
                 muscleLength(m.muscle, initialLength(test::pyramid(), m), simulation.time())));
  }
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  return {rod_error, muscle_error};
}

TEST(SpringyBody, RodsKeepTheirLengthsWhileTheMusclesMove) {
  const TubeErrors rigid = pyramidTubeErrors(thesisPhysics());
  EXPECT_LT(rigid.rod, 1e-3) << rigid.rod;
  EXPECT_LT(rigid.muscle, 1e-3) << rigid.muscle;
  // the soft rows give: the rods by their loads over 2000 N/m, the muscles' motors lag
  const TubeErrors soft = pyramidTubeErrors(softThesisPhysics());
  EXPECT_LT(soft.rod, 5e-3) << soft.rod;
  EXPECT_LT(soft.muscle, 1e-2) << soft.muscle;
}

// with its muscles holding their initial lengths, an organism on the ground, once it has settled
// for a second (soft rows sink it into the ground), does not move
TEST(SpringyBody, APassiveOrganismDoesNotMove) {
  const Creature creature = developOrganism(test::pyramid(), BodySettings{});
  for (const PhysicsSettings& physics : {thesisPhysics(), softThesisPhysics()}) {
    Simulation simulation(creature.body, creature.controller.get(), Environment{}, physics);
    ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
    for (int s = 0; s < 100; ++s)
      simulation.step(false);
    const Vec3 start = simulation.centerOfMass();
    for (int s = 0; s < 1000; ++s)
      simulation.step(false);
    EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
    EXPECT_LT(norm(simulation.centerOfMass() - start), 1e-3) << physics.global_cfm;
  }
}

// tubes meeting at a node, and a tube and its own nodes, never touch; the birth check passes
// though every capsule starts inside its node's sphere
TEST(SpringyBody, TubesSharingANodeDoNotTouch) {
  const Creature creature = developOrganism(test::pyramid(), BodySettings{});
  PhysicsSettings physics = thesisPhysics();
  physics.max_contact_rate = 0;  // no touch between parts at all
  Simulation simulation(creature.body, creature.controller.get(), Environment{}, physics);
  ASSERT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
  for (int s = 0; s < 100; ++s)
    simulation.step(false);
  EXPECT_EQ(simulation.status(), EvalStatus::ok) << simulation.message();
}

// the monitors: a joint error and a spin beyond tiny limits end the run with their statuses
TEST(SpringyBody, TheMonitorsGiveTheirStatuses) {
  Organism organism = test::pyramid();
  for (Tube& t : organism.tubes) {
    if (t.kind == TubeKind::muscle)
      t.muscle = {initialLength(organism, t), 0.15, 2.0, FirstMove::shorten};
  }
  const Creature creature = developOrganism(organism, BodySettings{});
  PhysicsSettings physics = thesisPhysics();
  physics.max_joint_error = 1e-9;
  Simulation error(creature.body, creature.controller.get(), Environment{}, physics);
  for (int s = 0; s < 200; ++s)
    error.step(true);
  EXPECT_EQ(error.status(), EvalStatus::joint_error) << error.message();
  EXPECT_NE(error.message().find("physics.max_joint_error"), std::string::npos);
  physics = thesisPhysics();
  physics.max_angular_speed = 1e-3;
  Simulation spin(creature.body, creature.controller.get(), Environment{}, physics);
  for (int s = 0; s < 200; ++s)
    spin.step(true);
  EXPECT_EQ(spin.status(), EvalStatus::exploded) << spin.message();
  EXPECT_NE(spin.message().find("physics.max_angular_speed"), std::string::npos);
}

// the Featherstone world builds no closed loops, carried colliders or position effectors: it
// refuses an organism and names the world that builds it
TEST(SpringyBody, TheFeatherstoneWorldRefusesOrganisms) {
  const Creature lone = developOrganism(test::screenshotMuscle(), BodySettings{});
  PhysicsSettings physics = thesisPhysics();
  physics.world = "featherstone";
  Simulation simulation(lone.body, lone.controller.get(), Environment{}, physics);
  EXPECT_EQ(simulation.status(), EvalStatus::invalid_body);
  EXPECT_NE(simulation.message().find("rigid_bodies"), std::string::npos) << simulation.message();
}

}  // namespace
}  // namespace cambrian::springy
