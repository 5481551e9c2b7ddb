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

}  // namespace cambrian::test
