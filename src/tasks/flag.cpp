// cambrian: the flag task — reach a flag: Krčah 2008's "reaching a flag", fitness f(d) + g(t).
#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <cmath>
#include <cstdint>

namespace cambrian {

/// After the start-up phases, measured for at most task.evaluation_time (N): the centre of mass
/// heads for a flag at (flag_x, flag_y) from where it was, and the run stops once it is within
/// flag_radius. Fitness α · (D − d) for a final distance d at most the flag's first distance D,
/// plus β · (N − t) when reached at t.
class FlagTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<FlagTask>(*this); }
  std::string name() const override { return "flag"; }
  std::string summary() const override {
    return "get near a flag, sooner is better (Krcah 2008's reaching a flag)";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"flag_distance", "m"},
            {"flag_start_distance", "m"},
            {"flag_time", "s"},
            {"flag_reached", "1"}};
  }
  void run(Episode& episode) const override;

  double flag_x = 0, flag_y = 5;  ///< m from the centre of mass when measuring begins
  double flag_radius = 0.5;       ///< m: reached within it
  double flag_alpha = 1;          ///< per m of distance gained
  double flag_beta = 1;           ///< per s left when reached
};

void FlagTask::declareSettings(SettingsSchema& s) {
  s.add("task.flag_x", flag_x,
        "flag: the flag's x, m from the centre of mass when measuring begins (Krcah: X)")
      .require([this] { return std::isfinite(flag_x); }, "must be finite");
  s.add("task.flag_y", flag_y,
        "flag: the flag's y, m from the centre of mass when measuring begins (Krcah: Y)")
      .require([this] { return std::isfinite(flag_y); }, "must be finite");
  s.add("task.flag_radius", flag_radius,
        "flag: reached once the centre of mass is this near, m (Krcah: R)")
      .require([this] { return flag_radius >= 0 && std::isfinite(flag_radius); },
               "must be >= 0 and finite");
  s.add("task.flag_alpha", flag_alpha, "flag: fitness per m the flag came nearer (Krcah: alpha)")
      .require([this] { return flag_alpha >= 0 && std::isfinite(flag_alpha); },
               "must be >= 0 and finite");
  s.add("task.flag_beta", flag_beta,
        "flag: fitness per s of task.evaluation_time left when the flag is reached (Krcah: beta)")
      .require([this] { return flag_beta >= 0 && std::isfinite(flag_beta); },
               "must be >= 0 and finite");
}

void FlagTask::run(Episode& episode) const {
  // the start-up phases, then at most N s towards the flag
  const EpisodeSettings& s = episode.settings();
  if (!episode.startUp())
    return;
  FlagJury flag(Vec3{flag_x, flag_y, 0}, flag_radius);
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&flag}))
    return;

  // t: the measured time until reached, N when not reached
  const double step = episode.simulation().timeStep();
  const double limit = static_cast<double>(std::llround(s.evaluation_time / step)) * step;
  const double seconds = flag.reached() ? static_cast<double>(flag.steps()) * step : limit;
  const double distance = flag.value(episode.simulation());
  const double start_distance = std::hypot(flag_x, flag_y);
  Outcome& outcome = episode.outcome();
  outcome.measures.push_back({"flag_distance", distance});
  outcome.measures.push_back({"flag_start_distance", start_distance});
  outcome.measures.push_back({"flag_time", seconds});
  outcome.measures.push_back({"flag_reached", flag.reached() ? 1.0 : 0.0});
  outcome.fitness = flagFitness(distance, start_distance, seconds, limit, flag_alpha, flag_beta);
}

/// The flag task's prototype (for the registry).
const Task& flagTask() {
  static const FlagTask task;
  return task;
}

}  // namespace cambrian
