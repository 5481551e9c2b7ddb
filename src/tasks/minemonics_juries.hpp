// cambrian: Minemonics' juries — the measures its creatures are rated by: how fast they get
// away, how high they stay, how often they touch the ground. Each is a Jury (tasks/juries.hpp),
// a named measure; the juries task records them all.
#pragma once

#include "tasks/juries.hpp"

#include <vector>

namespace cambrian {

/// "average_velocity": the straight-line displacement of the centre of mass over the measured
/// phase, divided by its duration and by the edge of the cube of the body's volume (its
/// size, 1 / volumeFactor), 1/s (body sizes per second).
class AverageVelocityJury : public Jury {
 public:
  const char* name() const override { return "average_velocity"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation&) override { ++steps_; }
  double value(const Simulation& simulation) const override;

 private:
  Vec3 start_;
  std::uint64_t steps_ = 0;
};

/// "integral_average_velocity": the length of the path of the centre of mass, step by step,
/// divided by the duration and by the volume cube's edge, 1/s.
class IntegralAverageVelocityJury : public Jury {
 public:
  const char* name() const override { return "integral_average_velocity"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  Vec3 last_;
  double path_ = 0;
  std::uint64_t steps_ = 0;
};

/// "maximum_height": the highest the centre of mass rose above the ground under it (no ground:
/// above z = 0), m.
class MaximumHeightJury : public Jury {
 public:
  const char* name() const override { return "maximum_height"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation&) const override { return highest_; }

 private:
  double highest_ = 0;
};

/// "average_height": the parts' volume-weighted mean height above the ground under each,
/// averaged over the measured steps, divided by the volume cube's edge (body sizes).
class AverageHeightJury : public Jury {
 public:
  const char* name() const override { return "average_height"; }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  std::vector<double> volumes_;  // each part's, for the weights
  double volume_ = 0;            // their sum
  double sum_ = 0;
  std::uint64_t steps_ = 0;
};

/// "ground_contact_quantity" (parts that touched the ground in some measured step) or
/// "ground_contact_ratio" (those parts over all parts).
class GroundContactJury : public Jury {
 public:
  explicit GroundContactJury(bool ratio) : ratio_(ratio) {}
  const char* name() const override {
    return ratio_ ? "ground_contact_ratio" : "ground_contact_quantity";
  }
  void begin(const Simulation& simulation) override;
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  bool ratio_;
  std::vector<std::uint8_t> touched_;
};

/// "time_on_ground": measured time during which some part touched the ground, s.
class TimeOnGroundJury : public Jury {
 public:
  const char* name() const override { return "time_on_ground"; }
  void begin(const Simulation&) override { steps_ = 0; }
  void observe(const Simulation& simulation) override;
  double value(const Simulation& simulation) const override;

 private:
  std::uint64_t steps_ = 0;
};

}  // namespace cambrian
