// Tests of the swim task: Sims' fitness by hand, a travelling-wave snake that swims in water and
// cannot move its centre of mass in a vacuum, a passive body that scores nothing.
#include "tasks/swim.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/evaluate.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// 10 m in 10 s and 4 m in the last 2.5 s: (1 + 1.6) / 2 m/s with equal weights
TEST(Swim, FitnessByHand) {
  EXPECT_DOUBLE_EQ(swimFitness(10, 10, 4, 2.5, 1), 1.3);
  EXPECT_DOUBLE_EQ(swimFitness(10, 10, 4, 2.5, 0), 1.0);
  EXPECT_DOUBLE_EQ(swimFitness(10, 10, 4, 2.5, 3), (1 + 3 * 1.6) / 4);
  EXPECT_EQ(swimFitness(10, 0, 4, 2.5, 1), 0);
}

// the snake of jobs/creatures in the swim task, in water with `viscosity`, with `changes`
Outcome swimmingSnake(const char* viscosity, const char* final_weight = "1",
                      std::initializer_list<std::pair<const char*, const char*>> changes = {}) {
  CreatureSettings settings;
  for (auto [key, value] : std::initializer_list<std::pair<const char*, const char*>>{
           {"task.name", "swim"},
           {"environment.name", "water"},
           {"environment.viscosity", viscosity},
           {"task.evaluation_time", "4"},
           {"task.final_weight", final_weight},
           {"genome.max_recursive_limit", "6"}})
    settings.set(key, value);
  for (auto [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return evaluate(readGenomeFile(kCreatures + "snake.genome"), settings, 0);
}

// a travelling wave swims in Sims' water; the measures add up to the fitness
TEST(Swim, ASnakeSwims) {
  Outcome outcome = swimmingSnake("100");
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  const double d = outcome.measure("distance"), d_final = outcome.measure("final_distance");
  EXPECT_GT(d, 0.2);
  EXPECT_GT(d_final, 0.05);
  EXPECT_DOUBLE_EQ(outcome.measure("speed"), d / 4);
  EXPECT_NEAR(outcome.fitness, swimFitness(d, 4, d_final, 1, 1), 1e-12);
  EXPECT_DOUBLE_EQ(swimmingSnake("100", "0").fitness, d / 4);
}

// without water nothing pushes back: the same wave leaves the centre of mass where it was
// (momentum is conserved, and there is no gravity and no ground); Bullet's integrator alone lets
// it drift 0.36 m (physics.momentum_correction = false)
TEST(Swim, NoSwimmingInAVacuum) {
  Outcome outcome = swimmingSnake("0");
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  EXPECT_LT(outcome.measure("distance"), 1e-9);
  Outcome drifting = swimmingSnake("0", "1", {{"physics.momentum_correction", "false"}});
  ASSERT_EQ(drifting.status, EvalStatus::ok) << drifting.message;
  EXPECT_GT(drifting.measure("distance"), 0.2);
}

// the swim converges with the step: at the default 1/240 s within 2 % of 1/4000 s (measured
// 1.0 %; without the momentum correction 3.9 %)
TEST(Swim, ConvergesWithTheStep) {
  const double coarse = swimmingSnake("100").measure("distance");
  const double fine =
      swimmingSnake("100", "1", {{"physics.time_step", "0.00025"}}).measure("distance");
  EXPECT_NEAR(coarse, fine, 0.02 * fine);
}

}  // namespace
}  // namespace cambrian
