// cambrian: the swim task — Sims' (1994) swimming speed: the straight-line distance the centre of
// mass travels per unit time, the final phase of the measured time weighted more, so that
// continuing motion beats one initial push. Meant for environment.name = water.
#include "tasks/swim.hpp"

#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cambrian {

double swimFitness(double distance, double seconds, double final_distance, double final_seconds,
                   double final_weight) {
  if (!(seconds > 0) || !(final_seconds > 0))
    return 0;
  return (distance / seconds + final_weight * final_distance / final_seconds) / (1 + final_weight);
}

/// Measures distance, final_distance and speed; the fitness is swimFitness.
class SwimTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<SwimTask>(*this); }
  std::string name() const override { return "swim"; }
  std::string summary() const override {
    return "swimming speed (Sims 1994): straight-line speed of the centre of mass, the final "
           "phase weighted more";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"distance", "m"}, {"final_distance", "m"}, {"speed", "m/s"}};
  }
  void run(Episode& episode) const override;

  double final_share = 0.25;  ///< the final phase, a share of task.evaluation_time
  double final_weight = 1;    ///< the final phase's speed, relative to the whole phase's
};

void SwimTask::declareSettings(SettingsSchema& s) {
  s.add("task.final_share", final_share,
        "swim: the final phase, as a share of task.evaluation_time, whose speed counts again")
      .require([this] { return final_share > 0 && final_share <= 1; }, "must be in (0, 1]");
  s.add("task.final_weight", final_weight,
        "swim: weight of the final phase's speed beside the whole phase's (Sims: 'a stronger "
        "relative weight')")
      .require([this] { return final_weight >= 0 && std::isfinite(final_weight); },
               "must be >= 0 and finite");
}

void SwimTask::run(Episode& episode) const {
  // settle (a neutrally buoyant body born at rest stays at rest), then measure
  const EpisodeSettings& s = episode.settings();
  if (!episode.settle(s.settle_time, EvalPhase::settle))
    return;
  const double step = episode.simulation().timeStep();
  const auto steps = static_cast<std::uint64_t>(std::llround(s.evaluation_time / step));
  const auto final_steps =
      std::min(steps, std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(
                                                     final_share * static_cast<double>(steps)))));
  DisplacementJury distance("distance"), final_distance("final_distance", steps - final_steps);
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&distance, &final_distance}))
    return;

  const Simulation& simulation = episode.simulation();
  const double d = distance.value(simulation), d_final = final_distance.value(simulation);
  const double seconds = static_cast<double>(steps) * step;
  Outcome& outcome = episode.outcome();
  outcome.measures.push_back({"distance", d});
  outcome.measures.push_back({"final_distance", d_final});
  outcome.measures.push_back({"speed", seconds > 0 ? d / seconds : 0});
  outcome.fitness =
      swimFitness(d, seconds, d_final, static_cast<double>(final_steps) * step, final_weight);
}

/// The swim task's prototype (for the registry).
const Task& swimTask() {
  static const SwimTask task;
  return task;
}

}  // namespace cambrian
