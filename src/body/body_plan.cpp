// cambrian: the aggregate measures of a developed BodyPlan.
#include "cambrian/body_plan.hpp"

namespace cambrian {

int BodyPlan::degreesOfFreedom() const {
  // the root's joint is rigid, so every part can be summed
  int total = 0;
  for (const PartPlan& part : parts) {
    total += cambrian::degreesOfFreedom(part.joint);
  }
  return total;
}

double BodyPlan::totalMass() const {
  // sum in part order, so the result is the same on every machine
  double total = 0;
  for (const PartPlan& part : parts) {
    total += part.mass;
  }
  return total;
}

double BodyPlan::totalVolume() const {
  // boxes only: volume is the product of the three sides
  double total = 0;
  for (const PartPlan& part : parts) {
    total += part.size.x * part.size.y * part.size.z;
  }
  return total;
}

}  // namespace cambrian
