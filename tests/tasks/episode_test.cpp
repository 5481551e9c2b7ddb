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

}  // namespace
}  // namespace cambrian
