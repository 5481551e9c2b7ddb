// cambrian: BodyPlan, the immutable developed body — the one meeting point between genome
// encodings and physics worlds. Parts with shapes and materials, joints of several kinds (a tree
// through each part's parent, plus closed-loop joints), sensors and effectors. No Bullet here.
#pragma once

#include "cambrian/math.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cambrian {

/// Part shapes. `PartPlan::size` is the full box size; a capsule or cylinder lies along its x
/// axis (size.x its whole length, size.y its diameter), a sphere's diameter is size.x.
enum class PartShape : std::uint8_t { box = 0, capsule = 1, sphere = 2, cylinder = 3 };
/// Number of PartShape values.
constexpr int kPartShapeKinds = 4;
/// Lower-case shape name ("capsule").
const char* shapeName(PartShape shape);

/// How a part is jointed to another. Degrees of freedom: fixed 0, revolute 1, universal 2,
/// spherical 3, prismatic 1 (a slider along its first axis).
enum class JointType : std::uint8_t {
  fixed = 0,
  revolute = 1,
  universal = 2,
  spherical = 3,
  prismatic = 4,
};
/// Number of JointType values.
constexpr int kJointTypeKinds = 5;
/// Degrees of freedom of a joint type.
int degreesOfFreedom(JointType type);
/// Lower-case joint name ("universal").
const char* jointName(JointType type);

/// What a part is made of. Mass is the part's own (the encoding computes it from the density).
struct Material {
  double density = 1000;  ///< kg / m^3
  double friction = 1.0;  ///< Coulomb coefficient (the world combines it with the other body's)
  /// Bounciness; negative: the world's default (physics.restitution)
  double restitution = -1;
  friend bool operator==(const Material&, const Material&) = default;
};

/// One part and the joint that ties it to its parent (the tree joint).
struct PartPlan {
  int node = 0;         ///< the gene (genome node) it was made from
  int parent = -1;      ///< index of the parent part, -1 for the root
  int connection = -1;  ///< the gene (connection) that made it, -1 for the root
  int depth = 0;        ///< root = 0
  PartShape shape = PartShape::box;
  Vec3 size;        ///< full size, metres (see PartShape)
  double mass = 0;  ///< kg
  Material material;
  Transform pose;                      ///< pose at birth in the creature frame (root at the origin)
  JointType joint = JointType::fixed;  ///< to the parent
  Vec3 pivot_in_parent;                ///< joint point in the parent's frame
  Vec3 pivot_in_child;                 ///< joint point in this part's frame
  Quat parent_to_child;                ///< this part's frame relative to the parent's frame
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  ///< in this part's frame
  /// symmetric limit per degree of freedom, radians (prismatic: m); infinite: none (the rigid-body
  /// world only)
  Vec3 joint_limit;
  /// passive damping per degree of freedom, N m s / rad (prismatic: N s / m); negative: the
  /// world's (physics.joint_damping)
  Vec3 joint_damping{-1, -1, -1};
  double cross_section = 0;  ///< m^2, a face meeting at the joint (genome.strength_section);
                             ///< physics turns it into the joint's maximum torque
  bool reflected = false;    ///< made through a reflected connection
  /// the joint's maximum force (prismatic, N) or torque (N m); negative: physics.strength_per_area
  /// x cross_section
  double strength = -1;
  /// false: no collider of its own, only its mass and the inertia of its shape (a spring-mass
  /// organism's proxy body); it may still carry colliders (BodyPlan::colliders)
  bool solid = true;
  int contact_group = -1;  ///< see ColliderPlan::groups; -1: none
};

/// A collider a part carries besides its own shape, fixed in the part's frame (a spring-mass
/// organism's tube on one of its end nodes). It adds no mass; only the rigid-body world builds it.
struct ColliderPlan {
  int part = 0;
  PartShape shape = PartShape::capsule;
  Vec3 size;       ///< full size, m (see PartShape)
  Transform pose;  ///< in the part's frame
  /// Colliders and parts that share a group never touch each other (a spring-mass organism's
  /// node: its sphere and the tubes that meet there); -1: none.
  std::array<int, 2> groups{-1, -1};
};

/// A joint that closes a loop between two parts already joined through the tree (a ladder's
/// rung, a spring-mass organism's tube). Worlds that cannot build loops refuse such a plan.
struct LoopJoint {
  int part_a = 0, part_b = 0;
  JointType joint = JointType::fixed;
  Vec3 pivot_in_a, pivot_in_b;  ///< the joint point in each part's frame
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  ///< in part b's frame
  Vec3 joint_limit;
};

/// What a sensor reads; physics writes the values into the controller's sensor array each step.
enum class SensorKind : std::uint8_t {
  joint_angle,  ///< position of degree of freedom `axis` of the joint to the parent / its limit
  contact,      ///< 1 if the part touches anything, else 0
  photo,        ///< component `axis` of the unit direction to the light in the part's frame
  /// face `axis` of the part (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z): 1 if something touches it,
  /// else -1 (Sims; Chaumont et al.'s `sen`)
  contact_face,
};

struct SensorPlan {
  SensorKind kind = SensorKind::contact;
  int part = 0;
  int axis = 0;
  friend bool operator==(const SensorPlan&, const SensorPlan&) = default;
};

/// What an effector does with its command.
enum class EffectorKind : std::uint8_t {
  joint,    ///< drives degree of freedom `dof` of the joint between `part` and its parent
  release,  ///< lets go of held object `dof` once the command exceeds kReleaseCommand, for good
  /// drives degree of freedom `dof` of the joint between `part` and its parent to the position
  /// command x the joint's limit by the end of the step, with the joint's strength (a servo: a
  /// spring-mass organism's muscle)
  position,
};

/// The command above which a release effector lets go (Chaumont et al.'s ignition).
constexpr double kReleaseCommand = 0.5;

/// One controller output: a joint's degree of freedom (the command in [-1, 1] times the joint's
/// strength) or the release of a held object.
struct EffectorPlan {
  int part = 0;
  int dof = 0;
  EffectorKind kind = EffectorKind::joint;
  friend bool operator==(const EffectorPlan&, const EffectorPlan&) = default;
};

/// A block the creature holds at birth and may let go of (Chaumont et al.'s projectile): not a
/// part (no joint, sensors or neurons), fixed to part `part` until its release effector fires,
/// then a free body of the world.
struct HeldObject {
  int part = 0;  ///< the part that holds it
  PartShape shape = PartShape::box;
  Vec3 size{0.2, 0.2, 0.2};  ///< full size, m (see PartShape)
  double mass = 8;           ///< kg
  Material material;
  Transform pose;  ///< in the holding part's frame
};

/// The developed body.
struct BodyPlan {
  std::vector<PartPlan> parts;  ///< parents always precede children
  std::vector<LoopJoint> loops;
  std::vector<SensorPlan> sensors;
  std::vector<EffectorPlan> effectors;
  std::vector<HeldObject> held;         ///< objects held at birth (a catapult's projectile)
  std::vector<ColliderPlan> colliders;  ///< colliders parts carry besides their own shapes
  bool truncated = false;               ///< development stopped at its part limit

  /// Joints of the tree plus loop joints.
  int jointCount() const;
  int degreesOfFreedom() const;
  double totalMass() const;
  double totalVolume() const;
};

/// The damping of degree of freedom `dof` of the part's joint: its own, else `world_damping`.
inline double jointDamping(const PartPlan& part, int dof, double world_damping) {
  return part.joint_damping[dof] < 0 ? world_damping : part.joint_damping[dof];
}

/// Volume of a part of `shape` and full size `size`, m^3.
double shapeVolume(PartShape shape, Vec3 size);
/// Surface of a part of `shape` and `size`, m^2.
double shapeSurface(PartShape shape, Vec3 size);
/// How far a part of `shape` and `size` turned by `rotation` reaches from its centre along the
/// unit world direction `direction`, m (a box: its farthest corner).
double shapeReach(PartShape shape, Vec3 size, Quat rotation, Vec3 direction);
/// A point on a part's surface and the outward unit normal there, in the part's frame.
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;
};
/// Where a part of `shape` and `size` is met in `direction` from its centre. A box: the face of
/// the direction's largest component (ties to the lower axis), at the point its other two give in
/// units of the half-size (Sims' attachment); the other shapes: where the ray from the centre
/// leaves them (Minemonics' joint anchor). A zero direction is +x.
SurfacePoint surfacePoint(PartShape shape, Vec3 size, Vec3 direction);
/// Area of the section of a part of `shape` and `size` across its axis `axis` through its centre,
/// m^2 (a box: the face perpendicular to the axis).
double sectionArea(PartShape shape, Vec3 size, int axis);
/// The lowest world z of a part at `pose`.
double lowestZ(const PartPlan& part, const Transform& pose);

/// Largest horizontal extent of the body at birth, m (for distances in body lengths).
double bodyLength(const BodyPlan& plan);

}  // namespace cambrian
