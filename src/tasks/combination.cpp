// cambrian: the combination task — Walking with Dinosaurs' "Combi": movement and jump measured
// in the same run ("using the jump test, together with a movement test, should logically result
// in a creature moving forward in small jumps"). After the start-up phases (as walk), the
// distance the centre of mass travels (walk's distance) and the highest the lowest point rises
// (jump's height) are measured together; the fitness is task.combination_move_weight x distance
// + task.combination_jump_weight x height. Walking with Dinosaurs gives no weights (it ran the
// plain movement test with the jump test); both default to 1.
#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <cmath>

namespace cambrian {

/// Measures distance and height; the fitness is their weighted sum.
class CombinationTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<CombinationTask>(*this); }
  std::string name() const override { return "combination"; }
  std::string summary() const override {
    return "distance and jump height at once (Walking with Dinosaurs' Combi)";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"distance", "m"}, {"height", "m"}};
  }
  void run(Episode& episode) const override;

  double move_weight = 1;  ///< fitness per m of distance
  double jump_weight = 1;  ///< fitness per m of height
};

void CombinationTask::declareSettings(SettingsSchema& s) {
  s.add("task.combination_move_weight", move_weight,
        "combination: fitness per m of distance travelled (Walking with Dinosaurs' Combi, \"the "
        "jump test, together with a movement test\", gives no weights)")
      .require([this] { return move_weight >= 0 && std::isfinite(move_weight); },
               "must be >= 0 and finite");
  s.add("task.combination_jump_weight", jump_weight,
        "combination: fitness per m of jump height (the lowest point's highest rise; Walking with "
        "Dinosaurs gives no weights)")
      .require([this] { return jump_weight >= 0 && std::isfinite(jump_weight); },
               "must be >= 0 and finite");
}

void CombinationTask::run(Episode& episode) const {
  // the start-up phases, then both juries watch the same measured run
  const EpisodeSettings& s = episode.settings();
  if (!episode.startUp())
    return;
  DistanceJury distance;
  HeightJury height;
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&distance, &height}))
    return;

  // the weighted sum of the two
  const double d = distance.value(episode.simulation());
  const double h = height.value(episode.simulation());
  Outcome& outcome = episode.outcome();
  outcome.measures.push_back({"distance", d});
  outcome.measures.push_back({"height", h});
  outcome.fitness = move_weight * d + jump_weight * h;
}

/// The combination task's prototype (for the registry).
const Task& combinationTask() {
  static const CombinationTask task;
  return task;
}

}  // namespace cambrian
