#include "cambrian/evaluate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace cambrian {
namespace {

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// short settings so the suite stays quick
TaskSettings shortWalk() {
  TaskSettings task;
  task.evaluation_time = 3;
  return task;
}

// every effector and joint controller switched off
Genome withoutEffectors(Genome genome) {
  for (PartGene& node : genome.nodes)
    node.effectors.clear();
  for (ConnectionGene& connection : genome.connections)
    connection.controller.enabled = false;
  return genome;
}

bool bitIdentical(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// the hand-written walker walks: a positive distance with status ok
TEST(Evaluate, WalkerMoves) {
  Genome walker = readGenomeFile(kCreatures + "walker4.genome");
  Outcome outcome = evaluate(walker, GenomeLimits{}, shortWalk(), PhysicsSettings{});
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  EXPECT_EQ(outcome.parts, 5);
  EXPECT_EQ(outcome.joints, 4);
  EXPECT_GT(outcome.measure("distance"), 0.0);
  EXPECT_EQ(outcome.fitness, outcome.measure("distance"));
  EXPECT_GT(outcome.steps, 0u);
}

// no energy from nothing: with every effector off, creatures do not travel
TEST(Evaluate, NoEffectorsNoTravel) {
  for (const char* name : {"walker4.genome", "snake.genome", "pole.genome"}) {
    Genome passive = withoutEffectors(readGenomeFile(kCreatures + name));
    Outcome outcome = evaluate(passive, GenomeLimits{}, shortWalk(), PhysicsSettings{});
    ASSERT_EQ(outcome.status, EvalStatus::ok) << name << ": " << outcome.message;
    EXPECT_LT(outcome.measure("distance"), 0.005) << name;
  }
}

// passive random creatures do not travel either
TEST(Evaluate, PassiveRandomCreaturesStayPut) {
  GenomeLimits limits;
  int evaluated = 0;
  for (std::uint64_t seed = 1; seed <= 200 && evaluated < 10; ++seed) {
    Genome passive = withoutEffectors(randomGenome(limits, seed));
    if (!isViable(passive, limits, PhysicsSettings{}))
      continue;
    Outcome outcome = evaluate(passive, limits, shortWalk(), PhysicsSettings{});
    ASSERT_EQ(outcome.status, EvalStatus::ok) << "seed " << seed << ": " << outcome.message;
    ++evaluated;
    EXPECT_LT(outcome.measure("distance"), 0.05) << "seed " << seed;
  }
  EXPECT_EQ(evaluated, 10);
}

// viability: valid bodies pass, overlapping ones fail with the reason
TEST(Evaluate, Viability) {
  Genome pole = readGenomeFile(kCreatures + "pole.genome");
  std::string reason;
  EXPECT_TRUE(isViable(pole, GenomeLimits{}, PhysicsSettings{}, &reason)) << reason;
  pole.connections.push_back(pole.connections[0]);
  EXPECT_FALSE(isViable(pole, GenomeLimits{}, PhysicsSettings{}, &reason));
  EXPECT_NE(reason.find("self_penetration"), std::string::npos) << reason;
  pole.nodes[0].dimensions.y = -1;
  EXPECT_FALSE(isViable(pole, GenomeLimits{}, PhysicsSettings{}, &reason));
}

// the same genome evaluated twice gives bit-identical outcomes
TEST(Evaluate, DeterministicInOneProcess) {
  Genome walker = readGenomeFile(kCreatures + "walker4.genome");
  Outcome a = evaluate(walker, GenomeLimits{}, shortWalk(), PhysicsSettings{});
  Outcome b = evaluate(walker, GenomeLimits{}, shortWalk(), PhysicsSettings{});
  EXPECT_TRUE(bitIdentical(a.fitness, b.fitness));
  EXPECT_EQ(a.measures, b.measures);
  EXPECT_EQ(a.steps, b.steps);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Genome random = randomGenome(GenomeLimits{}, seed);
    Outcome c = evaluate(random, GenomeLimits{}, shortWalk(), PhysicsSettings{});
    Outcome d = evaluate(random, GenomeLimits{}, shortWalk(), PhysicsSettings{});
    EXPECT_EQ(c.status, d.status);
    EXPECT_TRUE(bitIdentical(c.fitness, d.fitness)) << "seed " << seed;
  }
}

// a genome that breaks a rule gets invalid_body and the worst fitness
TEST(Evaluate, InvalidGenome) {
  Genome genome = readGenomeFile(kCreatures + "pole.genome");
  genome.nodes[0].dimensions.x = 0;
  Outcome outcome = evaluate(genome, GenomeLimits{}, shortWalk(), PhysicsSettings{});
  EXPECT_EQ(outcome.status, EvalStatus::invalid_body);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
  EXPECT_NE(outcome.message.find("dimensions"), std::string::npos) << outcome.message;
}

// an overlapping body gets self_penetration
TEST(Evaluate, SelfPenetration) {
  Genome genome = readGenomeFile(kCreatures + "pole.genome");
  ConnectionGene twin = genome.connections[0];
  genome.connections.push_back(twin);  // a second child on the same spot
  Outcome outcome = evaluate(genome, GenomeLimits{}, shortWalk(), PhysicsSettings{});
  EXPECT_EQ(outcome.status, EvalStatus::self_penetration) << outcome.message;
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// absurd explicit torques explode; the monitor catches it
TEST(Evaluate, Exploded) {
  Genome walker = readGenomeFile(kCreatures + "walker4.genome");
  PhysicsSettings physics;
  physics.actuation = Actuation::torque;
  physics.strength_per_area = 1e13;
  Outcome outcome = evaluate(walker, GenomeLimits{}, shortWalk(), physics);
  EXPECT_TRUE(outcome.status == EvalStatus::exploded || outcome.status == EvalStatus::non_finite)
      << statusName(outcome.status);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// the wall-clock bound stops an evaluation with a status
TEST(Evaluate, Timeout) {
  Genome walker = readGenomeFile(kCreatures + "walker4.genome");
  PhysicsSettings physics;
  physics.max_wall_seconds = 1e-9;
  Outcome outcome = evaluate(walker, GenomeLimits{}, shortWalk(), physics);
  EXPECT_EQ(outcome.status, EvalStatus::timeout);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// jump measures the height of the lowest point; a resting creature scores about zero
TEST(Evaluate, JumpOfPassiveCreature) {
  Genome passive = withoutEffectors(readGenomeFile(kCreatures + "walker4.genome"));
  TaskSettings task = shortWalk();
  task.kind = TaskKind::jump;
  Outcome outcome = evaluate(passive, GenomeLimits{}, task, PhysicsSettings{});
  ASSERT_EQ(outcome.status, EvalStatus::ok);
  EXPECT_LT(outcome.measure("height"), 0.01);
}

// the normalisations scale the same distance
TEST(Evaluate, Normalisations) {
  Genome walker = readGenomeFile(kCreatures + "walker4.genome");
  TaskSettings task = shortWalk();
  Outcome raw = evaluate(walker, GenomeLimits{}, task, PhysicsSettings{});
  task.normalisation = WalkNormalisation::volume;
  Outcome by_volume = evaluate(walker, GenomeLimits{}, task, PhysicsSettings{});
  task.normalisation = WalkNormalisation::chaumont;
  Outcome by_chaumont = evaluate(walker, GenomeLimits{}, task, PhysicsSettings{});
  EXPECT_EQ(raw.measure("distance"), by_volume.measure("distance"));
  EXPECT_NE(raw.fitness, by_volume.fitness);
  EXPECT_NE(raw.fitness, by_chaumont.fitness);
  EXPECT_GT(by_chaumont.fitness, 0);
}

// a two-part creature evolved under explicit torques that gains energy from the integrator
// (a thin plate driven hard through a spherical joint); a saturated motor takes the gain away
TEST(Evaluate, SaturatedMotorsDenyTheIntegratorExploit) {
  Genome exploit = readGenomeFile(std::string(CAMBRIAN_SOURCE_DIR) +
                                  "/tests/tasks/data/integrator_exploit.genome");
  TaskSettings task;  // the full 10 s walk it was evolved on
  PhysicsSettings torque;
  torque.actuation = Actuation::torque;
  Outcome with_torque = evaluate(exploit, GenomeLimits{}, task, torque);
  Outcome with_motor = evaluate(exploit, GenomeLimits{}, task, PhysicsSettings{});
  ASSERT_EQ(with_motor.status, EvalStatus::ok) << with_motor.message;
  EXPECT_LT(with_motor.measure("distance"), 1.0);
  // the fixture still is what it claims to be (about 10 m/s under explicit torques)
  EXPECT_GT(with_torque.measure("distance"), 20.0);
}

// a three-part creature evolved with self-collision on: its motor presses one part into another
// and Bullet's contact correction launches it (about 10 m/s, in the air); without self-contacts
// (the default) it stays put
TEST(Evaluate, NoSelfContactsDenyTheContactPump) {
  Genome exploit = readGenomeFile(std::string(CAMBRIAN_SOURCE_DIR) +
                                  "/tests/tasks/data/self_contact_exploit.genome");
  TaskSettings task;  // the full 10 s walk it was evolved on
  PhysicsSettings self_contacts;
  self_contacts.self_collision = true;
  Outcome with_contacts = evaluate(exploit, GenomeLimits{}, task, self_contacts);
  Outcome without = evaluate(exploit, GenomeLimits{}, task, PhysicsSettings{});
  ASSERT_EQ(without.status, EvalStatus::ok) << without.message;
  EXPECT_LT(without.measure("distance"), 1.0);
  // the fixture still is what it claims to be
  EXPECT_GT(with_contacts.measure("distance"), 20.0);
}

}  // namespace
}  // namespace cambrian
