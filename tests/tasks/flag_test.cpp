// Tests of the flag task: Krčah's f(d) + g(t) by hand, a still body with the flag under it and
// far from it, and a walker heading for a flag ahead of it and one behind it.
#include "cambrian/encodings.hpp"
#include "cambrian/evaluate.hpp"

#include "tasks/juries.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cambrian {
namespace {

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

// f(d) = α (D − d) for d <= D, else 0; g(t) = β (N − t), 0 when not reached (t = N)
TEST(Flag, FitnessByHand) {
  EXPECT_DOUBLE_EQ(flagFitness(2, 5, 10, 10, 1, 1), 3);           // 3 m nearer, not reached
  EXPECT_DOUBLE_EQ(flagFitness(0.4, 5, 6, 10, 2, 0.5), 9.2 + 2);  // reached after 6 of 10 s
  EXPECT_DOUBLE_EQ(flagFitness(7, 5, 10, 10, 1, 1), 0);           // farther than at the start
  EXPECT_DOUBLE_EQ(flagFitness(5, 5, 10, 10, 1, 1), 0);
}

Outcome flag(const std::string& genome, std::vector<std::pair<std::string, std::string>> changes) {
  CreatureSettings settings;
  settings.set("task.name", "flag");
  settings.set("task.evaluation_time", "4");
  for (const auto& [key, value] : changes)
    settings.set(key, value);
  settings.check();
  return evaluate(readGenomeFile(kCreatures + genome), settings, 0);
}

// a block that does not move: a flag within reach is reached at once (t = 0: the whole β N), one
// 3 m away never (t = N, d = D: fitness 0)
TEST(Flag, AStillBodyReachesOnlyAFlagUnderIt) {
  const Outcome near = flag("single_block.genome", {{"task.flag_x", "0.2"}, {"task.flag_y", "0"}});
  ASSERT_EQ(near.status, EvalStatus::ok) << near.message;
  EXPECT_EQ(near.measure("flag_reached"), 1);
  EXPECT_EQ(near.measure("flag_time"), 0);
  EXPECT_NEAR(near.fitness, 4 + (0.2 - near.measure("flag_distance")), 1e-9);
  const Outcome far = flag("single_block.genome", {{"task.flag_x", "3"}, {"task.flag_y", "0"}});
  ASSERT_EQ(far.status, EvalStatus::ok) << far.message;
  EXPECT_EQ(far.measure("flag_reached"), 0);
  EXPECT_DOUBLE_EQ(far.measure("flag_time"), 4);
  EXPECT_DOUBLE_EQ(far.measure("flag_start_distance"), 3);
  EXPECT_NEAR(far.measure("flag_distance"), 3, 1e-3);
  EXPECT_NEAR(far.fitness, 0, 1e-3);
}

// the centre of mass where measuring began and where it ended
class MeasuredPath : public FrameObserver {
 public:
  std::uint64_t frameStride() const override { return 1; }
  void begin(const BodyPlan&, double, const Environment&) override {}
  void frame(const EvalFrame& frame) override {
    if (frame.phase != EvalPhase::measure) {
      start = frame.center_of_mass;  // the last frame before measuring
      return;
    }
    end = frame.center_of_mass;
  }
  Vec3 start, end;
};

// walker4 walks one way whatever the flag: towards a flag on its path it gains distance, and
// with a wide radius reaches it and stops early; away from one behind it, it scores 0
TEST(Flag, AWalkerGainsOnAFlagAheadAndStopsWhenItReachesIt) {
  // which way walker4 goes: its walk's displacement
  CreatureSettings walk;
  walk.set("task.name", "walk");
  walk.set("task.evaluation_time", "4");
  walk.check();
  MeasuredPath path;
  const Outcome walked = evaluate(readGenomeFile(kCreatures + "walker4.genome"), walk, 0, &path);
  ASSERT_EQ(walked.status, EvalStatus::ok) << walked.message;
  ASSERT_GT(walked.measure("distance"), 0.3);
  const double dx = path.end.x - path.start.x, dy = path.end.y - path.start.y;
  EXPECT_NEAR(std::hypot(dx, dy), walked.measure("distance"), 1e-9);
  const double along = 5 / std::hypot(dx, dy);
  const std::string ahead_x = std::to_string(dx * along), ahead_y = std::to_string(dy * along);
  const Outcome ahead =
      flag("walker4.genome", {{"task.flag_x", ahead_x}, {"task.flag_y", ahead_y}});
  ASSERT_EQ(ahead.status, EvalStatus::ok) << ahead.message;
  EXPECT_EQ(ahead.measure("flag_reached"), 0);
  EXPECT_GT(ahead.fitness, 0.3);
  EXPECT_NEAR(ahead.measure("flag_start_distance"), 5, 1e-5);  // the flag's text has 6 decimals
  EXPECT_NEAR(ahead.fitness, ahead.measure("flag_start_distance") - ahead.measure("flag_distance"),
              1e-12);
  // the same flag with a radius it crosses within the 4 s: reached, the run ends early
  const std::string radius = std::to_string(5 - 0.5 * walked.measure("distance"));
  const Outcome reached =
      flag("walker4.genome",
           {{"task.flag_x", ahead_x}, {"task.flag_y", ahead_y}, {"task.flag_radius", radius}});
  ASSERT_EQ(reached.status, EvalStatus::ok) << reached.message;
  EXPECT_EQ(reached.measure("flag_reached"), 1);
  EXPECT_LT(reached.measure("flag_time"), 4);
  EXPECT_LT(reached.steps, ahead.steps);
  EXPECT_NEAR(reached.fitness,
              reached.measure("flag_start_distance") - reached.measure("flag_distance") +
                  (4 - reached.measure("flag_time")),
              1e-9);
  // behind it: farther than at the start
  const Outcome behind = flag("walker4.genome", {{"task.flag_x", std::to_string(-dx * along)},
                                                 {"task.flag_y", std::to_string(-dy * along)}});
  ASSERT_EQ(behind.status, EvalStatus::ok) << behind.message;
  EXPECT_GT(behind.measure("flag_distance"), 5);
  EXPECT_EQ(behind.fitness, 0);
}

}  // namespace
}  // namespace cambrian
