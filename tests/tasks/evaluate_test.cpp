// Tests of evaluating one creature through the creature settings: walking, passivity, viability,
// determinism, every failure status, the observer, jump heights, normalisations, the known
// exploits, and the rest rule.
#include "cambrian/evaluate.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "physics/physics_audit.hpp"
#include "physics/physics_settings.hpp"
#include "tasks/episode.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace cambrian {
namespace {

using graph::ConnectionGene;
using graph::Genome;
using graph::PartGene;

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// settings with `changes` (key, value) applied and checked
CreatureSettings settingsWith(
    std::initializer_list<std::pair<const char*, const char*>> changes = {}) {
  CreatureSettings settings;
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return settings;
}
CreatureSettings settingsWith(const std::vector<std::pair<std::string, std::string>>& changes) {
  CreatureSettings settings;
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return settings;
}

// a 3 s walk, so the suite stays quick, with `changes` applied
CreatureSettings shortWalk(
    std::initializer_list<std::pair<const char*, const char*>> changes = {}) {
  CreatureSettings settings = settingsWith({{"task.evaluation_time", "3"}});
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return settings;
}

// a directed-graph genome of a hand-written creature
Genome creature(const std::string& name) {
  return graph::graphGenome(readGenomeFile(kCreatures + name));
}

// evaluates a directed-graph genome
Outcome evaluateGraph(const Genome& genome, const CreatureSettings& settings,
                      FrameObserver* observer = nullptr) {
  return evaluate(graph::makeGenotype(genome), settings, 0, observer);
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
  Genome walker = creature("walker4.genome");
  Outcome outcome = evaluateGraph(walker, shortWalk());
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
    Genome passive = withoutEffectors(creature(name));
    Outcome outcome = evaluateGraph(passive, shortWalk());
    ASSERT_EQ(outcome.status, EvalStatus::ok) << name << ": " << outcome.message;
    EXPECT_LT(outcome.measure("distance"), 0.005) << name;
  }
}

// passive random creatures do not travel either
TEST(Evaluate, PassiveRandomCreaturesStayPut) {
  CreatureSettings settings = shortWalk();
  int evaluated = 0;
  for (std::uint64_t seed = 1; seed <= 200 && evaluated < 10; ++seed) {
    Genome passive = withoutEffectors(graph::randomGenome(graph::GenomeLimits{}, seed));
    if (!isViable(graph::makeGenotype(passive), settings))
      continue;
    Outcome outcome = evaluateGraph(passive, settings);
    ASSERT_EQ(outcome.status, EvalStatus::ok) << "seed " << seed << ": " << outcome.message;
    ++evaluated;
    EXPECT_LT(outcome.measure("distance"), 0.05) << "seed " << seed;
  }
  EXPECT_EQ(evaluated, 10);
}

// viability: valid bodies pass, overlapping ones fail with the reason
TEST(Evaluate, Viability) {
  Genome pole = creature("pole.genome");
  std::string reason;
  const CreatureSettings settings;
  EXPECT_TRUE(isViable(graph::makeGenotype(pole), settings, &reason)) << reason;
  pole.connections.push_back(pole.connections[0]);
  EXPECT_FALSE(isViable(graph::makeGenotype(pole), settings, &reason));
  EXPECT_NE(reason.find("self_penetration"), std::string::npos) << reason;
  pole.nodes[0].dimensions.y = -1;
  EXPECT_FALSE(isViable(graph::makeGenotype(pole), settings, &reason));
  EXPECT_NE(reason.find("dimensions"), std::string::npos) << reason;
}

// the same genome evaluated twice gives bit-identical outcomes
TEST(Evaluate, DeterministicInOneProcess) {
  Genome walker = creature("walker4.genome");
  Outcome a = evaluateGraph(walker, shortWalk());
  Outcome b = evaluateGraph(walker, shortWalk());
  EXPECT_TRUE(bitIdentical(a.fitness, b.fitness));
  EXPECT_EQ(a.measures, b.measures);
  EXPECT_EQ(a.steps, b.steps);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Genome random = graph::randomGenome(graph::GenomeLimits{}, seed);
    Outcome c = evaluateGraph(random, shortWalk());
    Outcome d = evaluateGraph(random, shortWalk());
    EXPECT_EQ(c.status, d.status);
    EXPECT_TRUE(bitIdentical(c.fitness, d.fitness)) << "seed " << seed;
  }
}

// task.check_substeps: a second evaluation at other substeps, the worse of the two kept whole
TEST(Evaluate, ASecondEvaluationAtOtherSubstepsKeepsTheWorse) {
  Genome walker = creature("walker4.genome");
  const Outcome two = evaluateGraph(walker, shortWalk());
  const Outcome four = evaluateGraph(walker, shortWalk({{"physics.substeps", "4"}}));
  ASSERT_EQ(two.status, EvalStatus::ok) << two.message;
  ASSERT_EQ(four.status, EvalStatus::ok) << four.message;
  ASSERT_NE(two.fitness, four.fitness);
  const Outcome& worse = two.fitness < four.fitness ? two : four;
  for (const auto& [substeps, check] : {std::pair{"2", "4"}, std::pair{"4", "2"}}) {
    const Outcome checked = evaluateGraph(
        walker, shortWalk({{"physics.substeps", substeps}, {"task.check_substeps", check}}));
    EXPECT_EQ(checked.status, EvalStatus::ok) << checked.message;
    EXPECT_TRUE(bitIdentical(checked.fitness, worse.fitness)) << substeps << " then " << check;
    EXPECT_EQ(checked.measures, worse.measures);
    EXPECT_EQ(checked.steps, two.steps + four.steps);
  }
}

// a creature that passes at one discretisation and fails at the other fails, with the check's
// status and a message naming the key
TEST(Evaluate, ACreatureThatFailsTheSecondEvaluationFails) {
  // the first random genome (of 1..200) that walks 3 s at 2 substeps under a speed limit of
  // 1 m/s and breaks it at 1 substep
  const CreatureSettings fine = shortWalk({{"physics.max_speed", "1"}});
  const CreatureSettings coarse =
      shortWalk({{"physics.max_speed", "1"}, {"physics.substeps", "1"}});
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const Genome random = graph::randomGenome(graph::GenomeLimits{}, seed);
    const Outcome at_two = evaluateGraph(random, fine);
    const Outcome at_one = evaluateGraph(random, coarse);
    if (at_two.status != EvalStatus::ok || at_one.status == EvalStatus::ok)
      continue;
    const Outcome checked = evaluateGraph(
        random, shortWalk({{"physics.max_speed", "1"}, {"task.check_substeps", "1"}}));
    EXPECT_EQ(checked.status, at_one.status) << "seed " << seed;
    EXPECT_EQ(checked.fitness, kWorstFitness);
    EXPECT_EQ(checked.message.rfind("at task.check_substeps = 1: ", 0), 0u) << checked.message;
    return;
  }
  FAIL() << "no random genome of 1..200 passes at 2 substeps and fails at 1";
}

// a genome that breaks a rule gets invalid_body and the worst fitness
TEST(Evaluate, InvalidGenome) {
  Genome genome = creature("pole.genome");
  genome.nodes[0].dimensions.x = 0;
  Outcome outcome = evaluateGraph(genome, shortWalk());
  EXPECT_EQ(outcome.status, EvalStatus::invalid_body);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
  EXPECT_NE(outcome.message.find("dimensions"), std::string::npos) << outcome.message;
}

// task.min_parts (Minemonics discards creatures of 0 or 1 limb): the single block is not
// evaluated under 2, with the worst fitness and a message naming the setting; the pole (two
// parts) is, and so is the block under the default 1
TEST(Evaluate, FewerPartsThanTaskMinPartsIsNotEvaluated) {
  const Outcome block =
      evaluateGraph(creature("single_block.genome"), shortWalk({{"task.min_parts", "2"}}));
  EXPECT_EQ(block.status, EvalStatus::invalid_body);
  EXPECT_EQ(block.fitness, kWorstFitness);
  EXPECT_EQ(block.steps, 0u);
  EXPECT_EQ(block.parts, 1);
  EXPECT_EQ(block.message, "1 part, fewer than task.min_parts = 2");
  const Outcome pole = evaluateGraph(creature("pole.genome"), shortWalk({{"task.min_parts", "2"}}));
  EXPECT_EQ(pole.status, EvalStatus::ok) << pole.message;
  EXPECT_EQ(evaluateGraph(creature("single_block.genome"), shortWalk()).status, EvalStatus::ok);
  EXPECT_THROW(settingsWith({{"task.min_parts", "0"}}), ConfigError);
}

// an overlapping body gets self_penetration
TEST(Evaluate, SelfPenetration) {
  Genome genome = creature("pole.genome");
  ConnectionGene twin = genome.connections[0];
  genome.connections.push_back(twin);  // a second child on the same spot
  Outcome outcome = evaluateGraph(genome, shortWalk());
  EXPECT_EQ(outcome.status, EvalStatus::self_penetration) << outcome.message;
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// absurd explicit torques explode; the monitor catches it
TEST(Evaluate, Exploded) {
  Genome walker = creature("walker4.genome");
  Outcome outcome = evaluateGraph(
      walker, shortWalk({{"physics.actuation", "torque"}, {"physics.strength_per_area", "1e13"}}));
  // the speed monitor sees it before any state turns non-finite
  EXPECT_EQ(outcome.status, EvalStatus::exploded) << statusName(outcome.status);
  EXPECT_NE(outcome.message.find("physics.max_speed"), std::string::npos) << outcome.message;
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// a state that turns non-finite (here: gravity NaN, which no config allows but the API does not
// refuse) ends as non_finite, not as exploded, on the first step
TEST(Evaluate, NonFiniteStateIsCaught) {
  Genome walker = creature("walker4.genome");
  for (const char* task : {"walk", "jump"}) {
    CreatureSettings settings = shortWalk({{"task.name", task}});
    settings.physics().gravity = std::nan("");  // past the settings' checks, through the API
    Outcome outcome = evaluateGraph(walker, settings);
    EXPECT_EQ(outcome.status, EvalStatus::non_finite)
        << statusName(outcome.status) << ": " << outcome.message;
    EXPECT_EQ(outcome.fitness, kWorstFitness);
    EXPECT_EQ(outcome.steps, 1u);
    EXPECT_NE(outcome.message.find("non-finite position"), std::string::npos) << outcome.message;
  }
}

// an observer that throws part-way through
class ThrowingObserver : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan&, double, const Environment&) override {}
  void frame(const EvalFrame& frame) override {
    if (frame.step == 100)
      throw std::runtime_error("observer gave up at step 100");
  }
};

// an exception inside an evaluation becomes status failed with its message, never a crash:
// from a frame observer, and from development under a limit it cannot meet
TEST(Evaluate, ExceptionBecomesFailed) {
  Genome walker = creature("walker4.genome");
  ThrowingObserver observer;
  Outcome thrown = evaluateGraph(walker, shortWalk(), &observer);
  EXPECT_EQ(thrown.status, EvalStatus::failed) << statusName(thrown.status);
  EXPECT_EQ(thrown.fitness, kWorstFitness);
  EXPECT_EQ(thrown.message, "observer gave up at step 100");
  EXPECT_TRUE(thrown.measures.empty());

  CreatureSettings no_parts = shortWalk();
  no_parts.set("genome.max_parts", "0");  // refused by check(), not by the API
  Outcome undeveloped = evaluateGraph(walker, no_parts);
  EXPECT_EQ(undeveloped.status, EvalStatus::failed)
      << statusName(undeveloped.status) << ": " << undeveloped.message;
  EXPECT_EQ(undeveloped.fitness, kWorstFitness);
  EXPECT_NE(undeveloped.message.find("max_parts"), std::string::npos) << undeveloped.message;
}

// the wall-clock bound stops an evaluation with a status
TEST(Evaluate, Timeout) {
  Genome walker = creature("walker4.genome");
  Outcome outcome = evaluateGraph(walker, shortWalk({{"physics.max_wall_seconds", "1e-9"}}));
  EXPECT_EQ(outcome.status, EvalStatus::timeout);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// jump measures the height of the lowest point; a resting creature scores about zero
TEST(Evaluate, JumpOfPassiveCreature) {
  Genome passive = withoutEffectors(creature("walker4.genome"));
  Outcome outcome = evaluateGraph(passive, shortWalk({{"task.name", "jump"}}));
  ASSERT_EQ(outcome.status, EvalStatus::ok);
  EXPECT_LT(outcome.measure("height"), 0.01);
}

// the lowest box corner of every frame, computed from the poses and the box sizes (not through
// Simulation::lowestPoint), with the phase of each frame
class LowestPointRecorder : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan& plan, double, const Environment&) override { plan_ = &plan; }
  void frame(const EvalFrame& frame) override {
    double lowest = INFINITY;
    for (std::size_t i = 0; i < frame.poses.size(); ++i) {
      const Vec3 half = plan_->parts[i].size * 0.5;
      for (int corner = 0; corner < 8; ++corner) {
        Vec3 local{(corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y,
                   (corner & 4) ? half.z : -half.z};
        lowest = std::min(lowest, apply(frame.poses[i], local).z);
      }
    }
    lowest_.push_back(lowest);
    phases_.push_back(frame.phase);
  }
  // the highest lowest point from the last frame before measuring to the end
  double highestWhileMeasured() const {
    double best = -INFINITY;
    for (std::size_t f = 1; f < phases_.size(); ++f) {
      if (phases_[f] == EvalPhase::measure)
        best = std::max(
            {best, lowest_[f], phases_[f - 1] != EvalPhase::measure ? lowest_[f - 1] : -INFINITY});
    }
    return best;
  }
  // the frame count in a phase
  std::size_t frames(EvalPhase phase) const {
    return static_cast<std::size_t>(std::count(phases_.begin(), phases_.end(), phase));
  }

 private:
  const BodyPlan* plan_ = nullptr;
  std::vector<double> lowest_;
  std::vector<EvalPhase> phases_;
};

// walker4's bound takes all four feet off the ground: the jump task's height is clearly positive
// and is the highest the lowest box corner rose while measured, computed here from the poses
TEST(Evaluate, JumpHeightOfAHoppingCreature) {
  Genome walker = creature("walker4.genome");
  CreatureSettings task = shortWalk({{"task.name", "jump"}});
  LowestPointRecorder frames;
  Outcome outcome = evaluateGraph(walker, task, &frames);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  EXPECT_EQ(frames.frames(EvalPhase::measure),
            static_cast<std::size_t>(std::llround(task.episode().evaluation_time * 240)));
  const double height = outcome.measure("height");
  EXPECT_EQ(outcome.fitness, height);
  // 1-4 cm, depending on the physics settings (contact dynamics are chaotic: the reference gives
  // 1.8-2.9 cm): far above resting contact jitter (micrometres)
  EXPECT_GT(height, 0.01);
  EXPECT_NEAR(height, frames.highestWhileMeasured(), 1e-9);
  // the same body without its drive stays on the ground
  Outcome passive = evaluateGraph(withoutEffectors(walker), task);
  EXPECT_LT(passive.measure("height"), 0.1 * height);
}

// the normalisations scale the same distance
TEST(Evaluate, Normalisations) {
  Genome walker = creature("walker4.genome");
  Outcome raw = evaluateGraph(walker, shortWalk());
  Outcome by_volume = evaluateGraph(walker, shortWalk({{"task.normalisation", "volume"}}));
  Outcome by_chaumont = evaluateGraph(walker, shortWalk({{"task.normalisation", "chaumont"}}));
  EXPECT_EQ(raw.measure("distance"), by_volume.measure("distance"));
  EXPECT_NE(raw.fitness, by_volume.fitness);
  EXPECT_NE(raw.fitness, by_chaumont.fitness);
  EXPECT_GT(by_chaumont.fitness, 0);
}

// the walk the fixtures below were evolved on (no rest check), with `more` settings
std::vector<std::pair<std::string, std::string>> evolvedOn(
    std::vector<std::pair<std::string, std::string>> more = {}) {
  more.insert(more.begin(), {"task.rest_check", "false"});
  return more;
}
// ... and under the physics of their day: before friction anchors, contact slop, implicit joint
// damping, the energy watch, the solved middle axis of spherical joints, the solver tolerance and
// the joint speed clamp out of reach
std::vector<std::pair<std::string, std::string>> earlierPhysics(
    std::vector<std::pair<std::string, std::string>> more = {}) {
  more.insert(more.end(), {{"physics.friction_anchors", "false"},
                           {"physics.contact_slop", "0"},
                           {"physics.implicit_damping", "false"},
                           {"physics.max_energy_gain", "0"},
                           {"physics.solve_every_dof", "false"},
                           {"physics.solver_tolerance", "0"},
                           {"physics.joint_speed_clamp", "100"}});
  return evolvedOn(more);
}

// a two-part creature evolved under explicit torques that gains energy from the integrator
// (a thin plate driven hard through a spherical joint); a saturated motor takes the gain away,
// and under torques the energy watch ends it as exploded
TEST(Evaluate, SaturatedMotorsDenyTheIntegratorExploit) {
  Genome exploit = graph::graphGenome(readGenomeFile(
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/tasks/data/integrator_exploit.genome"));
  // the full 10 s walk it was evolved on
  Outcome with_motor = evaluateGraph(exploit, settingsWith(evolvedOn()));
  ASSERT_EQ(with_motor.status, EvalStatus::ok) << with_motor.message;
  EXPECT_LT(with_motor.measure("distance"), 1.0);
  Outcome watched =
      evaluateGraph(exploit, settingsWith(evolvedOn({{"physics.actuation", "torque"}})));
  EXPECT_EQ(watched.status, EvalStatus::exploded);
  EXPECT_NE(watched.message.find("physics.max_energy_gain"), std::string::npos) << watched.message;
  // the fixture still is what it claims to be (about 10 m/s under explicit torques)
  Outcome with_torque =
      evaluateGraph(exploit, settingsWith(earlierPhysics({{"physics.actuation", "torque"},
                                                          {"physics.self_collision", "false"}})));
  ASSERT_EQ(with_torque.status, EvalStatus::ok) << with_torque.message;
  EXPECT_GT(with_torque.measure("distance"), 20.0);
}

// a two-part walker bred in the Featherstone world (a 5.9 kg plate on a strong spherical joint):
// in the rigid-body world its joint comes apart under the motor and Bullet's position correction
// pushes it back with energy the energy watch ends as exploded; a softer correction
// (physics.joint_erp 0.02) lets it walk there too
TEST(Evaluate, JointCorrectionEnergyIsCaughtInTheRigidBodyWorld) {
  Genome pump = graph::graphGenome(readGenomeFile(
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/tasks/data/joint_correction_pump.genome"));
  Outcome featherstone = evaluateGraph(pump, settingsWith({}));
  ASSERT_EQ(featherstone.status, EvalStatus::ok) << featherstone.message;
  EXPECT_GT(featherstone.measure("distance"), 2.0);
  Outcome rigid = evaluateGraph(pump, settingsWith({{"physics.world", "rigid_bodies"}}));
  EXPECT_EQ(rigid.status, EvalStatus::exploded);
  EXPECT_NE(rigid.message.find("physics.max_energy_gain"), std::string::npos) << rigid.message;
  Outcome softer = evaluateGraph(
      pump, settingsWith({{"physics.world", "rigid_bodies"}, {"physics.joint_erp", "0.02"}}));
  ASSERT_EQ(softer.status, EvalStatus::ok) << softer.message;
  EXPECT_GT(softer.measure("distance"), 0.5);
}

// two spheres held together, a random Minemonics body: while the ground asked Bullet for friction
// anchors (every contact with it anchored where it began) the passive body gained 175 J and
// rolled 2.8 m away from rest in both worlds; a box's contacts are still anchored, a capsule's or
// sphere's no longer, and it rests
TEST(Evaluate, ARollingBodyGainsNoEnergyFromFrictionAnchors) {
  const Genome spheres = graph::graphGenome(readGenomeFile(
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/tasks/data/rolling_spheres.genome"));
  const Creature creature = graph::develop(spheres, graph::GenomeLimits{});
  for (const char* world : {"featherstone", "rigid_bodies"}) {
    PhysicsSettings physics;
    physics.world = world;
    physics.time_step = 1.0 / 240;
    const RestAudit audit = auditRest(creature.body, Environment{}, physics, AuditSettings{});
    ASSERT_EQ(audit.status, EvalStatus::ok) << world << ": " << audit.message;
    EXPECT_TRUE(audit.at_rest) << world;
    EXPECT_LT(audit.creep, 0.001) << world;
    EXPECT_LT(audit.unexplained, 0.01 * audit.energy_scale) << world;
  }
}

// a three-part creature evolved with self-collision on under the earlier physics: its motor
// presses one part into another and Bullet's contact correction launched it (about 10 m/s, in
// the air); with friction anchors and contact slop (the defaults) it stays near where it was,
// and without them the energy watch ends it as exploded within a second
TEST(Evaluate, SelfContactsCannotBePumped) {
  Genome exploit = graph::graphGenome(readGenomeFile(
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/tasks/data/self_contact_exploit.genome"));
  // the full 10 s walk it was evolved on
  Outcome now = evaluateGraph(exploit, settingsWith(evolvedOn()));
  ASSERT_EQ(now.status, EvalStatus::ok) << now.message;
  EXPECT_LT(now.measure("distance"), 1.0);
  Outcome watched =
      evaluateGraph(exploit, settingsWith(evolvedOn({{"physics.friction_anchors", "false"},
                                                     {"physics.contact_slop", "0"}})));
  EXPECT_EQ(watched.status, EvalStatus::exploded) << watched.message;
  EXPECT_NE(watched.message.find("physics.max_energy_gain"), std::string::npos) << watched.message;
  EXPECT_LT(watched.steps, 480u);
  // the fixture still is what it claims to be
  Outcome earlier = evaluateGraph(exploit, settingsWith(earlierPhysics()));
  ASSERT_EQ(earlier.status, EvalStatus::ok) << earlier.message;
  EXPECT_GT(earlier.measure("distance"), 20.0);
}

//---------------------------------------------------------------- the rest check

// a pendulum: a heavy 0.6 m arm on a free hinge at the top of a 1 m tower on a wide, heavy
// base, born horizontal; with the default joint damping it swings for minutes
Genome pendulum() {
  return graph::parseGenomeText(R"(cambrian-genome 2
node 0 size 1.2 1.2 0.1 density 3000 joint rigid
node 1 size 1.0 0.1 0.1 density 500 joint rigid
node 2 size 0.6 0.1 0.1 density 3000 joint revolute limit 3.1 3.1 3.1
connection 0 -> 1 position 0 0 1
connection 1 -> 2 position 1 0 0 orientation 0 1.5708 0
end
)",
                                "pendulum");
}

// the rest check on, with the default threshold, time and cap
CreatureSettings withRestCheck(CreatureSettings settings) {
  settings.set("task.rest_check", "true");
  return settings;
}
CreatureSettings withoutRestCheck(CreatureSettings settings) {
  settings.set("task.rest_check", "false");
  return settings;
}

// every frame's phase and part positions (stride 1)
class PhaseRecorder : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan&, double, const Environment&) override {}
  void frame(const EvalFrame& frame) override {
    phases.push_back(frame.phase);
    positions.emplace_back();
    for (const Transform& pose : frame.poses)
      positions.back().push_back(pose.position);
  }
  // steps taken in `phase`
  std::uint64_t stepsIn(EvalPhase phase) const {
    return static_cast<std::uint64_t>(std::count(phases.begin() + 1, phases.end(), phase));
  }
  // the fastest part's speed over step s (frames s-1 to s), m/s
  double fastest(std::size_t s, double dt) const {
    double speed = 0;
    for (std::size_t i = 0; i < positions[s].size(); ++i)
      speed = std::max(speed, norm(positions[s][i] - positions[s - 1][i]) / dt);
    return speed;
  }
  std::vector<EvalPhase> phases;  // frame 0 is the birth
  std::vector<std::vector<Vec3>> positions;
};

// the rule is on by default (a body still falling from its birth pose is not measured); off,
// the results do not depend on its other settings
TEST(Evaluate, RestCheckIsOnByDefault) {
  EXPECT_TRUE(CreatureSettings().episode().rest_check);
  Outcome swinging = evaluateGraph(pendulum(), shortWalk({{"task.rest_check", "false"}}));
  ASSERT_EQ(swinging.status, EvalStatus::ok) << swinging.message;
  Outcome same = evaluateGraph(pendulum(), shortWalk({{"task.rest_check", "false"},
                                                      {"task.rest_speed", "1e-9"},
                                                      {"task.settle_max_time", "0.5"}}));
  EXPECT_TRUE(bitIdentical(same.fitness, swinging.fitness));
  EXPECT_EQ(same.steps, swinging.steps);
}

// a block born at rest: with the check on, walk and jump give the same bits and the same
// steps as without (its settle phases are as long as settle_time and resettle_time). Without
// contact slop: with it, a body born touching the ground sinks into the slop (1 mm) in its first
// four steps, faster than the default rest speed
TEST(Evaluate, RestCheckLeavesABlockAtRestAlone) {
  Genome block = creature("single_block.genome");
  for (const char* kind : {"walk", "jump"}) {
    CreatureSettings task = shortWalk({{"task.name", kind}, {"physics.contact_slop", "0"}});
    Outcome off = evaluateGraph(block, withoutRestCheck(task));
    Outcome on = evaluateGraph(block, withRestCheck(task));
    ASSERT_EQ(on.status, EvalStatus::ok) << on.message;
    EXPECT_EQ(on.steps, off.steps) << kind;
    EXPECT_GT(on.steps, 0u);
    EXPECT_TRUE(bitIdentical(on.fitness, off.fitness)) << kind;
    EXPECT_EQ(on.measures, off.measures) << kind;
  }
}

// a settle phase shorter than rest_time lasts rest_time: the block rests from its first step
TEST(Evaluate, RestCheckSettleLastsAtLeastTheRestTime) {
  Genome block = creature("single_block.genome");
  CreatureSettings task = shortWalk(
      {{"task.name", "jump"}, {"task.settle_time", "0.1"}, {"physics.contact_slop", "0"}});
  const PhysicsSettings physics;
  Outcome off = evaluateGraph(block, withoutRestCheck(task));
  Outcome on = evaluateGraph(block, withRestCheck(task));
  ASSERT_EQ(on.status, EvalStatus::ok) << on.message;
  const auto steps = [&](double seconds) {
    return static_cast<std::uint64_t>(std::llround(seconds / physics.time_step));
  };
  EXPECT_EQ(on.steps - off.steps,
            steps(task.episode().rest_time) - steps(task.episode().settle_time));
}

// a freely swinging arm never rests: unstable with the worst fitness once settle_max_time has
// passed in the first settle phase, in walk and jump; without the check it is evaluated
TEST(Evaluate, RestCheckFindsACreatureThatNeverRests) {
  for (const char* kind : {"walk", "jump"}) {
    CreatureSettings task = shortWalk({{"task.name", kind}});
    Outcome off = evaluateGraph(pendulum(), withoutRestCheck(task));
    ASSERT_EQ(off.status, EvalStatus::ok) << off.message;
    Outcome on = evaluateGraph(pendulum(), withRestCheck(task));
    EXPECT_EQ(on.status, EvalStatus::unstable) << kind << ": " << on.message;
    EXPECT_EQ(on.fitness, kWorstFitness);
    EXPECT_TRUE(on.measures.empty());
    EXPECT_EQ(on.steps, static_cast<std::uint64_t>(std::llround(task.episode().settle_max_time /
                                                                PhysicsSettings{}.time_step)));
    EXPECT_NE(on.message.find("task.settle_max_time"), std::string::npos) << on.message;
    EXPECT_NE(on.message.find("settle phase"), std::string::npos) << on.message;
  }
}

// the same arm with heavy joint damping comes to rest: each settle phase ends at the first step,
// past its minimum, that closes rest_time of steps in which no part moved faster than
// rest_speed (checked on the recorded frames), and the run is deterministic
TEST(Evaluate, RestCheckSettlesUntilAtRest) {
  const CreatureSettings settings = withRestCheck(shortWalk({{"physics.joint_damping", "5"}}));
  const double dt = settings.physics().time_step;
  const EpisodeSettings& task = settings.episode();
  const std::uint64_t rest_steps = std::llround(task.rest_time / dt);
  PhaseRecorder frames;
  Outcome on = evaluateGraph(pendulum(), settings, &frames);
  ASSERT_EQ(on.status, EvalStatus::ok) << on.message;
  Outcome again = evaluateGraph(pendulum(), settings);
  EXPECT_EQ(again.steps, on.steps);
  EXPECT_TRUE(bitIdentical(again.fitness, on.fitness));
  ASSERT_EQ(frames.phases.size(), on.steps + 1);

  // the swinging arm made the first settle phase longer than settle_time
  const std::uint64_t settle = frames.stepsIn(EvalPhase::settle);
  const std::uint64_t resettle = frames.stepsIn(EvalPhase::resettle);
  EXPECT_GT(settle, std::llround(task.settle_time / dt) + rest_steps);
  EXPECT_EQ(frames.stepsIn(EvalPhase::trial), std::llround(task.trial_time / dt));
  EXPECT_EQ(frames.stepsIn(EvalPhase::measure), std::llround(task.evaluation_time / dt));

  // each settle phase ends exactly when the rule first holds after its minimum
  std::size_t first = 1;
  for (auto [length, minimum] : {std::pair{settle, std::llround(task.settle_time / dt)},
                                 std::pair{resettle, std::llround(task.resettle_time / dt)}}) {
    std::uint64_t run = 0;
    std::uint64_t ended = 0;
    for (std::size_t s = first; s < frames.phases.size() && ended == 0; ++s) {
      run = frames.fastest(s, dt) <= task.rest_speed ? run + 1 : 0;
      if (run >= rest_steps && s - first + 1 >= static_cast<std::uint64_t>(minimum))
        ended = s - first + 1;
    }
    EXPECT_EQ(length, ended);
    first += length + (first == 1 ? frames.stepsIn(EvalPhase::trial) : 0);
  }

  // the check off: settle phases of exactly settle_time and resettle_time
  CreatureSettings off_task = settings;
  off_task.set("task.rest_check", "false");
  Outcome off = evaluateGraph(pendulum(), off_task);
  ASSERT_EQ(off.status, EvalStatus::ok) << off.message;
  EXPECT_EQ(on.steps - off.steps, settle + resettle - std::llround(task.settle_time / dt) -
                                      std::llround(task.resettle_time / dt));
}

// task.distance_of = root (Chaumont et al.): the distance is the horizontal travel of the root
// part's centre over the measured phase, as the frames show it
TEST(Evaluate, DistanceOfTheRootIsTheRootsTravel) {
  Genome walker = creature("walker4.genome");
  PhaseRecorder frames;
  Outcome root = evaluateGraph(walker, shortWalk({{"task.distance_of", "root"}}), &frames);
  ASSERT_EQ(root.status, EvalStatus::ok) << root.message;
  const auto first = std::find(frames.phases.begin(), frames.phases.end(), EvalPhase::measure);
  ASSERT_NE(first, frames.phases.end());
  const Vec3 start =
      frames.positions[static_cast<std::size_t>(first - frames.phases.begin()) - 1][0];
  const Vec3 moved = frames.positions.back()[0] - start;
  EXPECT_NEAR(root.measure("distance"), std::hypot(moved.x, moved.y), 1e-12);
  Outcome centre = evaluateGraph(walker, shortWalk());
  EXPECT_NE(root.measure("distance"), centre.measure("distance"));
  EXPECT_EQ(root.steps, centre.steps);
}

}  // namespace
}  // namespace cambrian
