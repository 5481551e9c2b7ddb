#include "tasks/juries.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

void DistanceJury::begin(const Simulation& simulation) {
  start_ = simulation.centerOfMass();
}

double DistanceJury::value(const Simulation& simulation) const {
  Vec3 moved = simulation.centerOfMass() - start_;
  return std::sqrt(moved.x * moved.x + moved.y * moved.y);
}

void HeightJury::begin(const Simulation& simulation) {
  best_ = simulation.lowestPoint();
}

void HeightJury::observe(const Simulation& simulation) {
  best_ = std::max(best_, simulation.lowestPoint());
}

double chaumontFactor(const BodyPlan& plan, double k) {
  // C_l: mean summed side length; C_s: mean surface; C_v: mean volume (Chaumont et al. 3.4)
  double lengths = 0, surfaces = 0, volumes = 0;
  for (const PartPlan& part : plan.parts) {
    Vec3 b = part.size;
    lengths += b.x + b.y + b.z;
    surfaces += 2 * (b.x * b.y + b.x * b.z + b.y * b.z);
    volumes += b.x * b.y * b.z;
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

double bodyLength(const BodyPlan& plan) {
  // horizontal span of every box corner at birth
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  bool first = true;
  for (const PartPlan& part : plan.parts) {
    Vec3 half = part.size * 0.5;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3 local{(corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y,
                 (corner & 4) ? half.z : -half.z};
      Vec3 p = apply(part.pose, local);
      if (first) {
        min_x = max_x = p.x;
        min_y = max_y = p.y;
        first = false;
      }
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  }
  return std::max(max_x - min_x, max_y - min_y);
}

}  // namespace cambrian
