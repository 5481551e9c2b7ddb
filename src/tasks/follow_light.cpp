// cambrian: the follow_light task — Sims' (1994) following: in several trials, each from birth,
// the light the photosensors see is put in places around the creature, the trials' first
// bearings turned evenly round, and the fitness is the average speed at which the centre of
// mass moves towards it. The turned trials take away what a fixed path would gain.
#include "tasks/follow_light.hpp"

#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

Vec3 lightPosition(int k, Vec3 centre, double distance, double first_degrees, double turn_degrees) {
  const double bearing = (first_degrees + k * turn_degrees) * kPi / 180;
  return centre + Vec3{std::cos(bearing), std::sin(bearing), 0} * distance;
}

/// Measures approach and approach_speed; the fitness is the approach speed, or 0 for a creature
/// that moved away (selection needs fitness >= 0; a failed creature also scores 0).
class FollowLightTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<FollowLightTask>(*this); }
  std::string name() const override { return "follow_light"; }
  std::string summary() const override {
    return "average speed towards a light moved around the creature (Sims 1994)";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"approach", "m"}, {"approach_speed", "m/s"}};
  }
  void run(Episode& episode) const override;

  int light_trials = 4;       ///< trials from birth, first bearings 360 / trials degrees apart
  int light_positions = 2;    ///< places the light takes in a trial, equal shares of its time
  double light_distance = 5;  ///< m from the centre of mass when the light is placed
  double light_bearing = 0;   ///< degrees from +x of the first position
  double light_turn = 90;     ///< degrees between successive bearings
};

void FollowLightTask::declareSettings(SettingsSchema& s) {
  s.add("task.light_trials", light_trials,
        "follow_light: trials, each from birth and measured for task.evaluation_time, their first "
        "light bearings 360 / trials degrees apart (Sims: 'several trials')")
      .require([this] { return light_trials >= 1 && light_trials <= 64; }, "must be in 1..64");
  s.add("task.light_positions", light_positions,
        "follow_light: places the light takes in a trial, each for an equal share of "
        "task.evaluation_time")
      .require([this] { return light_positions >= 1 && light_positions <= 1000; },
               "must be in 1..1000");
  s.add("task.light_distance", light_distance,
        "follow_light: m from the centre of mass at which the light is placed")
      .require([this] { return light_distance > 0 && std::isfinite(light_distance); },
               "must be > 0 and finite");
  s.add("task.light_bearing", light_bearing,
        "follow_light: degrees from +x (anticlockwise from above) of the first light position")
      .require([this] { return std::isfinite(light_bearing); }, "must be finite");
  s.add("task.light_turn", light_turn,
        "follow_light: degrees between the bearings of successive light positions (from +x)")
      .require([this] { return std::isfinite(light_turn); }, "must be finite");
}

void FollowLightTask::run(Episode& episode) const {
  // each trial: from birth, settle, then the light in each place in turn, the approach measured
  const EpisodeSettings& s = episode.settings();
  const double share = s.evaluation_time / light_positions;
  const double step = episode.simulation().timeStep();
  double approach = 0, seconds = 0;
  for (int trial = 0; trial < light_trials; ++trial) {
    if (trial > 0)
      episode.restart();
    if (!episode.settle(s.settle_time, EvalPhase::settle))
      return;
    const double first = light_bearing + trial * 360.0 / light_trials;
    for (int k = 0; k < light_positions; ++k) {
      episode.moveLight(
          lightPosition(k, episode.simulation().centerOfMass(), light_distance, first, light_turn));
      ApproachJury jury;
      if (!episode.run(share, EvalPhase::measure, {&jury}))
        return;
      approach += jury.value(episode.simulation());
      seconds += static_cast<double>(std::llround(share / step)) * step;
    }
  }
  const double speed = seconds > 0 ? approach / seconds : 0;
  Outcome& outcome = episode.outcome();
  outcome.measures.push_back({"approach", approach});
  outcome.measures.push_back({"approach_speed", speed});
  outcome.fitness = std::max(0.0, speed);
}

/// The follow_light task's prototype (for the registry).
const Task& followLightTask() {
  static const FollowLightTask task;
  return task;
}

}  // namespace cambrian
