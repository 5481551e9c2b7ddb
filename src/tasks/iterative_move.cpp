// cambrian: the iterative move task — Walking with Dinosaurs' "Iterative move" and the
// conditioned tests built on it (dwarf slaying, box loving, fat loving).
//
// Walking with Dinosaurs (3.3.3, Walking): iterative move "also takes the time into
// consideration, since distance gained late in the process is more often caused by continuous
// movement, than distance gained early". Its formula is not given; here, after the start-up
// phases (as walk), every measured step i at time t_i from the start of measuring (T the measured
// time) takes d_i, the horizontal distance of the centre of mass from where measuring began, and
// the fitness is Σ_i (d_i − d_{i−1}) · t_i / T (d_0 = 0): each gain of distance weighted by how
// late it came. A steady walker to distance D scores about D / 2, a creature that gets to D at
// once and stops about 0, one that gets there at the very end about D (Walking with Dinosaurs,
// 5.3.1: fallers "optimize their falls so they are timed well with the ending of the
// simulation"). The raw sum may be negative (the body came back); the fitness is floored at 0,
// the measure keeps the raw value.
//
// task.wwd_condition adds its conditioned tests: dwarf_slaying "kills creatures with fewer than
// 3 parts" (task.dwarf_min_parts: status invalid_body, the worst fitness), box_loving scales the
// fitness "with the amount of parts the creature consists of", fat_loving "by the creatures
// weight" (total mass, kg).
#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

namespace cambrian {

/// The conditioned tests of Walking with Dinosaurs, all built on iterative move.
enum class WwdCondition : std::uint8_t {
  none,           ///< iterative move alone
  dwarf_slaying,  ///< fewer than task.dwarf_min_parts parts: invalid_body
  box_loving,     ///< fitness x part count
  fat_loving,     ///< fitness x total mass, kg
};

/// Measures iterative_distance, distance and mass (the outcome carries the part count); the fitness
/// is the iterative distance (at least 0), conditioned.
class IterativeMoveTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override {
    return std::make_unique<IterativeMoveTask>(*this);
  }
  std::string name() const override { return "iterative_move"; }
  std::string summary() const override {
    return "distance gained while measured, later gains weigh more (Walking with Dinosaurs' "
           "iterative move)";
  }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override {
    return {{"iterative_distance", "m"}, {"distance", "m"}, {"mass", "kg"}};
  }
  void run(Episode& episode) const override;

  WwdCondition condition = WwdCondition::none;
  int dwarf_min_parts = 3;  ///< dwarf slaying: fewer parts and the creature is killed
};

void IterativeMoveTask::declareSettings(SettingsSchema& s) {
  s.addChoice("task.wwd_condition", condition,
              {{"none", WwdCondition::none},
               {"dwarf_slaying", WwdCondition::dwarf_slaying},
               {"box_loving", WwdCondition::box_loving},
               {"fat_loving", WwdCondition::fat_loving}},
              "iterative_move: Walking with Dinosaurs' conditioned tests: none | dwarf_slaying "
              "(\"kills creatures with fewer than 3 parts\": task.dwarf_min_parts) | box_loving "
              "(\"scaling the fitness value ... with the amount of parts\") | fat_loving (\"scales "
              "the fitness values ... by the creatures weight\", kg)");
  s.add("task.dwarf_min_parts", dwarf_min_parts,
        "iterative_move, dwarf_slaying: a creature of fewer parts is killed (status invalid_body, "
        "the worst fitness; Walking with Dinosaurs: 3)")
      .require([this] { return dwarf_min_parts >= 1 && dwarf_min_parts <= 1000; },
               "must be in 1..1000");
}

void IterativeMoveTask::run(Episode& episode) const {
  // what the conditions weigh, measured whatever the condition
  Outcome& outcome = episode.outcome();
  const BodyPlan& plan = episode.plan();
  const auto parts = static_cast<double>(plan.parts.size());
  const double mass = plan.totalMass();

  // dwarf slaying: too few parts, never simulated
  if (condition == WwdCondition::dwarf_slaying &&
      plan.parts.size() < static_cast<std::size_t>(dwarf_min_parts)) {
    const std::size_t n = plan.parts.size();
    outcome.status = EvalStatus::invalid_body;
    outcome.message = "dwarf slaying: " + std::to_string(n) + " part" + (n == 1 ? "" : "s") +
                      ", fewer than task.dwarf_min_parts = " + std::to_string(dwarf_min_parts);
    outcome.fitness = kWorstFitness;
    outcome.measures.push_back({"mass", mass});
    return;
  }

  // the start-up phases, then the iterative and the plain distance of the same measured run
  const EpisodeSettings& s = episode.settings();
  if (!episode.startUp())
    return;
  IterativeDistanceJury iterative;
  DistanceJury distance;
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&iterative, &distance}))
    return;
  const double raw = iterative.value(episode.simulation());
  outcome.measures.push_back({"iterative_distance", raw});
  outcome.measures.push_back({"distance", distance.value(episode.simulation())});
  outcome.measures.push_back({"mass", mass});

  // the fitness: at least 0, scaled by the condition
  const double fitness = std::max(kWorstFitness, raw);
  switch (condition) {
    case WwdCondition::none:
    case WwdCondition::dwarf_slaying:
      outcome.fitness = fitness;
      break;
    case WwdCondition::box_loving:
      outcome.fitness = fitness * parts;
      break;
    case WwdCondition::fat_loving:
      outcome.fitness = fitness * mass;
      break;
  }
}

/// The iterative move task's prototype (for the registry).
const Task& iterativeMoveTask() {
  static const IterativeMoveTask task;
  return task;
}

}  // namespace cambrian
