// Tests of the combination task (Walking with Dinosaurs' Combi): walker4's distance and hop height
// measured in one run — the distance walk's, the height the lowest box corner's, computed here
// from the poses — and the fitness the weighted sum of the two for several weights.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace cambrian {
namespace {

using Changes = std::vector<std::pair<std::string, std::string>>;

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// settings for a 3 s combination with `changes`, checked
CreatureSettings settingsWith(const Changes& changes) {
  CreatureSettings settings;
  settings.set("task.name", "combination");
  settings.set("task.evaluation_time", "3");
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return settings;
}

// the highest lowest box corner while measured (from the last frame before measuring on), from
// the poses and the box sizes
class LowestPoint : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan& plan, double, const Environment&) override { plan_ = &plan; }
  void frame(const EvalFrame& frame) override {
    double lowest = INFINITY;
    for (std::size_t i = 0; i < frame.poses.size(); ++i) {
      const Vec3 half = plan_->parts[i].size * 0.5;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local{(corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y,
                         (corner & 4) ? half.z : -half.z};
        lowest = std::min(lowest, apply(frame.poses[i], local).z);
      }
    }
    if (frame.phase != EvalPhase::measure) {
      highest = lowest;  // where measuring begins
      return;
    }
    highest = std::max(highest, lowest);
  }
  double highest = -INFINITY;

 private:
  const BodyPlan* plan_ = nullptr;
};

// walker4 bounds forward: both measures are clearly positive, the distance is walk's distance of
// the same protocol, the height the lowest corner's highest rise, and the fitness their sum
TEST(Combination, MeasuresWalkersDistanceAndHopInOneRun) {
  const Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  LowestPoint frames;
  const Outcome both = evaluate(walker, settingsWith({}), 0, &frames);
  ASSERT_EQ(both.status, EvalStatus::ok) << both.message;
  const double distance = both.measure("distance"), height = both.measure("height");
  EXPECT_GT(distance, 0.3);
  EXPECT_GT(height, 0.01);
  EXPECT_NEAR(height, frames.highest, 1e-9);
  EXPECT_DOUBLE_EQ(both.fitness, distance + height);

  const Outcome walked = evaluate(walker, settingsWith({{"task.name", "walk"}}), 0);
  ASSERT_EQ(walked.status, EvalStatus::ok) << walked.message;
  EXPECT_EQ(distance, walked.measure("distance"));
}

// the weights scale each measure; the measures do not depend on them
TEST(Combination, FitnessIsTheWeightedSum) {
  const Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  const Outcome plain = evaluate(walker, settingsWith({}), 0);
  ASSERT_EQ(plain.status, EvalStatus::ok) << plain.message;
  const double distance = plain.measure("distance"), height = plain.measure("height");
  for (const auto& [move, jump] :
       std::vector<std::pair<double, double>>{{2, 0.5}, {0, 3}, {1, 0}}) {
    const Outcome weighted =
        evaluate(walker,
                 settingsWith({{"task.combination_move_weight", std::to_string(move)},
                               {"task.combination_jump_weight", std::to_string(jump)}}),
                 0);
    ASSERT_EQ(weighted.status, EvalStatus::ok) << weighted.message;
    EXPECT_EQ(weighted.measure("distance"), distance);
    EXPECT_EQ(weighted.measure("height"), height);
    EXPECT_DOUBLE_EQ(weighted.fitness, move * distance + jump * height) << move << " " << jump;
  }
}

// the weights must be >= 0; both default to 1
TEST(Combination, WeightsAreChecked) {
  CreatureSettings settings;
  EXPECT_EQ(std::stod(settings.value("task.combination_move_weight")), 1);
  EXPECT_EQ(std::stod(settings.value("task.combination_jump_weight")), 1);
  settings.set("task.combination_move_weight", "-1");
  EXPECT_THROW(settings.check(), ConfigError);
  settings.set("task.combination_move_weight", "1");
  settings.set("task.combination_jump_weight", "-0.5");
  EXPECT_THROW(settings.check(), ConfigError);
}

}  // namespace
}  // namespace cambrian
