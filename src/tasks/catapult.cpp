// cambrian: the catapult task — Chaumont et al. (2007) 4.2: a creature whose root part, the arm,
// holds a projectile (genome.catapult) lets go of it; the projectile is followed from where it
// was let go until it comes to rest, horizontally, and the fitness is that distance (F_D = D_p)
// or, aiming at a target point, F_a = alpha_p D_p - alpha_t D_t with D_t the least distance of
// its centre's path from that point.
#include "tasks/catapult.hpp"

#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cambrian {

double catapultAim(double distance, double miss, double alpha_distance, double alpha_miss) {
  return alpha_distance * distance - alpha_miss * miss;
}

double catapultFitness(CatapultFitness kind, double distance, double miss, double target_range,
                       double alpha_distance, double alpha_miss) {
  if (kind == CatapultFitness::distance)
    return std::max(0.0, distance);
  return std::max(
      0.0, catapultAim(distance, miss, alpha_distance, alpha_miss) + alpha_miss * target_range);
}

/// Measures distance (D_p), miss (D_t), aim (F_a) and release_time; the fitness is
/// catapultFitness.
class CatapultTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<CatapultTask>(*this); }
  std::string name() const override { return "catapult"; }
  std::string summary() const override {
    return "how far a catapult throws its projectile, or how near a target (Chaumont et al. "
           "2007); needs genome.catapult = true";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"distance", "m"}, {"miss", "m"}, {"aim", "m"}, {"release_time", "s"}};
  }
  void run(Episode& episode) const override;

  CatapultFitness fitness = CatapultFitness::distance;
  double target_distance = 5;  ///< m from the birth place, horizontally
  double target_bearing = 0;   ///< degrees from +x, anticlockwise from above
  double target_height = 0;    ///< m above the ground
  double alpha_distance = 1;   ///< alpha_p (Chaumont et al.: 1)
  double alpha_miss = 1;       ///< alpha_t (Chaumont et al.: 1)
};

void CatapultTask::declareSettings(SettingsSchema& s) {
  s.addChoice("task.catapult_fitness", fitness,
              {{"distance", CatapultFitness::distance}, {"aim", CatapultFitness::aim}},
              "catapult: distance (F_D = D_p, how far the projectile went from where it was let "
              "go to where it came to rest) | aim (F_a = alpha_p D_p - alpha_t D_t, D_t the "
              "least distance of its path from the target point)");
  s.add("task.target_distance", target_distance,
        "catapult: the target's horizontal distance from the birth place, m")
      .require([this] { return target_distance >= 0 && std::isfinite(target_distance); },
               "must be >= 0 and finite");
  s.add("task.target_bearing", target_bearing,
        "catapult: the target's bearing, degrees from +x (anticlockwise from above)")
      .require([this] { return std::isfinite(target_bearing); }, "must be finite");
  s.add("task.target_height", target_height,
        "catapult: the target's height above the ground, m (0: a point on the ground)")
      .require([this] { return target_height >= 0 && std::isfinite(target_height); },
               "must be >= 0 and finite");
  s.add("task.alpha_distance", alpha_distance, "catapult aim: alpha_p, the weight of D_p")
      .require([this] { return alpha_distance >= 0 && std::isfinite(alpha_distance); },
               "must be >= 0 and finite");
  s.add("task.alpha_miss", alpha_miss, "catapult aim: alpha_t, the weight of D_t")
      .require([this] { return alpha_miss >= 0 && std::isfinite(alpha_miss); },
               "must be >= 0 and finite");
}

void CatapultTask::run(Episode& episode) const {
  Outcome& outcome = episode.outcome();
  if (episode.plan().held.empty()) {
    outcome.status = EvalStatus::invalid_body;
    outcome.message =
        "the catapult task needs a body that holds a projectile (genome.catapult "
        "= true)";
    outcome.fitness = kWorstFitness;
    return;
  }

  // settle holding the projectile, then the controller on until the projectile, let go, has
  // come to rest (or the measured time is over)
  const EpisodeSettings& s = episode.settings();
  if (!episode.settle(s.settle_time, EvalPhase::settle))
    return;
  const double step = episode.simulation().timeStep();
  const double bearing = target_bearing * kPi / 180;
  const Vec3 target =
      Vec3{std::cos(bearing), std::sin(bearing), 0} * target_distance + Vec3{0, 0, target_height};
  ThrowJury jury(
      target, s.rest_speed,
      std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(s.rest_time / step))));
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&jury}))
    return;

  const double distance = jury.released() ? jury.value(episode.simulation()) : 0.0;
  outcome.measures.push_back({"distance", distance});
  outcome.measures.push_back({"miss", jury.miss()});
  outcome.measures.push_back(
      {"aim", catapultAim(distance, jury.miss(), alpha_distance, alpha_miss)});
  outcome.measures.push_back(
      {"release_time", jury.released() ? static_cast<double>(jury.releaseStep()) * step : -1.0});
  outcome.fitness =
      catapultFitness(fitness, distance, jury.miss(), std::hypot(target_distance, target_height),
                      alpha_distance, alpha_miss);
}

/// The catapult task's prototype (for the registry).
const Task& catapultTask() {
  static const CatapultTask task;
  return task;
}

}  // namespace cambrian
