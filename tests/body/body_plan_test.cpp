// Tests of BodyPlan: the names and degrees of freedom of the joint kinds, shape geometry
// (volume, surface, reach, lowest point, body length) and the aggregate measures.
#include "cambrian/body_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

namespace cambrian {
namespace {

// distance from p to the segment of a capsule's straight middle, [-h, h] on x
double fromMiddle(Vec3 p, double h) {
  const double x = std::clamp(p.x, -h, h);
  return std::sqrt((p.x - x) * (p.x - x) + p.y * p.y + p.z * p.z);
}

TEST(BodyPlan, SurfacePointsLieOnTheSurfaceWithUnitOutwardNormals) {
  // a box: Sims' rule, the face of the largest component at the point the others give
  const SurfacePoint face = surfacePoint(PartShape::box, {0.6, 0.4, 0.2}, {0.5, -1, 0.25});
  EXPECT_EQ(face.point, (Vec3{0.15, -0.2, 0.025}));
  EXPECT_EQ(face.normal, (Vec3{0, -1, 0}));
  EXPECT_EQ(surfacePoint(PartShape::box, {0.6, 0.4, 0.2}, {0, 0, 0}).point, (Vec3{0.3, 0, 0}));

  // a capsule 0.8 long, 0.2 thick: the ray from its centre leaves it where distance = radius
  const Vec3 size{0.8, 0.2, 0.2};
  for (const Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.3, 0.2, -0.4},
                       Vec3{1, 0.05, 0}, Vec3{-0.9, 0.1, 0.2}, Vec3{0, 0, 0}}) {
    const SurfacePoint s = surfacePoint(PartShape::capsule, size, d);
    EXPECT_NEAR(fromMiddle(s.point, 0.3), 0.1, 1e-12) << d.x << " " << d.y << " " << d.z;
    EXPECT_NEAR(norm(s.normal), 1, 1e-12);
    // the normal points away from the nearest point of the middle
    const Vec3 nearest{std::clamp(s.point.x, -0.3, 0.3), 0, 0};
    EXPECT_LT(norm(s.point - nearest - s.normal * 0.1), 1e-12);
    // and along the direction asked
    if (norm(d) > 0) {
      EXPECT_LT(norm(s.point * (1 / norm(s.point)) - d * (1 / norm(d))), 1e-12);
    }
  }
  EXPECT_LT(norm(surfacePoint(PartShape::capsule, size, {-1, 0, 0}).point - Vec3{-0.4, 0, 0}),
            1e-15);
  EXPECT_NEAR(surfacePoint(PartShape::sphere, {0.5, 0.5, 0.5}, {0, 3, 4}).point.z, 0.2, 1e-15);
  const SurfacePoint cap = surfacePoint(PartShape::cylinder, {0.4, 0.2, 0.2}, {1, 0.1, 0});
  EXPECT_NEAR(cap.point.x, 0.2, 1e-15);
  EXPECT_EQ(cap.normal, (Vec3{1, 0, 0}));
}

TEST(BodyPlan, SectionAreas) {
  EXPECT_DOUBLE_EQ(sectionArea(PartShape::box, {0.6, 0.4, 0.2}, 0), 0.4 * 0.2);
  EXPECT_DOUBLE_EQ(sectionArea(PartShape::box, {0.6, 0.4, 0.2}, 2), 0.6 * 0.4);
  EXPECT_DOUBLE_EQ(sectionArea(PartShape::capsule, {0.8, 0.2, 0.2}, 0), kPi * 0.01);
  EXPECT_DOUBLE_EQ(sectionArea(PartShape::capsule, {0.8, 0.2, 0.2}, 1), 0.6 * 0.2 + kPi * 0.01);
}

}  // namespace
}  // namespace cambrian
