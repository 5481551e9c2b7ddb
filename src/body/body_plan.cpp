// cambrian: names of the body kinds, shape geometry and the aggregate measures of a BodyPlan.
#include "cambrian/body_plan.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

namespace {

// radius and the half length of the straight middle of a capsule or cylinder lying along x
double radiusOf(Vec3 size) {
  return 0.5 * size.y;
}

// calls visit(corner) for the eight corners of a box of `size` in its own frame
template <class Visit>
void forEachCorner(Vec3 size, Visit visit) {
  Vec3 half = size * 0.5;
  for (int corner = 0; corner < 8; ++corner) {
    visit(Vec3{(corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y,
               (corner & 4) ? half.z : -half.z});
  }
}

}  // namespace

const char* shapeName(PartShape shape) {
  switch (shape) {
    case PartShape::box:
      return "box";
    case PartShape::capsule:
      return "capsule";
    case PartShape::sphere:
      return "sphere";
    case PartShape::cylinder:
      return "cylinder";
  }
  return "unknown";
}

int degreesOfFreedom(JointType type) {
  switch (type) {
    case JointType::fixed:
      return 0;
    case JointType::revolute:
    case JointType::prismatic:
      return 1;
    case JointType::universal:
      return 2;
    case JointType::spherical:
      return 3;
  }
  return 0;
}

const char* jointName(JointType type) {
  switch (type) {
    case JointType::fixed:
      return "fixed";
    case JointType::revolute:
      return "revolute";
    case JointType::universal:
      return "universal";
    case JointType::spherical:
      return "spherical";
    case JointType::prismatic:
      return "prismatic";
  }
  return "unknown";
}

double shapeVolume(PartShape shape, Vec3 size) {
  const double r = radiusOf(size);
  switch (shape) {
    case PartShape::box:
      return size.x * size.y * size.z;
    case PartShape::sphere: {
      const double radius = 0.5 * size.x;
      return 4.0 / 3.0 * kPi * radius * radius * radius;
    }
    case PartShape::capsule:
      return kPi * r * r * std::max(0.0, size.x - 2 * r) + 4.0 / 3.0 * kPi * r * r * r;
    case PartShape::cylinder:
      return kPi * r * r * size.x;
  }
  return 0;
}

double shapeSurface(PartShape shape, Vec3 size) {
  const double r = radiusOf(size);
  switch (shape) {
    case PartShape::box:
      return 2 * (size.x * size.y + size.x * size.z + size.y * size.z);
    case PartShape::sphere: {
      const double radius = 0.5 * size.x;
      return 4 * kPi * radius * radius;
    }
    case PartShape::capsule:
      return 2 * kPi * r * std::max(0.0, size.x - 2 * r) + 4 * kPi * r * r;
    case PartShape::cylinder:
      return 2 * kPi * r * size.x + 2 * kPi * r * r;
  }
  return 0;
}

double shapeReach(PartShape shape, Vec3 size, Quat rotation, Vec3 direction) {
  // the part's x axis in the world and its share of the direction
  const double along = dot(rotate(rotation, Vec3{1, 0, 0}), direction);
  const double r = radiusOf(size);
  switch (shape) {
    case PartShape::box: {
      double reach = 0;
      for (int k = 0; k < 3; ++k) {
        Vec3 axis;
        axis[k] = 1;
        reach += std::fabs(dot(rotate(rotation, axis), direction)) * 0.5 * size[k];
      }
      return reach;
    }
    case PartShape::sphere:
      return 0.5 * size.x;
    case PartShape::capsule:
      return std::fabs(along) * std::max(0.0, 0.5 * size.x - r) + r;
    case PartShape::cylinder:
      return std::fabs(along) * 0.5 * size.x + r * std::sqrt(std::max(0.0, 1 - along * along));
  }
  return 0;
}

SurfacePoint surfacePoint(PartShape shape, Vec3 size, Vec3 direction) {
  if (shape == PartShape::box) {
    int k = 0;
    for (int i = 1; i < 3; ++i) {
      if (std::fabs(direction[i]) > std::fabs(direction[k]))
        k = i;
    }
    const double sign = direction[k] < 0 ? -1.0 : 1.0;
    Vec3 on_face = direction;
    on_face[k] = sign;
    Vec3 normal;
    normal[k] = sign;
    return {hadamard(on_face, size * 0.5), normal};
  }
  const double length = std::sqrt(dot(direction, direction));
  const Vec3 d = length > 0 ? direction * (1 / length) : Vec3{1, 0, 0};
  const double across = std::sqrt(d.y * d.y + d.z * d.z);  // the share away from the x axis
  const Vec3 radial = across > 0 ? Vec3{0, d.y / across, d.z / across} : Vec3{0, 0, 0};
  if (shape == PartShape::sphere)
    return {d * (0.5 * size.x), d};
  const double r = radiusOf(size);
  if (shape == PartShape::cylinder) {
    const double to_side = across > 0 ? r / across : HUGE_VAL;
    const double to_cap = d.x != 0 ? 0.5 * size.x / std::fabs(d.x) : HUGE_VAL;
    if (to_side <= to_cap)
      return {d * to_side, radial};
    return {d * to_cap, Vec3{d.x < 0 ? -1.0 : 1.0, 0, 0}};
  }
  // a capsule: the straight middle, else the cap the ray leaves through
  const double half_middle = std::max(0.0, 0.5 * size.x - r);
  if (across > 0 && std::fabs(d.x) * (r / across) <= half_middle)
    return {d * (r / across), radial};
  const Vec3 centre{d.x < 0 ? -half_middle : half_middle, 0, 0};
  const double b = dot(d, centre);
  const double t = b + std::sqrt(std::max(0.0, b * b - dot(centre, centre) + r * r));
  const Vec3 point = d * t;
  return {point, (point - centre) * (1 / r)};
}

double sectionArea(PartShape shape, Vec3 size, int axis) {
  const double r = radiusOf(size);
  switch (shape) {
    case PartShape::box:
      return size[(axis + 1) % 3] * size[(axis + 2) % 3];
    case PartShape::sphere:
      return kPi * 0.25 * size.x * size.x;
    case PartShape::capsule:
      return axis == 0 ? kPi * r * r : std::max(0.0, size.x - 2 * r) * 2 * r + kPi * r * r;
    case PartShape::cylinder:
      return axis == 0 ? kPi * r * r : size.x * 2 * r;
  }
  return 0;
}

double lowestZ(const PartPlan& part, const Transform& pose) {
  // a box: its lowest corner, exactly as placed
  if (part.shape == PartShape::box) {
    double lowest = 0;
    bool first = true;
    forEachCorner(part.size, [&](Vec3 local) {
      double z = apply(pose, local).z;
      if (first || z < lowest)
        lowest = z;
      first = false;
    });
    return lowest;
  }
  return pose.position.z - shapeReach(part.shape, part.size, pose.rotation, Vec3{0, 0, 1});
}

int BodyPlan::jointCount() const {
  return (parts.empty() ? 0 : static_cast<int>(parts.size()) - 1) + static_cast<int>(loops.size());
}

int BodyPlan::degreesOfFreedom() const {
  // the root's joint is fixed, so every part can be summed
  int total = 0;
  for (const PartPlan& part : parts)
    total += cambrian::degreesOfFreedom(part.joint);
  for (const LoopJoint& loop : loops)
    total += cambrian::degreesOfFreedom(loop.joint);
  return total;
}

double BodyPlan::totalMass() const {
  // sum in part order, so the result is the same on every machine
  double total = 0;
  for (const PartPlan& part : parts)
    total += part.mass;
  return total;
}

double BodyPlan::totalVolume() const {
  double total = 0;
  for (const PartPlan& part : parts)
    total += shapeVolume(part.shape, part.size);
  return total;
}

double bodyLength(const BodyPlan& plan) {
  // horizontal span of every part at birth (boxes: every corner)
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  bool first = true;
  auto include = [&](Vec3 p) {
    if (first) {
      min_x = max_x = p.x;
      min_y = max_y = p.y;
      first = false;
    }
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y);
    max_y = std::max(max_y, p.y);
  };
  for (const PartPlan& part : plan.parts) {
    if (part.shape == PartShape::box) {
      forEachCorner(part.size, [&](Vec3 local) { include(apply(part.pose, local)); });
      continue;
    }
    for (Vec3 direction : {Vec3{1, 0, 0}, Vec3{0, 1, 0}}) {
      double reach = shapeReach(part.shape, part.size, part.pose.rotation, direction);
      include(part.pose.position + direction * reach);
      include(part.pose.position - direction * reach);
    }
  }
  return std::max(max_x - min_x, max_y - min_y);
}

}  // namespace cambrian
