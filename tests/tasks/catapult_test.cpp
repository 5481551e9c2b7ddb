// Tests of the catapult task: Chaumont et al.'s F_D and F_a by hand; a block let go beside a
// slab drops without travelling, at the mechanism's time — step 30 when the network is silent or
// pulls the other way, at once when it signals; too fast a projectile has exploded; a body with
// nothing to throw is refused.
#include "tasks/catapult.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/evaluate.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace cambrian {
namespace {

// F_a = alpha_p D_p - alpha_t D_t; the aim fitness adds alpha_t times the target's range
TEST(Catapult, FitnessByHand) {
  EXPECT_DOUBLE_EQ(catapultAim(10, 3, 1, 1), 7);
  EXPECT_DOUBLE_EQ(catapultAim(10, 3, 0.5, 2), -1);
  EXPECT_DOUBLE_EQ(catapultFitness(CatapultFitness::distance, 10, 3, 5, 1, 1), 10);
  EXPECT_DOUBLE_EQ(catapultFitness(CatapultFitness::aim, 10, 3, 5, 1, 1), 12);
  EXPECT_DOUBLE_EQ(catapultFitness(CatapultFitness::aim, 0, 5, 5, 1, 1), 0);
  EXPECT_DOUBLE_EQ(catapultFitness(CatapultFitness::aim, 0, 7, 5, 1, 1), 0);  // never below 0
}

// a 1 x 1 x 0.2 m slab lying on the ground holds a 0.1 m block at the middle of its +x face; the
// release wire is the constant `trigger`
Outcome dropBeside(double trigger, const char* fitness = "distance", const char* max_speed = "50") {
  const std::string text =
      "cambrian-genome 2\nnode 0 size 1 1 0.2 density 1000 joint rigid limit 1 1 1 recursion 1\n"
      "projectile size 0.1 0.1 0.1 density 1000 position 1 0 0 trigger constant 0 0 " +
      std::to_string(trigger) + "\nend\n";
  CreatureSettings settings;
  for (auto [key, value] : std::initializer_list<std::pair<const char*, const char*>>{
           {"task.name", "catapult"},
           {"task.catapult_fitness", fitness},
           {"task.evaluation_time", "5"},
           {"task.target_distance", "3"},
           {"task.target_bearing", "90"},
           {"genome.catapult", "true"},
           {"physics.time_step", "0.016666666666666667"},
           {"physics.substeps", "4"},
           {"physics.max_speed", max_speed}})
    settings.set(key, value);
  settings.check();
  return evaluate(graph::makeGenotype(graph::parseGenomeText(text)), settings, 0);
}

// let go with no throw: it drops beside the slab; the target (3 m along +y, on the ground) is as
// far from its path as from the release point, and F_a = 0 - that
TEST(Catapult, ADroppedBlockTravelsNothing) {
  const Outcome outcome = dropBeside(0);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  EXPECT_LT(outcome.measure("distance"), 0.01);
  EXPECT_NEAR(outcome.measure("miss"), std::hypot(0.55, 3.0), 0.01);
  EXPECT_NEAR(outcome.measure("aim"), -outcome.measure("miss") + outcome.measure("distance"),
              1e-12);
  EXPECT_DOUBLE_EQ(outcome.fitness, outcome.measure("distance"));
  // the task ends once the block is at rest, long before the 5 s are over
  EXPECT_LT(outcome.steps, 300u);
  const Outcome aimed = dropBeside(0, "aim");
  EXPECT_DOUBLE_EQ(aimed.fitness, std::max(0.0, 3 + aimed.measure("aim")));
}

// the mechanism: step 30 (0.5 s at 1/60 s) when the network says nothing or pulls the other way,
// within two steps when it signals
TEST(Catapult, TheMechanismLetsGoByStep30) {
  EXPECT_DOUBLE_EQ(dropBeside(0).measure("release_time"), 30.0 / 60);
  EXPECT_DOUBLE_EQ(dropBeside(-1).measure("release_time"), 30.0 / 60);
  EXPECT_LE(dropBeside(1).measure("release_time"), 2.0 / 60);
}

// the projectile is watched like a part: faster than physics.max_speed has exploded
TEST(Catapult, AProjectileTooFastHasExploded) {
  const Outcome outcome = dropBeside(0, "distance", "0.5");
  EXPECT_EQ(outcome.status, EvalStatus::exploded) << outcome.message;
  EXPECT_NE(outcome.message.find("held object 0 moved at"), std::string::npos) << outcome.message;
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

// a body that holds nothing cannot be a catapult
TEST(Catapult, NothingToThrowIsRefused) {
  CreatureSettings settings;
  settings.set("task.name", "catapult");
  settings.check();
  const std::string text = "cambrian-genome 2\nnode 0 size 0.5 0.5 0.5\nend\n";
  const Outcome outcome = evaluate(graph::makeGenotype(graph::parseGenomeText(text)), settings, 0);
  EXPECT_EQ(outcome.status, EvalStatus::invalid_body);
  EXPECT_NE(outcome.message.find("genome.catapult"), std::string::npos);
  EXPECT_EQ(outcome.fitness, kWorstFitness);
}

}  // namespace
}  // namespace cambrian
