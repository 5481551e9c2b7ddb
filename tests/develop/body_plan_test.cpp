// Tests of BodyPlan's aggregate measures: degrees of freedom, mass and volume.
#include "cambrian/body_plan.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

// a part of the given size, mass and joint
PartPlan part(Vec3 size, double mass, JointType joint) {
  PartPlan p;
  p.size = size;
  p.mass = mass;
  p.joint = joint;
  return p;
}

TEST(BodyPlan, EmptyPlanMeasuresZero) {
  const BodyPlan plan;
  EXPECT_EQ(plan.degreesOfFreedom(), 0);
  EXPECT_EQ(plan.totalMass(), 0.0);
  EXPECT_EQ(plan.totalVolume(), 0.0);
  EXPECT_EQ(plan.jointCount(), 0);
}

TEST(BodyPlan, SumsDegreesOfFreedomMassAndVolumeOverParts) {
  BodyPlan plan;
  plan.parts.push_back(part({1, 0.5, 0.2}, 10, JointType::rigid));
  plan.parts.push_back(part({0.2, 0.2, 0.2}, 2, JointType::revolute));
  plan.parts.push_back(part({0.1, 0.2, 0.3}, 1.5, JointType::universal));
  plan.parts.push_back(part({0.5, 0.1, 0.1}, 0.5, JointType::spherical));
  EXPECT_EQ(plan.degreesOfFreedom(), 0 + 1 + 2 + 3);
  EXPECT_DOUBLE_EQ(plan.totalMass(), 14.0);
  EXPECT_DOUBLE_EQ(plan.totalVolume(), 0.1 + 0.008 + 0.006 + 0.005);
  EXPECT_EQ(plan.jointCount(), 3);
}

TEST(BodyPlan, SignalLayoutIsSensorsThenNeurons) {
  BodyPlan plan;
  plan.sensors.resize(5);
  plan.neurons.resize(3);
  EXPECT_EQ(plan.signalCount(), 8);
  EXPECT_EQ(plan.neuronSignal(0), 5);
  EXPECT_EQ(plan.neuronSignal(2), 7);
}

}  // namespace
}  // namespace cambrian
