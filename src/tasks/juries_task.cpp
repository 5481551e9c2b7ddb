// cambrian: the juries task — Minemonics' way of rating a creature: settle, then every jury
// watches the measured phase (average and integral average velocity, horizontal distance,
// maximum and average height, ground contacts, time on ground). Its fitness is one jury's value
// (task.fitness_jury); evolution.ranking combines several into Minemonics' competitive ranking.
#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/minemonics_juries.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

/// Every Minemonics jury; the fitness is the one task.fitness_jury names.
class JuriesTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<JuriesTask>(*this); }
  std::string name() const override { return "juries"; }
  std::string summary() const override {
    return "Minemonics' juries: velocities, heights, ground contacts (fitness: task.fitness_jury)";
  }
  std::vector<MeasureInfo> measures() const override {
    return {{"average_velocity", "1/s"},   {"integral_average_velocity", "1/s"},
            {"horizontal_distance", "m"},  {"maximum_height", "m"},
            {"average_height", "1"},       {"ground_contact_quantity", "1"},
            {"ground_contact_ratio", "1"}, {"time_on_ground", "s"}};
  }

  void declareSettings(SettingsSchema& s) override {
    std::vector<std::string> names;
    for (const MeasureInfo& measure : measures())
      names.push_back(measure.name);
    s.add("task.fitness_jury", fitness_jury_,
          "juries: the jury whose value is an evaluation's fitness (evolution.ranking may rank "
          "several instead)")
        .oneOf(names);
  }

  void run(Episode& episode) const override {
    const EpisodeSettings& s = episode.settings();
    if (!episode.settle(s.settle_time, EvalPhase::settle))
      return;
    AverageVelocityJury average_velocity;
    IntegralAverageVelocityJury integral_average_velocity;
    DistanceJury horizontal_distance(TrackedPoint::centre_of_mass, "horizontal_distance");
    MaximumHeightJury maximum_height;
    AverageHeightJury average_height;
    GroundContactJury contact_quantity(false), contact_ratio(true);
    TimeOnGroundJury time_on_ground;
    const std::initializer_list<Jury*> juries = {
        &average_velocity, &integral_average_velocity, &horizontal_distance, &maximum_height,
        &average_height,   &contact_quantity,          &contact_ratio,       &time_on_ground};
    if (!episode.run(s.evaluation_time, EvalPhase::measure, juries))
      return;
    Outcome& outcome = episode.outcome();
    for (const Jury* jury : juries) {
      outcome.measures.push_back({jury->name(), jury->value(episode.simulation())});
      if (fitness_jury_ == jury->name())
        outcome.fitness = std::max(0.0, outcome.measures.back().value);
    }
  }

 private:
  std::string fitness_jury_ = "average_velocity";
};

/// The juries task's prototype (for the registry).
const Task& juriesTask() {
  static const JuriesTask task;
  return task;
}

}  // namespace cambrian
