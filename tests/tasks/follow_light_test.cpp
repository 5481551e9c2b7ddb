// Tests of the follow_light task: where the light goes, the measures of a passive body and of a
// walker that does not look at the light (towards it, away from it), and the clamp at zero.
#include "tasks/follow_light.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/evaluate.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian {
namespace {

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

TEST(FollowLight, LightPositionsByHand) {
  const Vec3 centre{1, 2, 3};
  const Vec3 first = lightPosition(0, centre, 5, 0, 90);
  EXPECT_EQ(first, (Vec3{6, 2, 3}));
  const Vec3 second = lightPosition(1, centre, 5, 0, 90);
  EXPECT_NEAR(second.x, 1, 1e-12);
  EXPECT_NEAR(second.y, 7, 1e-12);
  EXPECT_EQ(second.z, 3);
  const Vec3 behind = lightPosition(0, centre, 2, 180, 90);
  EXPECT_NEAR(behind.x, -1, 1e-12);
  EXPECT_NEAR(behind.y, 2, 1e-12);
}

Outcome follow(const std::string& genome,
               std::vector<std::pair<std::string, std::string>> changes) {
  CreatureSettings settings;
  settings.set("task.name", "follow_light");
  settings.set("task.evaluation_time", "4");
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return evaluate(readGenomeFile(kCreatures + genome), settings, 0);
}

// a block in water without gravity never moves: no approach in any of the four positions
TEST(FollowLight, APassiveBodyApproachesNothing) {
  Outcome outcome = follow("single_block.genome", {{"environment.name", "water"}});
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  EXPECT_EQ(outcome.measure("approach"), 0);
  EXPECT_EQ(outcome.measure("approach_speed"), 0);
  EXPECT_EQ(outcome.fitness, 0);
}

// the walker does not see the light, so it walks the same way wherever the light is: with the
// light ahead of it it scores its approach speed, with the light behind it moves away (a negative
// approach) and scores 0
TEST(FollowLight, TowardsScoresAndAwayScoresZero) {
  Outcome ahead = follow(
      "walker4.genome",
      {{"task.light_trials", "1"}, {"task.light_positions", "1"}, {"task.light_bearing", "0"}});
  Outcome behind = follow(
      "walker4.genome",
      {{"task.light_trials", "1"}, {"task.light_positions", "1"}, {"task.light_bearing", "180"}});
  ASSERT_EQ(ahead.status, EvalStatus::ok) << ahead.message;
  ASSERT_EQ(behind.status, EvalStatus::ok) << behind.message;
  EXPECT_GT(ahead.measure("approach"), 0.1);
  EXPECT_LT(behind.measure("approach"), -0.1);
  EXPECT_DOUBLE_EQ(ahead.fitness, ahead.measure("approach") / 4);
  EXPECT_DOUBLE_EQ(ahead.measure("approach_speed"), ahead.measure("approach") / 4);
  EXPECT_EQ(behind.fitness, 0);
}

// the trials start from birth with their first bearings turned evenly round, so a walker that
// does not look at the light, and would score its full speed with the light always ahead, scores
// little over four trials; each trial takes its own settle and measured steps
TEST(FollowLight, TurnedTrialsTakeAwayWhatAFixedPathGains) {
  Outcome ahead =
      follow("walker4.genome", {{"task.light_trials", "1"}, {"task.light_positions", "1"}});
  Outcome one = follow("walker4.genome", {{"task.light_trials", "1"}});
  Outcome four = follow("walker4.genome", {});
  ASSERT_EQ(four.status, EvalStatus::ok) << four.message;
  EXPECT_GT(ahead.measure("approach_speed"), 0.05);
  EXPECT_LT(std::abs(four.measure("approach_speed")), 0.3 * ahead.measure("approach_speed"));
  EXPECT_EQ(four.steps, 4 * one.steps);
}

}  // namespace
}  // namespace cambrian
