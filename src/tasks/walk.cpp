// cambrian: the walk task — settle, trial, settle again, then the distance the centre of mass
// travels while measured (Sims 1994; Chaumont et al. 2007's protocol and normalisation).
#include "core/settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/juries.hpp"
#include "tasks/task.hpp"

#include <cmath>
#include <cstdint>

namespace cambrian {

/// Walk fitness normalisations from the seeds.
enum class WalkNormalisation : std::uint8_t {
  none,      ///< raw distance, metres
  chaumont,  ///< D * C_v / (C_s * C_l) * k^N (Chaumont et al. eq. 1)
  volume,    ///< D / cbrt(total volume) (Minemonics)
};

/// Measures distance, body_length and body_lengths; the fitness is the distance, normalised.
class WalkTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<WalkTask>(*this); }
  std::string name() const override { return "walk"; }
  std::string summary() const override { return "distance walked while measured"; }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override;
  void run(Episode& episode) const override;

  WalkNormalisation normalisation = WalkNormalisation::none;
  TrackedPoint distance_of = TrackedPoint::centre_of_mass;  ///< the point whose travel counts
  double chaumont_k = 1.02;                                 ///< k in k^N
};

void WalkTask::declareSettings(SettingsSchema& s) {
  s.addChoice("task.normalisation", normalisation,
              {{"none", WalkNormalisation::none},
               {"chaumont", WalkNormalisation::chaumont},
               {"volume", WalkNormalisation::volume}},
              "walk fitness: none | chaumont | volume");
  s.addChoice("task.distance_of", distance_of,
              {{"centre_of_mass", TrackedPoint::centre_of_mass}, {"root", TrackedPoint::root}},
              "walk: the point whose horizontal travel is the distance: centre_of_mass (Sims) | "
              "root (Chaumont et al.: the root block's centre of mass)");
  s.add("task.chaumont_k", chaumont_k, "k of the k^N complexity bonus (chaumont normalisation)")
      .require([this] { return chaumont_k > 0 && std::isfinite(chaumont_k); },
               "must be > 0 and finite");
}

std::vector<MeasureInfo> WalkTask::measures() const {
  return {{"distance", "m"}, {"body_length", "m"}, {"body_lengths", "1"}};
}

void WalkTask::run(Episode& episode) const {
  // Chaumont's start-up: settle controller off, trial on, settle again; then measure
  const EpisodeSettings& s = episode.settings();
  if (!episode.startUp())
    return;
  DistanceJury distance(distance_of);
  if (!episode.run(s.evaluation_time, EvalPhase::measure, {&distance}))
    return;

  // the distance, also in body lengths, normalised into the fitness
  Outcome& outcome = episode.outcome();
  const BodyPlan& plan = episode.plan();
  double d = distance.value(episode.simulation());
  double length = bodyLength(plan);
  outcome.measures.push_back({"distance", d});
  outcome.measures.push_back({"body_length", length});
  outcome.measures.push_back({"body_lengths", length > 0 ? d / length : 0});
  switch (normalisation) {
    case WalkNormalisation::none:
      outcome.fitness = d;
      break;
    case WalkNormalisation::chaumont:
      outcome.fitness = d * chaumontFactor(plan, chaumont_k);
      break;
    case WalkNormalisation::volume:
      outcome.fitness = d * volumeFactor(plan);
      break;
  }
}

/// The walk task's prototype (for the registry).
const Task& walkTask() {
  static const WalkTask task;
  return task;
}

}  // namespace cambrian
