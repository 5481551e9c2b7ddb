// Tests of BodyPlan: the names and degrees of freedom of the joint kinds, shape geometry
// (volume, surface, reach, lowest point, body length) and the aggregate measures.
#include "cambrian/body_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace cambrian {
namespace {

// a part of the given size, mass and joint
PartPlan part(Vec3 size, double mass, JointType joint, PartShape shape = PartShape::box) {
  PartPlan p;
  p.size = size;
  p.mass = mass;
  p.joint = joint;
  p.shape = shape;
  return p;
}

TEST(BodyPlan, EmptyPlanMeasuresZero) {
  const BodyPlan plan;
  EXPECT_EQ(plan.degreesOfFreedom(), 0);
  EXPECT_EQ(plan.totalMass(), 0.0);
  EXPECT_EQ(plan.totalVolume(), 0.0);
  EXPECT_EQ(plan.jointCount(), 0);
  EXPECT_EQ(bodyLength(plan), 0.0);
}

TEST(BodyPlan, SumsDegreesOfFreedomMassAndVolumeOverPartsAndLoops) {
  BodyPlan plan;
  plan.parts.push_back(part({1, 0.5, 0.2}, 10, JointType::fixed));
  plan.parts.push_back(part({0.2, 0.2, 0.2}, 2, JointType::revolute));
  plan.parts.push_back(part({0.1, 0.2, 0.3}, 1.5, JointType::universal));
  plan.parts.push_back(part({0.5, 0.1, 0.1}, 0.5, JointType::spherical));
  plan.parts.push_back(part({0.4, 0.1, 0.1}, 0.5, JointType::prismatic));
  EXPECT_EQ(plan.degreesOfFreedom(), 0 + 1 + 2 + 3 + 1);
  EXPECT_DOUBLE_EQ(plan.totalMass(), 14.5);
  EXPECT_DOUBLE_EQ(plan.totalVolume(), 0.1 + 0.008 + 0.006 + 0.005 + 0.004);
  EXPECT_EQ(plan.jointCount(), 4);
  // a closed loop adds a joint and its degrees of freedom
  LoopJoint loop;
  loop.part_a = 1;
  loop.part_b = 3;
  loop.joint = JointType::universal;
  plan.loops.push_back(loop);
  EXPECT_EQ(plan.jointCount(), 5);
  EXPECT_EQ(plan.degreesOfFreedom(), 7 + 2);
}

TEST(BodyPlan, KindsHaveDistinctNames) {
  std::set<std::string> joints, shapes;
  for (int j = 0; j < kJointTypeKinds; ++j)
    joints.insert(jointName(static_cast<JointType>(j)));
  for (int s = 0; s < kPartShapeKinds; ++s)
    shapes.insert(shapeName(static_cast<PartShape>(s)));
  EXPECT_EQ(joints.size(), static_cast<std::size_t>(kJointTypeKinds));
  EXPECT_EQ(shapes.size(), static_cast<std::size_t>(kPartShapeKinds));
  EXPECT_STREQ(jointName(JointType::prismatic), "prismatic");
  EXPECT_STREQ(shapeName(PartShape::capsule), "capsule");
}

TEST(Shape, VolumesAndSurfaces) {
  const double r = 0.1;
  EXPECT_DOUBLE_EQ(shapeVolume(PartShape::box, {1, 2, 3}), 6.0);
  EXPECT_DOUBLE_EQ(shapeSurface(PartShape::box, {1, 2, 3}), 22.0);
  EXPECT_NEAR(shapeVolume(PartShape::sphere, {2 * r, 2 * r, 2 * r}), 4.0 / 3.0 * kPi * r * r * r,
              1e-15);
  EXPECT_NEAR(shapeSurface(PartShape::sphere, {2 * r, 2 * r, 2 * r}), 4 * kPi * r * r, 1e-15);
  // a capsule of length 1 and diameter 0.2: a cylinder of 0.8 and a sphere
  EXPECT_NEAR(shapeVolume(PartShape::capsule, {1, 2 * r, 2 * r}),
              kPi * r * r * 0.8 + 4.0 / 3.0 * kPi * r * r * r, 1e-15);
  EXPECT_NEAR(shapeVolume(PartShape::cylinder, {1, 2 * r, 2 * r}), kPi * r * r, 1e-15);
  EXPECT_NEAR(shapeSurface(PartShape::cylinder, {1, 2 * r, 2 * r}), 2 * kPi * r + 2 * kPi * r * r,
              1e-15);
}

TEST(Shape, ReachAlongADirection) {
  const Vec3 up{0, 0, 1};
  const Quat identity{};
  // turned 90 degrees about y, the x axis points down
  const Quat pitched = quatFromEuler({0, kPi / 2, 0});
  EXPECT_DOUBLE_EQ(shapeReach(PartShape::box, {1, 2, 3}, identity, up), 1.5);
  EXPECT_NEAR(shapeReach(PartShape::box, {1, 2, 3}, pitched, up), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(shapeReach(PartShape::sphere, {0.4, 0.4, 0.4}, pitched, up), 0.2);
  EXPECT_DOUBLE_EQ(shapeReach(PartShape::capsule, {1, 0.2, 0.2}, identity, up), 0.1);
  EXPECT_NEAR(shapeReach(PartShape::capsule, {1, 0.2, 0.2}, pitched, up), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(shapeReach(PartShape::cylinder, {1, 0.2, 0.2}, identity, up), 0.1);
  EXPECT_NEAR(shapeReach(PartShape::cylinder, {1, 0.2, 0.2}, pitched, up), 0.5, 1e-12);
}

TEST(Shape, LowestPointAndBodyLength) {
  PartPlan box = part({1, 0.5, 0.2}, 1, JointType::fixed);
  box.pose.position = {0, 0, 1};
  EXPECT_DOUBLE_EQ(lowestZ(box, box.pose), 0.9);
  PartPlan ball = part({0.4, 0.4, 0.4}, 1, JointType::fixed, PartShape::sphere);
  ball.pose.position = {2, 0, 1};
  EXPECT_DOUBLE_EQ(lowestZ(ball, ball.pose), 0.8);
  BodyPlan plan;
  plan.parts = {box, ball};
  // from the box's left end (-0.5) to the sphere's right side (2.2)
  EXPECT_DOUBLE_EQ(bodyLength(plan), 2.7);
}

}  // namespace
}  // namespace cambrian
