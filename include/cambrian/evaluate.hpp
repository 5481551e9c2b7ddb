// cambrian: evaluating one creature — a pure function of (genome, creature settings, seed). The
// creature settings choose and configure the plug-ins: the encoding (genome.encoding), the task
// (task.name), the world (physics.world) and the environment (environment.name).
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/encoding.hpp"
#include "cambrian/environment.hpp"
#include "cambrian/outcome.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace cambrian {

struct PhysicsSettings;
struct EpisodeSettings;
class SettingsSchema;
class Task;

/// Everything that decides how one creature is made and evaluated: every registered encoding,
/// task and environment kind with its settings, the physics, and which of each is chosen. Copies
/// are deep. Settings are set by key, as in an experiment file ("task.evaluation_time", "3").
class CreatureSettings {
 public:
  /// Every setting at its default: the directed-graph encoding, the walk task, the Featherstone
  /// world on a plane.
  CreatureSettings();
  CreatureSettings(const CreatureSettings& other);
  CreatureSettings& operator=(const CreatureSettings& other);
  ~CreatureSettings();

  /// Sets one setting from text (ConfigError for an unknown key or a bad value).
  void set(const std::string& key, const std::string& value);
  /// The value of one setting as text (ConfigError for an unknown key).
  std::string value(const std::string& key) const;
  /// Checks every setting's range; throws ConfigError "key = value: rule" for the first broken.
  void check() const;
  /// The [environment], [genome], [physics] and [task] settings as INI text.
  std::string iniText() const;
  /// Declares the same settings, bound to this object, in another schema (a command's).
  void declareSettings(SettingsSchema& schema);

  /// The chosen encoding (genome.encoding), configured.
  const Encoding& encoding() const;
  /// The chosen task (task.name), configured.
  const Task& task() const;
  /// The physics ([physics]).
  const PhysicsSettings& physics() const;
  PhysicsSettings& physics();
  /// The evaluation protocol the tasks share (settle, trial, measure times; rest rule).
  const EpisodeSettings& episode() const;
  /// The environment built by the chosen kind (environment.name), before the task adds to it.
  Environment environment() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Whether a genome makes a body that may be born: it validates, develops into at least one
/// part and does not overlap itself (Chaumont et al. 5.5: new individuals are tested for
/// self-collision and redrawn until valid). Cheap: no stepping. `reason` gets the failed rule.
bool isViable(const Genotype& genome, const CreatureSettings& settings,
              std::string* reason = nullptr);

/// The seed handed to the evaluation of individual `id` of a run: a pure function of both.
std::uint64_t evaluationSeed(std::uint64_t run_seed, std::uint64_t id);

/// The phases of an evaluation, in the order tasks run them (each task says which it runs).
enum class EvalPhase : std::uint8_t {
  settle,    ///< controller off, the body comes to rest
  trial,     ///< controller on, not measured
  resettle,  ///< controller off again
  measure,   ///< controller on, the juries watch
};

/// Lower-case phase name ("settle", "trial", "resettle", "measure"); "unknown" otherwise.
constexpr const char* phaseName(EvalPhase phase) {
  switch (phase) {
    case EvalPhase::settle:
      return "settle";
    case EvalPhase::trial:
      return "trial";
    case EvalPhase::resettle:
      return "resettle";
    case EvalPhase::measure:
      return "measure";
  }
  return "unknown";
}

/// What a FrameObserver sees of one frame. `poses` is only valid during the call.
struct EvalFrame {
  std::uint64_t step = 0;               ///< physics steps taken before this frame (0: at birth)
  double time = 0;                      ///< simulated time, s (step * time step)
  EvalPhase phase = EvalPhase::settle;  ///< phase of the step that led here (settle at birth)
  Vec3 center_of_mass;                  ///< mass-weighted centre of the parts, world frame, m
  std::span<const Transform> poses;     ///< world pose of every part, BodyPlan order
  /// World pose of every held object (BodyPlan::held order: a catapult's projectile), held or
  /// let go; empty for most creatures.
  std::span<const Transform> held_poses;
  std::span<const std::uint8_t> held_released;  ///< per held object: 1 once it has been let go
  Vec3 light;  ///< where the light the photosensors point at is now, world, m
};

/// Watches an evaluation, e.g. to record a trajectory for rendering. It only reads: an
/// evaluation gives bit-identical outcomes with and without an observer.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  /// Steps between two frames, >= 1 (1: every step); read once, before the world is built.
  virtual std::uint64_t frameStride() const = 0;
  /// Called once the world is built, before the first frame; never for a creature that does not
  /// reach the physics (invalid genome, no parts, a task without bodies). `plan` outlives the
  /// frames; `time_step` is the physics step, s; `environment` what surrounds the body.
  virtual void begin(const BodyPlan& plan, double time_step, const Environment& environment) = 0;
  /// Called at birth (step 0) and after every frameStride()-th step while every rule holds.
  virtual void frame(const EvalFrame& frame) = 0;
};

/// Evaluates one creature in a fresh world. Never throws for a bad creature: a rule-breaking
/// creature gets a status and kWorstFitness. `eval_seed` feeds any randomness inside.
/// `observer`, when not null, is shown the world every frameStride() steps; it does not change
/// the outcome, and without one the evaluation does no extra work.
Outcome evaluate(const Genotype& genome, const CreatureSettings& settings,
                 std::uint64_t eval_seed = 0, FrameObserver* observer = nullptr);

}  // namespace cambrian
