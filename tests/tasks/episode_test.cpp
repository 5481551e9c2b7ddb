// Tests of the Episode protocol with a task of the test's own: the task places an object in the
// environment before birth and reads it back from the world, runs its phases, and reports a
// measure; a creature that is not born runs no phase.
#include "tasks/episode.hpp"

#include "cambrian/error.hpp"

#include "physics/physics_settings.hpp"
#include "tasks/task.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace cambrian {
namespace {

// a task that drops a cube beside the creature and measures how far it fell while measured
class DropTheCube : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<DropTheCube>(*this); }
  std::string name() const override { return "drop_the_cube"; }
  std::string summary() const override { return "test"; }
  std::vector<MeasureInfo> measures() const override { return {{"fall", "m"}}; }
  void prepare(Environment& environment) const override {
    FreeObject cube;
    cube.name = "cube";
    cube.size = {0.1, 0.1, 0.1};
    cube.mass = 0.2;
    cube.pose.position = {1, 0, 1.0};
    environment.objects.push_back(cube);
  }
  void run(Episode& episode) const override {
    const World& world = episode.simulation().world();
    double start = world.objectPose(0).position.z;
    if (!episode.settle(0.1, EvalPhase::settle) || !episode.run(1.0, EvalPhase::measure))
      return;
    double fall = start - world.objectPose(0).position.z;
    episode.outcome().measures.push_back({"fall", fall});
    episode.outcome().fitness = fall;
  }
};

// a block as a creature, without a controller
Creature block() {
  Creature creature;
  PartPlan part;
  part.size = {0.2, 0.2, 0.2};
  part.mass = 8;
  creature.body.parts.push_back(part);
  return creature;
}

TEST(Episode, ATaskPlacesAnObjectAndReadsItBack) {
  DropTheCube task;
  Environment environment;
  task.prepare(environment);
  Creature creature = block();
  PhysicsSettings physics;
  EpisodeSettings settings;
  settings.rest_check = false;  // the phases last exactly their settle times
  Episode episode(creature, environment, physics, settings, std::chrono::steady_clock::now(),
                  nullptr);
  ASSERT_TRUE(episode.born());
  task.run(episode);
  Outcome outcome = episode.finish();
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  // from 1 m to resting on the ground (centre at 0.05 m)
  EXPECT_NEAR(outcome.measure("fall"), 0.95, 3e-3);
  EXPECT_EQ(outcome.steps, static_cast<std::uint64_t>(std::llround(1.1 / physics.time_step)));
  EXPECT_EQ(outcome.parts, 1);
}

TEST(Episode, AnUnbornCreatureEndsWithItsBirthStatus) {
  Creature creature = block();
  LoopJoint loop;
  creature.body.loops.push_back(loop);  // the Featherstone world builds no loops
  Environment environment;
  Episode episode(creature, environment, PhysicsSettings{}, EpisodeSettings{},
                  std::chrono::steady_clock::now(), nullptr);
  EXPECT_FALSE(episode.born());
  Outcome outcome = episode.finish();
  EXPECT_EQ(outcome.status, EvalStatus::invalid_body);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
  EXPECT_EQ(outcome.steps, 0u);
}

// a tall block and a child held out on a pitching hinge halfway up: the child droops at birth
Creature drooping() {
  Creature creature = block();
  creature.body.parts[0].size = {0.4, 0.2, 0.6};
  creature.body.parts[0].mass = 48;
  PartPlan child;
  child.parent = 0;
  child.connection = 0;
  child.depth = 1;
  child.size = {0.3, 0.1, 0.1};
  child.mass = 3;
  child.pose.position = {0.35, 0, 0.2};
  child.joint = JointType::revolute;
  child.axes = {Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}};
  child.pivot_in_parent = {0.2, 0, 0.2};
  child.pivot_in_child = {-0.15, 0, 0};
  child.joint_limit = {1.0, 1.0, 1.0};
  child.cross_section = 0.01;
  creature.body.parts.push_back(child);
  return creature;
}

// Walking with Dinosaurs' relaxation: the drooping child settles, on the frictionless ground,
// and the centre of mass keeps its height for task.relax_steps steps before anything else
TEST(Episode, RelaxationLastsUntilTheCentreOfMassKeepsItsHeight) {
  const Creature creature = drooping();
  PhysicsSettings physics;
  EpisodeSettings settings;
  settings.relaxation = true;
  settings.relax_steps = 120;
  const Environment environment;  // outlives the episodes, which keep a reference
  Episode episode(creature, environment, physics, settings, std::chrono::steady_clock::now(),
                  nullptr);
  ASSERT_TRUE(episode.born());
  const double born_at = episode.simulation().centerOfMass().z;
  ASSERT_TRUE(episode.relax());
  const Outcome outcome = episode.finish();
  EXPECT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  // it drooped (the centre of mass sank) and then kept still for the steps asked for
  EXPECT_LT(episode.simulation().centerOfMass().z, born_at - 0.005);
  EXPECT_GT(outcome.steps, 120u);
  EXPECT_LT(outcome.steps,
            static_cast<std::uint64_t>(std::llround(settings.relax_max_time / physics.time_step)));
  // off, relax() takes no step
  settings.relaxation = false;
  Episode unrelaxed(creature, environment, physics, settings, std::chrono::steady_clock::now(),
                    nullptr);
  ASSERT_TRUE(unrelaxed.relax());
  EXPECT_EQ(unrelaxed.finish().steps, 0u);
}

// a creature that cannot keep its height for task.relax_steps within task.relax_max_time is
// discarded: unstable, the worst fitness, a message naming the settings
TEST(Episode, ACreatureNotRelaxedInTimeIsUnstable) {
  const Creature creature = drooping();
  EpisodeSettings settings;
  settings.relaxation = true;
  settings.relax_steps = 500;
  settings.relax_max_time = 0.5;  // 120 steps
  const Environment environment;
  Episode episode(creature, environment, PhysicsSettings{}, settings,
                  std::chrono::steady_clock::now(), nullptr);
  EXPECT_FALSE(episode.relax());
  const Outcome outcome = episode.finish();
  EXPECT_EQ(outcome.status, EvalStatus::unstable);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
  EXPECT_NE(outcome.message.find("task.relax_max_time"), std::string::npos) << outcome.message;
}

// the height test: taller than task.max_height is too_tall, the worst fitness; 0 is no limit
TEST(Episode, ACreatureTallerThanTheHeightLimitIsTooTall) {
  Creature tower = block();
  tower.body.parts[0].size = {0.2, 0.2, 2.0};
  EpisodeSettings settings;
  const Environment environment;
  for (double limit : {1.5, 2.5, 0.0}) {
    settings.max_height = limit;
    Episode episode(tower, environment, PhysicsSettings{}, settings,
                    std::chrono::steady_clock::now(), nullptr);
    const bool legal = episode.relax();
    const Outcome outcome = episode.finish();
    if (limit == 1.5) {
      EXPECT_FALSE(legal);
      EXPECT_EQ(outcome.status, EvalStatus::too_tall);
      EXPECT_EQ(outcome.fitness, kWorstFitness);
      EXPECT_NE(outcome.message.find("2 m tall at birth"), std::string::npos) << outcome.message;
    } else {
      EXPECT_TRUE(legal) << limit;
      EXPECT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
    }
  }
}

}  // namespace
}  // namespace cambrian
