// Tests of the iterative move task (Walking with Dinosaurs): the iterative distance by hand —
// steady, early and late gains, a way back — the jury against a walker's recorded path, and the
// conditions (dwarf slaying, box loving, fat loving) on a hand-built falling tower and on walker4.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "physics/box_part.hpp"
#include "physics/physics_settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace cambrian {
namespace {

using Changes = std::vector<std::pair<std::string, std::string>>;

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// the iterative distance of distances d_1..d_n at times 1/n, 2/n, ..., 1 (T = 1)
double iterative(const std::vector<double>& distances) {
  IterativeDistance sum;
  const auto n = static_cast<double>(distances.size());
  for (std::size_t i = 0; i < distances.size(); ++i)
    sum.add(distances[i], static_cast<double>(i + 1) / n);
  return sum.value();
}

// Σ (d_i − d_{i−1}) t_i / T by hand, four steps of 0.25 s to 1 m
TEST(IterativeMove, IterativeDistanceByHand) {
  // steady: 0.25 m per step, weights 1/4, 2/4, 3/4, 4/4
  EXPECT_DOUBLE_EQ(iterative({0.25, 0.5, 0.75, 1}), 0.25 * (0.25 + 0.5 + 0.75 + 1));
  // all of it in the first step, then still: only the first weight
  EXPECT_DOUBLE_EQ(iterative({1, 1, 1, 1}), 0.25);
  // all of it in the last step: the whole metre
  EXPECT_DOUBLE_EQ(iterative({0, 0, 0, 1}), 1);
  // out at once and back at the end: the loss weighs more than the gain
  EXPECT_DOUBLE_EQ(iterative({1, 1, 1, 0}), 0.25 - 1);
  // nothing measured yet
  EXPECT_EQ(IterativeDistance().value(), 0);
}

// T is the last time fed: the same path over twice the time, the second half still, scores half
TEST(IterativeMove, IterativeDistanceDividesByTheLastTime) {
  IterativeDistance half, whole;
  for (int i = 1; i <= 4; ++i) {
    half.add(0.5 * i, 0.5 * i);
    whole.add(0.5 * i, 0.5 * i);
  }
  for (int i = 5; i <= 8; ++i)
    whole.add(2, 0.5 * i);
  EXPECT_DOUBLE_EQ(half.value(), 0.5 * (0.5 + 1 + 1.5 + 2) / 2);
  EXPECT_DOUBLE_EQ(whole.value(), half.value() / 2);
}

// Walking with Dinosaurs' cases over many steps: a steady mover to D scores about D / 2 (D / 2 + D
// / 2n exactly), one that gets there in the first step about 0 (D / n), in the last step D
TEST(IterativeMove, SteadyEarlyAndLateMovers) {
  const int n = 1000;
  const double d = 2;
  std::vector<double> steady, early(n, d), late(n, 0);
  for (int i = 1; i <= n; ++i)
    steady.push_back(d * i / n);
  late.back() = d;
  EXPECT_NEAR(iterative(steady), d / 2 + d / (2 * n), 1e-12);
  EXPECT_NEAR(iterative(early), d / n, 1e-12);
  EXPECT_NEAR(iterative(late), d, 1e-12);
}

// settings for the iterative move task with `changes`, checked
CreatureSettings settingsWith(const Changes& changes) {
  CreatureSettings settings;
  settings.set("task.name", "iterative_move");
  settings.set("task.evaluation_time", "3");
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return settings;
}

// the centre of mass of every frame of the measured phase, and the last one before it
class MeasuredPath : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan&, double time_step, const Environment&) override { step = time_step; }
  void frame(const EvalFrame& frame) override {
    if (frame.phase != EvalPhase::measure) {
      start = frame.center_of_mass;
      path.clear();
      return;
    }
    path.push_back(frame.center_of_mass);
  }
  // the horizontal distance of frame `i` from the start
  double distance(std::size_t i) const {
    return std::hypot(path[i].x - start.x, path[i].y - start.y);
  }
  double step = 0;
  Vec3 start;
  std::vector<Vec3> path;
};

// walker4's measure is the sum over its recorded path, step by step; its distance is walk's, and
// a steady walker's iterative distance is about half its distance
TEST(IterativeMove, AWalkersIterativeDistanceIsItsPathsWeightedGains) {
  const Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  MeasuredPath frames;
  const Outcome outcome = evaluate(walker, settingsWith({}), 0, &frames);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  ASSERT_EQ(frames.path.size(), static_cast<std::size_t>(std::llround(3 / frames.step)));

  // Σ (d_i − d_{i−1}) t_i / T over the frames, computed here
  double weighted = 0, last = 0;
  for (std::size_t i = 0; i < frames.path.size(); ++i) {
    weighted += (frames.distance(i) - last) * static_cast<double>(i + 1) * frames.step;
    last = frames.distance(i);
  }
  const double expected = weighted / (static_cast<double>(frames.path.size()) * frames.step);
  const double measured = outcome.measure("iterative_distance");
  EXPECT_NEAR(measured, expected, 1e-9);
  EXPECT_NEAR(outcome.measure("distance"), last, 1e-12);
  EXPECT_EQ(outcome.fitness, std::max(0.0, measured));

  // the same run's distance as walk's, and about half of it for a walker
  CreatureSettings walk = settingsWith({{"task.name", "walk"}});
  const Outcome walked = evaluate(walker, walk, 0);
  EXPECT_EQ(outcome.measure("distance"), walked.measure("distance"));
  ASSERT_GT(last, 0.3);
  EXPECT_GT(measured, 0.3 * last);
  EXPECT_LT(measured, 0.7 * last);
}

// the conditions multiply walker4's fitness by its 5 parts and by its mass, by hand: a
// 0.6 x 0.3 x 0.15 m body of density 300 (8.1 kg) and four 0.3 x 0.1 x 0.1 m legs of 1000 (3 kg)
TEST(IterativeMove, BoxAndFatLovingScaleAWalkersFitness) {
  const Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  const Outcome plain = evaluate(walker, settingsWith({}), 0);
  ASSERT_EQ(plain.status, EvalStatus::ok) << plain.message;
  ASSERT_GT(plain.fitness, 0.1);
  EXPECT_EQ(plain.parts, 5);
  EXPECT_NEAR(plain.measure("mass"), 8.1 + 4 * 3, 1e-9);

  const Outcome boxes = evaluate(walker, settingsWith({{"task.wwd_condition", "box_loving"}}), 0);
  ASSERT_EQ(boxes.status, EvalStatus::ok) << boxes.message;
  EXPECT_EQ(boxes.measure("iterative_distance"), plain.measure("iterative_distance"));
  EXPECT_DOUBLE_EQ(boxes.fitness, 5 * plain.fitness);

  const Outcome fat = evaluate(walker, settingsWith({{"task.wwd_condition", "fat_loving"}}), 0);
  ASSERT_EQ(fat.status, EvalStatus::ok) << fat.message;
  EXPECT_EQ(fat.measure("iterative_distance"), plain.measure("iterative_distance"));
  EXPECT_NEAR(fat.fitness, 20.1 * plain.fitness, 1e-9 * fat.fitness);
}

// dwarf slaying through evaluate: walker4's 5 parts pass task.dwarf_min_parts = 5, not 6
TEST(IterativeMove, DwarfSlayingThroughEvaluate) {
  const Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  const Outcome plain = evaluate(walker, settingsWith({}), 0);
  const Outcome five = evaluate(
      walker,
      settingsWith({{"task.wwd_condition", "dwarf_slaying"}, {"task.dwarf_min_parts", "5"}}), 0);
  ASSERT_EQ(five.status, EvalStatus::ok) << five.message;
  EXPECT_EQ(five.fitness, plain.fitness);
  const Outcome six = evaluate(
      walker,
      settingsWith({{"task.wwd_condition", "dwarf_slaying"}, {"task.dwarf_min_parts", "6"}}), 0);
  EXPECT_EQ(six.status, EvalStatus::invalid_body);
  EXPECT_EQ(six.fitness, kWorstFitness);
  EXPECT_EQ(six.steps, 0u);
  EXPECT_EQ(six.message, "dwarf slaying: 5 parts, fewer than task.dwarf_min_parts = 6");
  EXPECT_EQ(six.parts, 5);
}

// a tall 0.1 x 0.1 x 0.8 m block (8 kg) leaning 0.3 rad towards +x, with `cubes` 0.1 m cubes
// (1 kg each) fixed on top of each other along it: it falls over at once
Creature tower(int cubes) {
  Creature creature;
  const Quat lean = quatFromEuler({0, 0.3, 0});
  PartPlan root = test::box({0.1, 0.1, 0.8}, {0, 0, 0});
  root.pose.rotation = lean;
  creature.body.parts.push_back(root);
  for (int c = 0; c < cubes; ++c) {
    const double below = c == 0 ? 0.4 : 0.05;  // half the height of the part below
    PartPlan cube = test::box({0.1, 0.1, 0.1}, {}, c);
    cube.joint = JointType::fixed;
    cube.connection = c;
    cube.pivot_in_parent = {0, 0, below};
    cube.pivot_in_child = {0, 0, -0.05};
    cube.pose.rotation = lean;
    cube.pose.position = rotate(lean, {0, 0, 0.4 + 0.1 * c + 0.05});
    creature.body.parts.push_back(cube);
  }
  return creature;
}

// the task on a hand-built creature, as evaluate runs it: measured from birth (no start-up
// phases), for 2 s
Outcome runTask(const Creature& creature, const Changes& changes) {
  Changes all = {{"task.evaluation_time", "2"},
                 {"task.rest_check", "false"},
                 {"task.settle_time", "0"},
                 {"task.trial_time", "0"},
                 {"task.resettle_time", "0"}};
  all.insert(all.end(), changes.begin(), changes.end());
  const CreatureSettings settings = settingsWith(all);
  Environment environment = settings.environment();
  settings.task().prepare(environment);
  Episode episode(creature, environment, settings.physics(), settings.episode(),
                  std::chrono::steady_clock::now(), nullptr);
  EXPECT_TRUE(episode.born()) << episode.finish().message;
  if (episode.born())
    settings.task().run(episode);
  return episode.finish();
}

// the tower's fall comes early: it gains most of its distance in the first part of the 2 s, so
// its iterative distance is well under half its distance
TEST(IterativeMove, AnEarlyFallScoresLittle) {
  const Outcome fall = runTask(tower(2), {});
  ASSERT_EQ(fall.status, EvalStatus::ok) << fall.message;
  EXPECT_GT(fall.measure("distance"), 0.2);
  EXPECT_GT(fall.measure("iterative_distance"), 0);
  EXPECT_LT(fall.measure("iterative_distance"), 0.5 * fall.measure("distance"));
  EXPECT_EQ(fall.fitness, fall.measure("iterative_distance"));
}

// dwarf slaying refuses 2 parts (invalid_body, the worst fitness, never simulated) and takes 3,
// scored as iterative move
TEST(IterativeMove, DwarfSlayingKillsFewerThanThreeParts) {
  const Changes dwarf = {{"task.wwd_condition", "dwarf_slaying"}};
  const Outcome two = runTask(tower(1), dwarf);
  EXPECT_EQ(two.status, EvalStatus::invalid_body);
  EXPECT_EQ(two.fitness, kWorstFitness);
  EXPECT_EQ(two.steps, 0u);
  EXPECT_NE(two.message.find("dwarf slaying"), std::string::npos) << two.message;
  EXPECT_NE(two.message.find("2 parts"), std::string::npos) << two.message;
  EXPECT_NE(two.message.find("task.dwarf_min_parts = 3"), std::string::npos) << two.message;
  EXPECT_TRUE(std::isnan(two.measure("iterative_distance")));
  EXPECT_EQ(two.parts, 2);
  EXPECT_DOUBLE_EQ(two.measure("mass"), 9);
  // the same body without the condition is evaluated
  const Outcome free = runTask(tower(1), {});
  EXPECT_EQ(free.status, EvalStatus::ok) << free.message;
  EXPECT_GT(free.fitness, 0);

  const Outcome three = runTask(tower(2), dwarf);
  ASSERT_EQ(three.status, EvalStatus::ok) << three.message;
  const Outcome plain = runTask(tower(2), {});
  EXPECT_GT(plain.fitness, 0);
  EXPECT_EQ(three.fitness, plain.fitness);
  // a higher bar refuses the 3-part tower too
  const Outcome four =
      runTask(tower(2), {{"task.wwd_condition", "dwarf_slaying"}, {"task.dwarf_min_parts", "4"}});
  EXPECT_EQ(four.status, EvalStatus::invalid_body);
  EXPECT_EQ(four.fitness, kWorstFitness);
}

// box loving multiplies by the part count, fat loving by the mass: 8 kg + 2 x 1 kg
TEST(IterativeMove, BoxAndFatLovingOnAHandBuiltTower) {
  const Outcome plain = runTask(tower(2), {});
  ASSERT_EQ(plain.status, EvalStatus::ok) << plain.message;
  ASSERT_GT(plain.fitness, 0);
  EXPECT_EQ(plain.parts, 3);
  EXPECT_DOUBLE_EQ(plain.measure("mass"), 10);
  const Outcome boxes = runTask(tower(2), {{"task.wwd_condition", "box_loving"}});
  ASSERT_EQ(boxes.status, EvalStatus::ok) << boxes.message;
  EXPECT_DOUBLE_EQ(boxes.fitness, 3 * plain.fitness);
  const Outcome fat = runTask(tower(2), {{"task.wwd_condition", "fat_loving"}});
  ASSERT_EQ(fat.status, EvalStatus::ok) << fat.message;
  EXPECT_DOUBLE_EQ(fat.fitness, 10 * plain.fitness);
}

// the settings' ranges and choices
TEST(IterativeMove, SettingsAreChecked) {
  CreatureSettings settings;
  EXPECT_EQ(settings.value("task.wwd_condition"), "none");
  EXPECT_EQ(settings.value("task.dwarf_min_parts"), "3");
  EXPECT_THROW(settings.set("task.wwd_condition", "giant_loving"), ConfigError);
  settings.set("task.dwarf_min_parts", "0");
  EXPECT_THROW(settings.check(), ConfigError);
}

}  // namespace
}  // namespace cambrian
