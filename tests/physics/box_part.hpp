// test helper: a box part of a hand-built BodyPlan
#pragma once

#include "cambrian/body_plan.hpp"

namespace cambrian::test {

/// A box part of `size` at `position` (creature frame), density 1000, child of `parent`.
inline PartPlan box(Vec3 size, Vec3 position, int parent = -1) {
  PartPlan part;
  part.size = size;
  part.mass = 1000 * size.x * size.y * size.z;
  part.pose.position = position;
  part.parent = parent;
  return part;
}

/// A 0.3 x 0.1 x 0.1 m box on a revolute joint (limit 1 rad) at the centre of the +x face of a
/// 0.4 x 0.2 x 0.1 m root at the origin, the root's child.
inline PartPlan hingedChild() {
  PartPlan child = box({0.3, 0.1, 0.1}, {0.35, 0, 0}, 0);
  child.joint = JointType::revolute;
  child.pivot_in_parent = {0.2, 0, 0};
  child.pivot_in_child = {-0.15, 0, 0};
  child.joint_limit = {1.0, 1.0, 1.0};
  child.cross_section = 0.01;
  child.connection = 0;
  return child;
}

}  // namespace cambrian::test
