// cambrian: juries — named measures taken over a phase, reusable by every task.
#pragma once

#include "cambrian/body_plan.hpp"

#include "physics/simulation.hpp"

#include <cstdint>

namespace cambrian {

/// A measure taken over the measured phase of an evaluation.
class Jury {
 public:
  virtual ~Jury() = default;
  /// Measure name as stored in outcomes and histories ("distance").
  virtual const char* name() const = 0;
  /// Called once when measuring starts.
  virtual void begin(const Simulation&) {}
  /// Called after every measured step.
  virtual void observe(const Simulation&) {}
  /// The measure at the end of the measured phase.
  virtual double value(const Simulation& simulation) const = 0;
  /// True once the jury has measured all it will: the phase then ends early (a thrown block
  /// come to rest).
  virtual bool finished() const { return false; }
};

/// The point of a body a distance is measured at.
enum class TrackedPoint : std::uint8_t {
  centre_of_mass,  ///< of the whole body (Sims)
  root,            ///< the root part's centre (Chaumont et al.: "the center of mass of its root
                   ///< block")
};

/// The world position of `point` of the simulated body.
Vec3 trackedPosition(const Simulation& simulation, TrackedPoint point);

/// "distance": horizontal displacement of the tracked point over the measured phase, m.
class DistanceJury : public Jury {
 public:
  explicit DistanceJury(TrackedPoint point = TrackedPoint::centre_of_mass,
                        const char* name = "distance")
      : point_(point), name_(name) {}
  const char* name() const override { return name_; }
  void begin(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  TrackedPoint point_;
  const char* name_;
  Vec3 start_;
};

/// The straight-line (3-D) distance of the centre of mass from where it was after `from_step`
/// measured steps (0: where measuring began) to where it is, m: Sims' swimming distance.
class DisplacementJury : public Jury {
 public:
  explicit DisplacementJury(const char* name, std::uint64_t from_step = 0)
      : name_(name), from_step_(from_step) {}
  const char* name() const override { return name_; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  const char* name_;
  std::uint64_t from_step_;
  std::uint64_t steps_ = 0;
  Vec3 start_;
};

/// "approach": how much nearer the light (Simulation::light) the centre of mass came while
/// measured, m (negative: it went away).
class ApproachJury : public Jury {
 public:
  const char* name() const override { return "approach"; }
  void begin(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  double start_distance_ = 0;
};

/// "flag_distance": the horizontal distance of the centre of mass from a flag placed at
/// `offset` (x, y) from where the centre of mass was when measuring began, m. The jury finishes,
/// and the phase ends, once the centre of mass is within `radius` of the flag (Krčah 2008: "the
/// run stops when it is within R metres of the flag").
class FlagJury : public Jury {
 public:
  FlagJury(Vec3 offset, double radius) : offset_(offset), radius_(radius) {}
  const char* name() const override { return "flag_distance"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;
  bool finished() const override { return reached_; }
  /// Measured steps until the flag was reached (all of them while it is not).
  std::uint64_t steps() const { return steps_; }
  bool reached() const { return reached_; }

 private:
  Vec3 offset_;
  double radius_;
  Vec3 flag_;
  std::uint64_t steps_ = 0;
  bool reached_ = false;
};

/// Krčah's flag fitness f(d) + g(t): α · (D − d) when the final distance d to the flag is at most
/// D, the flag's distance from the start (else 0), plus β · (N − t) for reaching it at t of the N
/// seconds (0 when it is not reached: t = N).
double flagFitness(double distance, double start_distance, double seconds, double limit,
                   double alpha, double beta);

/// "height": the highest the creature's lowest point rose above the ground, m (WWD's jump).
class HeightJury : public Jury {
 public:
  const char* name() const override { return "height"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation&) const override { return best_ < 0 ? 0 : best_; }

 private:
  double best_ = 0;
};

/// The arithmetic of Walking with Dinosaurs' iterative move: fed the distance d_i from the start
/// at each measured time t_i (from the start of measuring, increasing), its value is
/// Σ_i (d_i − d_{i−1}) · t_i / T, with d_0 = 0 and T the last t_i: each gain of distance weighted
/// by how late it came. A steady mover to distance D scores about D / 2, one that gets to D at
/// once and stops about 0, one that gets there at the very end about D; losses count negatively.
class IterativeDistance {
 public:
  /// Distance `distance` (m) at time `time` (s) from the start of measuring.
  void add(double distance, double time);
  /// The weighted sum, m (0 before the first add or while T = 0).
  double value() const { return time_ > 0 ? weighted_ / time_ : 0; }

 private:
  double distance_ = 0;  // d_{i−1}
  double time_ = 0;      // t_{i−1}, at the end T
  double weighted_ = 0;  // Σ (d_i − d_{i−1}) · t_i
};

/// "iterative_distance": Walking with Dinosaurs' iterative move (IterativeDistance) over the
/// horizontal distance of the tracked point from where it was when measuring began, each
/// measured step at its time from then, m. May be negative (the point came back).
class IterativeDistanceJury : public Jury {
 public:
  explicit IterativeDistanceJury(TrackedPoint point = TrackedPoint::centre_of_mass)
      : point_(point) {}
  const char* name() const override { return "iterative_distance"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation&) const override { return sum_.value(); }

 private:
  TrackedPoint point_;
  Vec3 start_;
  std::uint64_t steps_ = 0;
  IterativeDistance sum_;
};

/// "distance": Chaumont et al.'s throw (4.2). Held object 0 is followed from the step it is let
/// go: the horizontal distance from where it was let go to where it is (D_p), the least distance
/// of its centre's path from the point `target` (D_t), and whether it has come to rest (its
/// centre slower than `rest_speed` for `rest_steps` steps in a row), which finishes the jury.
class ThrowJury : public Jury {
 public:
  ThrowJury(Vec3 target, double rest_speed, std::uint64_t rest_steps)
      : target_(target), rest_speed_(rest_speed), rest_steps_(rest_steps) {}
  const char* name() const override { return "distance"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation&) const override { return distance_; }
  bool finished() const override { return resting_ >= rest_steps_; }
  /// Whether the object has been let go.
  bool released() const { return released_; }
  /// Measured steps before it was let go (-1 while held).
  std::int64_t releaseStep() const { return release_step_; }
  /// D_t, m: the target's distance from the projectile while held.
  double miss() const { return miss_; }

 private:
  Vec3 target_;
  double rest_speed_;
  std::uint64_t rest_steps_;
  std::int64_t steps_ = 0, release_step_ = -1;
  bool released_ = false;
  Vec3 release_point_, last_;
  double distance_ = 0, miss_ = 0;
  std::uint64_t resting_ = 0;
};

/// Chaumont et al.'s size normalisation C_v / (C_s * C_l) * k^N over the parts of a plan.
double chaumontFactor(const BodyPlan& plan, double k);
/// Minemonics' normalisation: 1 / cbrt(total volume).
double volumeFactor(const BodyPlan& plan);

}  // namespace cambrian
