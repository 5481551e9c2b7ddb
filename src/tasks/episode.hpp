// cambrian: one evaluation of one body, run phase by phase — the protocol every task with bodies
// shares: settle (controller off, optionally until at rest, Chaumont et al. 3.3), trial (on,
// unmeasured), measure (on, juries watching); a wall-clock bound; an optional observer.
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/outcome.hpp"

#include "physics/simulation.hpp"
#include "tasks/juries.hpp"

#include <chrono>
#include <initializer_list>
#include <memory>
#include <vector>

namespace cambrian {

class SettingsSchema;

/// The evaluation protocol's settings, shared by the tasks with bodies ([task] keys).
struct EpisodeSettings {
  double evaluation_time = 10;  ///< s, the measured phase
  double settle_time = 0.5;     ///< s, controller off before the trial (Chaumont)
  double trial_time = 1.0;      ///< s, controller on, not measured (Chaumont)
  double resettle_time = 0.5;   ///< s, controller off again before measuring
  /// Chaumont et al. 3.3's rest rule: each settle phase (controller off) lasts until every part
  /// has moved slower than `rest_speed` for `rest_time` in a row (and at least its settle_time or
  /// resettle_time); a creature not at rest within `settle_max_time` ends `unstable`. On by
  /// default: a body still falling from its birth pose must not be measured as moving. Off: the
  /// settle phases last exactly settle_time and resettle_time.
  bool rest_check = true;
  /// m/s, fastest part centre of mass at rest: Chaumont's "below the simulator's inaccuracy"
  /// for Bullet (his ODE figure, 1/300 m per 1/60 s = 0.2 m/s, lets a limb still turning from
  /// the fall be measured as motion: docs/physics-and-tasks.md, "The rest check")
  double rest_speed = 0.01;
  double rest_time = 0.5;        ///< s of consecutive steps at rest
  double settle_max_time = 5.0;  ///< s, the longest a settle phase may last with rest_check
  /// Fewer parts and a creature is not evaluated (invalid_body): Minemonics discards creatures
  /// of 0 or 1 limb ("degenerate and can not move at all").
  int min_parts = 1;
  /// Physics substeps of a second evaluation of every creature that passes the first; its
  /// fitness is then the lower of the two, and a creature that fails the second fails. A gait
  /// that rides one discretisation (a hop that skims a monitor, a path that hangs on one
  /// contact's timing) scores only what it keeps at the other. 0: one evaluation.
  int check_substeps = 0;
  /// Walking with Dinosaurs' relaxation before the start-up: the creature, controller off, on a
  /// frictionless ground until its centre of mass has stayed within relax_tolerance of one height
  /// for relax_steps steps in a row; not relaxed within relax_max_time: unstable. Then the ground
  /// has its friction again.
  bool relaxation = false;
  int relax_steps = 500;          ///< steps the centre of mass must keep its height
  double relax_tolerance = 1e-4;  ///< m, the most it may move up or down meanwhile
  double relax_max_time = 10;     ///< s
  /// m, the tallest a creature may be once relaxed (or at birth without relaxation): taller is
  /// `too_tall` (Walking with Dinosaurs: 15); 0: no limit
  double max_height = 0;

  /// Declares the keys, bound to this object, with their ranges.
  void declareSettings(SettingsSchema& schema);
};

/// A born creature's evaluation. Phases return false when the evaluation ends (a rule broke, the
/// wall-clock bound passed, or the body never came to rest); the outcome then says why.
class Episode {
 public:
  using Clock = std::chrono::steady_clock;

  /// Builds the world for `creature` in `environment` (both must outlive the episode: it keeps
  /// references); the evaluation started at `start` (for physics.max_wall_seconds). `observer`
  /// (may be null) sees the birth and every stride-th step.
  Episode(const Creature& creature, const Environment& environment, const PhysicsSettings& physics,
          const EpisodeSettings& settings, Clock::time_point start, FrameObserver* observer);

  /// Whether the creature was born (status ok after building the world).
  bool born() const { return simulation_->status() == EvalStatus::ok; }
  /// Starts again from birth in a fresh world (another trial of the same creature, Sims'
  /// "several trials"); the steps taken so far still count in the outcome and the frames.
  void restart();
  /// A settle phase of `seconds` (controller off); with the rest check, until at rest.
  bool settle(double seconds, EvalPhase phase);
  /// `seconds` with the controller on; each jury begins first and observes every step.
  bool run(double seconds, EvalPhase phase, std::initializer_list<Jury*> juries = {});
  /// Walking with Dinosaurs' legality before anything else: the relaxation (task.relaxation),
  /// then the height test (task.max_height); true at once when both are off.
  bool relax();
  /// Chaumont et al.'s start-up before measuring, after relax(): settle (task.settle_time,
  /// controller off), a trial (task.trial_time, on), settle again (task.resettle_time); false
  /// once a phase ends the evaluation.
  bool startUp();

  /// Moves the light the photosensors point at (a task that makes the creature follow it).
  void moveLight(Vec3 position) { simulation_->moveLight(position); }
  /// The simulation (for juries and task measures).
  const Simulation& simulation() const { return *simulation_; }
  /// The body.
  const BodyPlan& plan() const { return creature_.body; }
  /// The protocol settings.
  const EpisodeSettings& settings() const { return settings_; }
  /// The outcome being made: tasks add measures and the fitness.
  Outcome& outcome() { return outcome_; }
  /// The outcome with the steps taken and, when a rule broke or time ran out, that status, its
  /// message and the worst fitness.
  Outcome finish();

 private:
  enum class PhaseEnd { done, stopped, unstable };
  PhaseEnd runSteps(std::uint64_t steps, bool controller_on, EvalPhase phase,
                    std::initializer_list<Jury*> juries, bool rest);
  // after a step: the observer's frame; false once the wall-clock bound has passed
  bool watched(EvalPhase phase);
  // ends the evaluation with `status` and `message`, the worst fitness
  void refuse(EvalStatus status, std::string message);
  void show(EvalPhase phase);
  bool pastDeadline() const;

  std::uint64_t totalSteps() const { return steps_before_ + simulation_->steps(); }

  const Creature& creature_;
  const Environment& environment_;
  PhysicsSettings physics_;
  EpisodeSettings settings_;
  std::unique_ptr<Simulation> simulation_;
  std::uint64_t steps_before_ = 0;  // steps of the trials before restart()
  Outcome outcome_;
  bool bounded_ = false;
  Clock::time_point deadline_;
  FrameObserver* observer_ = nullptr;
  std::uint64_t stride_ = 1;
  std::vector<Transform> poses_;       // the observer's and the rest check's pose buffer
  std::vector<Transform> held_poses_;  // the observer's held objects
  std::vector<std::uint8_t> held_released_;
};

}  // namespace cambrian
