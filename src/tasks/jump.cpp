// cambrian: the jump task — relax (when on), settle, then the highest the creature's lowest point
// rises while measured (Walking with Dinosaurs' jump).
#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

namespace cambrian {

/// Measures height; the fitness is the height.
class JumpTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<JumpTask>(*this); }
  std::string name() const override { return "jump"; }
  std::string summary() const override { return "height of the lowest point while measured"; }
  std::vector<MeasureInfo> measures() const override { return {{"height", "m"}}; }

  void run(Episode& episode) const override {
    const EpisodeSettings& s = episode.settings();
    if (!episode.relax() || !episode.settle(s.settle_time, EvalPhase::settle))
      return;
    HeightJury height;
    if (!episode.run(s.evaluation_time, EvalPhase::measure, {&height}))
      return;
    double value = height.value(episode.simulation());
    episode.outcome().measures.push_back({"height", value});
    episode.outcome().fitness = value;
  }
};

/// The jump task's prototype (for the registry).
const Task& jumpTask() {
  static const JumpTask task;
  return task;
}

}  // namespace cambrian
