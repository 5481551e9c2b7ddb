#include "tasks/juries.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian {
namespace {

BodyPlan boxes(std::initializer_list<Vec3> sizes) {
  BodyPlan plan;
  double x = 0;
  for (Vec3 size : sizes) {
    PartPlan part;
    part.size = size;
    part.mass = 1000 * size.x * size.y * size.z;
    part.pose.position = {x + size.x / 2, 0, 0};
    x += size.x;
    plan.parts.push_back(part);
  }
  return plan;
}

// Chaumont's coefficients for a single unit cube: C_l = 3, C_s = 6, C_v = 1, k^1
TEST(Juries, ChaumontFactorUnitCube) {
  BodyPlan plan = boxes({{1, 1, 1}});
  EXPECT_DOUBLE_EQ(chaumontFactor(plan, 1.02), 1.0 / 18.0 * 1.02);
}

// scaling a body by s scales C_v / (C_s C_l) by 1, so distances in equal proportion score equal
TEST(Juries, ChaumontFactorScales) {
  BodyPlan small = boxes({{0.1, 0.2, 0.3}, {0.2, 0.1, 0.1}});
  BodyPlan large = boxes({{0.2, 0.4, 0.6}, {0.4, 0.2, 0.2}});
  EXPECT_NEAR(chaumontFactor(large, 1.0) * 1.0, chaumontFactor(small, 1.0) * 1.0, 1e-12);
}

// the volume factor is one over the cube root of the total volume
TEST(Juries, VolumeFactor) {
  BodyPlan plan = boxes({{2, 2, 2}});
  EXPECT_NEAR(volumeFactor(plan), 0.5, 1e-12);
}

// body length is the largest horizontal span
TEST(Juries, BodyLength) {
  BodyPlan plan = boxes({{0.5, 0.2, 0.1}, {0.3, 0.1, 0.1}});
  EXPECT_NEAR(bodyLength(plan), 0.8, 1e-12);
}

}  // namespace
}  // namespace cambrian
