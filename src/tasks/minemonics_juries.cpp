// cambrian: Minemonics' juries.
#include "tasks/minemonics_juries.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

namespace {

// the measured time of `steps` steps, s
double measuredTime(const Simulation& simulation, std::uint64_t steps) {
  return static_cast<double>(steps) * simulation.timeStep();
}

// Minemonics' size of a body: the edge of the cube of its total volume, m
double volumeCubeEdge(const BodyPlan& plan) {
  return 1.0 / volumeFactor(plan);
}

double length(Vec3 v) {
  return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

}  // namespace

void AverageVelocityJury::begin(const Simulation& simulation) {
  start_ = simulation.centerOfMass();
  steps_ = 0;
}

double AverageVelocityJury::value(const Simulation& simulation) const {
  const double time = measuredTime(simulation, steps_);
  if (time <= 0)
    return 0;
  return length(simulation.centerOfMass() - start_) / time / volumeCubeEdge(simulation.plan());
}

void IntegralAverageVelocityJury::begin(const Simulation& simulation) {
  last_ = simulation.centerOfMass();
  path_ = 0;
  steps_ = 0;
}

void IntegralAverageVelocityJury::observe(const Simulation& simulation) {
  const Vec3 now = simulation.centerOfMass();
  path_ += length(now - last_);
  last_ = now;
  ++steps_;
}

double IntegralAverageVelocityJury::value(const Simulation& simulation) const {
  const double time = measuredTime(simulation, steps_);
  return time <= 0 ? 0 : path_ / time / volumeCubeEdge(simulation.plan());
}

void MaximumHeightJury::begin(const Simulation& simulation) {
  highest_ = 0;
  observe(simulation);
}

void MaximumHeightJury::observe(const Simulation& simulation) {
  const Vec3 centre = simulation.centerOfMass();
  const double ground = simulation.environment().ground.heightAt(centre.x, centre.y);
  // no ground (water): the height above z = 0, where the plane would be
  const double above = std::isfinite(ground) ? centre.z - ground : centre.z;
  highest_ = std::max(highest_, above);
}

void AverageHeightJury::begin(const Simulation& simulation) {
  volumes_.clear();
  volume_ = 0;
  for (const PartPlan& part : simulation.plan().parts) {
    volumes_.push_back(shapeVolume(part.shape, part.size));
    volume_ += volumes_.back();
  }
  sum_ = 0;
  steps_ = 0;
}

void AverageHeightJury::observe(const Simulation& simulation) {
  const Ground& ground = simulation.environment().ground;
  double weighted = 0;
  for (int i = 0; i < static_cast<int>(volumes_.size()); ++i) {
    const Vec3 at = simulation.world().partPosition(i);
    const double floor = ground.heightAt(at.x, at.y);
    weighted += volumes_[i] * (std::isfinite(floor) ? at.z - floor : at.z);
  }
  sum_ += volume_ > 0 ? weighted / volume_ : 0;
  ++steps_;
}

double AverageHeightJury::value(const Simulation& simulation) const {
  return steps_ == 0 ? 0 : sum_ / static_cast<double>(steps_) / volumeCubeEdge(simulation.plan());
}

void GroundContactJury::begin(const Simulation& simulation) {
  touched_.assign(simulation.plan().parts.size(), 0);
}

void GroundContactJury::observe(const Simulation& simulation) {
  const std::vector<std::uint8_t>& now = simulation.groundContacts();
  for (std::size_t i = 0; i < touched_.size() && i < now.size(); ++i)
    touched_[i] |= now[i];
}

double GroundContactJury::value(const Simulation&) const {
  const double touched = static_cast<double>(std::count(touched_.begin(), touched_.end(), 1));
  if (!ratio_)
    return touched;
  return touched_.empty() ? 0 : touched / static_cast<double>(touched_.size());
}

void TimeOnGroundJury::observe(const Simulation& simulation) {
  const std::vector<std::uint8_t>& now = simulation.groundContacts();
  if (std::any_of(now.begin(), now.end(), [](std::uint8_t c) { return c != 0; }))
    ++steps_;
}

double TimeOnGroundJury::value(const Simulation& simulation) const {
  return measuredTime(simulation, steps_);
}

}  // namespace cambrian
