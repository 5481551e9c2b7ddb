// cambrian: the distance, displacement, approach, flag, height, iterative distance and throw
// juries and the walk normalisations.
#include "tasks/juries.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

namespace {
// horizontal distance between two points, m
double horizontal(Vec3 a, Vec3 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
}  // namespace

Vec3 trackedPosition(const Simulation& simulation, TrackedPoint point) {
  return point == TrackedPoint::root ? simulation.world().partPosition(0)
                                     : simulation.centerOfMass();
}

void DistanceJury::begin(const Simulation& simulation) {
  start_ = trackedPosition(simulation, point_);
}

double DistanceJury::value(const Simulation& simulation) const {
  Vec3 moved = trackedPosition(simulation, point_) - start_;
  return std::sqrt(moved.x * moved.x + moved.y * moved.y);
}

void DisplacementJury::begin(const Simulation& simulation) {
  steps_ = 0;
  start_ = simulation.centerOfMass();
}

void DisplacementJury::observe(const Simulation& simulation) {
  if (++steps_ == from_step_)
    start_ = simulation.centerOfMass();
}

double DisplacementJury::value(const Simulation& simulation) const {
  return norm(simulation.centerOfMass() - start_);
}

void ApproachJury::begin(const Simulation& simulation) {
  start_distance_ = norm(simulation.light() - simulation.centerOfMass());
}

double ApproachJury::value(const Simulation& simulation) const {
  return start_distance_ - norm(simulation.light() - simulation.centerOfMass());
}

void FlagJury::begin(const Simulation& simulation) {
  const Vec3 start = simulation.centerOfMass();
  flag_ = {start.x + offset_.x, start.y + offset_.y, 0};
  steps_ = 0;
  reached_ = horizontal(start, flag_) <= radius_;
}

void FlagJury::observe(const Simulation& simulation) {
  if (reached_)
    return;
  ++steps_;
  reached_ = horizontal(simulation.centerOfMass(), flag_) <= radius_;
}

double FlagJury::value(const Simulation& simulation) const {
  return horizontal(simulation.centerOfMass(), flag_);
}

double flagFitness(double distance, double start_distance, double seconds, double limit,
                   double alpha, double beta) {
  const double closer = distance <= start_distance ? alpha * (start_distance - distance) : 0;
  return closer + beta * (limit - seconds);
}

void HeightJury::begin(const Simulation& simulation) {
  best_ = simulation.lowestPoint();
}

void HeightJury::observe(const Simulation& simulation) {
  best_ = std::max(best_, simulation.lowestPoint());
}

void IterativeDistance::add(double distance, double time) {
  // this gain of distance, weighted by when it came (divided by T in value())
  weighted_ += (distance - distance_) * time;
  distance_ = distance;
  time_ = time;
}

void IterativeDistanceJury::begin(const Simulation& simulation) {
  start_ = trackedPosition(simulation, point_);
  steps_ = 0;
  sum_ = IterativeDistance();
}

void IterativeDistanceJury::observe(const Simulation& simulation) {
  ++steps_;
  sum_.add(horizontal(trackedPosition(simulation, point_), start_),
           static_cast<double>(steps_) * simulation.timeStep());
}

double chaumontFactor(const BodyPlan& plan, double k) {
  // C_l: mean summed side length; C_s: mean surface; C_v: mean volume (Chaumont et al. 3.4)
  double lengths = 0, surfaces = 0, volumes = 0;
  for (const PartPlan& part : plan.parts) {
    Vec3 b = part.size;
    lengths += b.x + b.y + b.z;
    surfaces += shapeSurface(part.shape, b);
    volumes += shapeVolume(part.shape, b);
  }
  double n = static_cast<double>(plan.parts.size());
  if (n == 0)
    return 0;
  double c_l = lengths / n, c_s = surfaces / n, c_v = volumes / n;
  return c_v / (c_s * c_l) * std::pow(k, n);
}

double volumeFactor(const BodyPlan& plan) {
  double volume = plan.totalVolume();
  return volume > 0 ? 1.0 / std::cbrt(volume) : 0;
}

void ThrowJury::begin(const Simulation& simulation) {
  steps_ = 0;
  release_step_ = -1;
  released_ = false;
  resting_ = 0;
  distance_ = 0;
  last_ = simulation.world().heldPose(0).position;
  miss_ = norm(last_ - target_);
}

void ThrowJury::observe(const Simulation& simulation) {
  ++steps_;
  const World& world = simulation.world();
  const Vec3 here = world.heldPose(0).position;
  if (!released_) {
    if (!world.released(0)) {
      last_ = here;
      return;
    }
    // let go during this step: measured from where it was when the step began
    released_ = true;
    release_step_ = steps_ - 1;
    release_point_ = last_;
    miss_ = norm(last_ - target_);
  }

  // the path: nearest the target on the segment its centre moved along this step
  const Vec3 ab = here - last_;
  const double length_sq = dot(ab, ab);
  const double u = length_sq > 0 ? std::clamp(dot(target_ - last_, ab) / length_sq, 0.0, 1.0) : 0.0;
  const Vec3 nearest = last_ + ab * u - target_;
  miss_ = std::min(miss_, norm(nearest));
  distance_ = horizontal(release_point_, here);

  // at rest: slower than rest_speed for rest_steps steps in a row
  resting_ = std::sqrt(length_sq) <= rest_speed_ * simulation.timeStep() ? resting_ + 1 : 0;
  last_ = here;
}

}  // namespace cambrian
