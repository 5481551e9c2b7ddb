// cambrian: juries — named measures taken over a phase, reusable by every task.
#pragma once

#include "cambrian/body_plan.hpp"

#include "physics/simulation.hpp"

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
};

/// "distance": horizontal displacement of the centre of mass over the measured phase, m.
class DistanceJury : public Jury {
 public:
  const char* name() const override { return "distance"; }
  void begin(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  Vec3 start_;
};

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

/// Chaumont et al.'s size normalisation C_v / (C_s * C_l) * k^N over the parts of a plan.
double chaumontFactor(const BodyPlan& plan, double k);
/// Minemonics' normalisation: 1 / cbrt(total volume).
double volumeFactor(const BodyPlan& plan);

}  // namespace cambrian
