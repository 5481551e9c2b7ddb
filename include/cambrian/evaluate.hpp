// cambrian: evaluating one creature — a pure function of (genome, settings, seed).
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/genome.hpp"
#include "cambrian/outcome.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace cambrian {

/// How effector commands move the joints.
enum class Actuation : std::uint8_t {
  /// Chaumont et al. 5.3: a velocity motor run at saturation. The command's sign picks the
  /// direction of a fixed, high target speed and its magnitude the largest torque the motor may
  /// use (|command| * strength); the constraint solver applies it implicitly with the contacts.
  saturated_motor,
  /// Sims: the command times the strength is applied as an explicit joint torque.
  torque,
};

/// The physical world an evaluation runs in. Units: SI.
struct PhysicsSettings {
  double time_step = 1.0 / 240.0;  ///< s, fixed: sensors, brain and monitors run at this rate
  int substeps = 2;       ///< Bullet steps per time step; 1 lets thin, light, strongly driven parts
                          ///< gain energy from the integrator at 1/240 s
  double gravity = 9.81;  ///< m / s^2, pointing down (-z)
  double ground_friction = 1.0;  ///< Coulomb coefficient
  double restitution = 0.0;
  double joint_damping = 0.05;      ///< N m s / rad, passive damping on every joint
  double strength_per_area = 2000;  ///< N m of torque per m^2 of the smaller cross-section
  Actuation actuation = Actuation::saturated_motor;  ///< how commands move the joints
  double motor_speed = 10;                           ///< rad / s, target speed of a saturated motor
  /// Whether a creature's parts collide with each other while it moves (Sims) or only with the
  /// ground (Walking with Dinosaurs; Chaumont et al. test self-overlap at birth only). Overlap at
  /// birth is rejected either way. Off by default: a motor pressing one part into another lets
  /// Bullet's contact correction pump energy into the body.
  bool self_collision = false;
  int solver_iterations = 20;
  double max_speed = 50;          ///< m / s: any part faster has exploded
  double max_displacement = 100;  ///< m: any part farther from its start has exploded
  double penetration_tolerance =
      0.002;                     ///< m of overlap allowed between non-adjacent parts at birth
  double max_wall_seconds = 60;  ///< wall-clock bound of one evaluation (0 = none)
};

/// What is asked of the creature and how it is measured.
enum class TaskKind : std::uint8_t { walk, jump, synthetic };
/// Walk fitness normalisations from the seeds.
enum class WalkNormalisation : std::uint8_t {
  none,      ///< raw distance, metres
  chaumont,  ///< D * C_v / (C_s * C_l) * k^N (Chaumont et al. eq. 1)
  volume,    ///< D / cbrt(total volume) (Minemonics)
};

/// How the synthetic task's cost varies from creature to creature (task.synthetic_distribution).
enum class SyntheticDistribution : std::uint8_t {
  uniform,    ///< mean cost times 1 + synthetic_noise * (2u - 1)
  lognormal,  ///< lognormal with the mean cost as mean and synthetic_cv as coefficient of variation
  fixed,      ///< the mean cost, always
};

struct TaskSettings {
  TaskKind kind = TaskKind::walk;
  double evaluation_time = 10;  ///< s, the measured phase
  double settle_time = 0.5;     ///< s, brain off before the trial (Chaumont)
  double trial_time = 1.0;      ///< s, brain on, not measured (Chaumont)
  double resettle_time = 0.5;   ///< s, brain off again before measuring
  /// Chaumont et al. 3.3's rest rule: each settle phase (brain off) lasts until every part has
  /// moved slower than `rest_speed` for `rest_time` in a row (and at least its settle_time or
  /// resettle_time); a creature not at rest within `settle_max_time` ends `unstable`. Off: the
  /// settle phases last exactly settle_time and resettle_time.
  bool rest_check = false;
  double rest_speed = 0.2;       ///< m/s, fastest part centre of mass at rest (1/300 m per 1/60 s)
  double rest_time = 0.5;        ///< s of consecutive steps at rest
  double settle_max_time = 5.0;  ///< s, the longest a settle phase may last with rest_check
  WalkNormalisation normalisation = WalkNormalisation::none;
  double chaumont_k = 1.02;  ///< k in k^N
  Vec3 target{10, 0, 0};     ///< photosensor target, metres
  // synthetic task (framework overhead studies)
  double synthetic_cost_us = 10000;       ///< busy work per evaluation, microseconds
  double synthetic_cost_per_gene_us = 0;  ///< extra per genome node
  double synthetic_noise = 0;  ///< relative spread of the cost, deterministic per creature
  SyntheticDistribution synthetic_distribution = SyntheticDistribution::uniform;  ///< cost law
  double synthetic_cv = 0.5;  ///< lognormal: coefficient of variation of the cost
};

const char* taskName(TaskKind kind);

/// Whether a genome makes a body that may be born: it validates, develops into at least one
/// part and does not overlap itself (Chaumont et al. 5.5: new individuals are tested for
/// self-collision and redrawn until valid). Cheap: no stepping. `reason` gets the failed rule.
bool isViable(const Genome& genome, const GenomeLimits& limits, const PhysicsSettings& physics,
              std::string* reason = nullptr);

/// The phases of an evaluation, in the order they run (jump and synthetic skip trial and
/// resettle).
enum class EvalPhase : std::uint8_t {
  settle,    ///< brain off, the body comes to rest
  trial,     ///< brain on, not measured (walk)
  resettle,  ///< brain off again (walk)
  measure,   ///< brain on, the juries watch
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
};

/// Watches an evaluation, e.g. to record a trajectory for rendering. It only reads: an
/// evaluation gives bit-identical outcomes with and without an observer.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  /// Steps between two frames, >= 1 (1: every step); read once, before the world is built.
  virtual std::uint64_t frameStride() const = 0;
  /// Called once the world is built, before the first frame; never for a creature that does not
  /// reach the physics (invalid genome, no parts, synthetic task). `plan` outlives the frames.
  virtual void begin(const BodyPlan& plan, const PhysicsSettings& physics) = 0;
  /// Called at birth (step 0) and after every frameStride()-th step while every rule holds.
  virtual void frame(const EvalFrame& frame) = 0;
};

/// Evaluates one creature in a fresh world. Never throws for a bad creature: a rule-breaking
/// creature gets a status and kWorstFitness. `eval_seed` feeds any randomness inside.
/// `observer`, when not null, is shown the world every frameStride() steps; it does not change
/// the outcome, and without one the evaluation does no extra work.
Outcome evaluate(const Genome& genome, const GenomeLimits& limits, const TaskSettings& task,
                 const PhysicsSettings& physics, std::uint64_t eval_seed = 0,
                 FrameObserver* observer = nullptr);

}  // namespace cambrian
