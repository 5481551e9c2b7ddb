// cambrian: what the Bullet worlds share around a creature — conversions, part shapes, the
// ground (plane and terrain), free rigid bodies (the environment's objects and held objects),
// the contact readings and the birth-overlap check. Internal to the physics module.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/environment.hpp"
#include "cambrian/math.hpp"

#include "physics/physics_settings.hpp"
#include "physics/viscous_drag.hpp"

#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <btBulletDynamicsCommon.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

inline btVector3 toBt(Vec3 v) {
  return btVector3(v.x, v.y, v.z);
}
inline Vec3 fromBt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}
inline btQuaternion toBt(Quat q) {
  return btQuaternion(q.x, q.y, q.z, q.w);
}
inline Quat fromBt(const btQuaternion& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

/// The user index of the ground; parts carry their own index (>= 0), free object k objectIndex(k).
constexpr int kGroundIndex = -1;
inline int objectIndex(int k) {
  return -2 - k;
}

/// The collision shape of a part or object (capsules and cylinders along their x axis).
std::unique_ptr<btCollisionShape> shapeOf(PartShape shape, Vec3 size);
/// The most torque (prismatic: force) the joint between `part` and its parent exerts, N m: its
/// own strength, else physics.strength_per_area x its cross-section.
inline double jointStrength(const PartPlan& part, const PhysicsSettings& physics) {
  return part.strength >= 0 ? part.strength : physics.strength_per_area * part.cross_section;
}
/// Principal inertia of a part about its centre.
btVector3 inertiaOf(PartShape shape, Vec3 size, double mass);
/// How far a part reaches below its centre along world z, given its world basis.
double reachDown(const PartPlan& part, const btMatrix3x3& basis);
/// Collision memory pools sized for one creature (at most a few dozen parts): Bullet's default
/// pools (4,096 manifolds and algorithms) cost more to set up than a birth check itself; a pool
/// that runs out falls back to the heap, which changes no result.
btDefaultCollisionConstructionInfo creaturePools();
/// The fixed-step solver settings of physics.* into Bullet's solver info.
void setSolverInfo(btContactSolverInfo& solver, const PhysicsSettings& physics);
/// At least the highest ground z under the parts' bounding boxes at their plan poses (hills).
double highestGroundUnder(const Environment& environment, const std::vector<PartPlan>& parts);
/// Sets Bullet's friction anchors on `object`, of `shape`, when physics.friction_anchors and it
/// is a box. Bullet anchors a contact when either body asks, so the ground does not: a box's
/// contacts with the ground are anchored, a rolling capsule's or sphere's are not (an anchor
/// holds the contact where it was on a surface that rolls on, and pumps energy into the roll).
void anchorFriction(btCollisionObject& object, PartShape shape, const PhysicsSettings& physics);

/// Where the root part is born: at its plan position, raised so the body's lowest point is
/// `birth_height` m above z = 0 (on hills, above the highest ground under the body).
Vec3 birthPosition(const BodyPlan& plan, const Environment& environment, double birth_height);
/// The fluid's drag on every part, then every environment object, then every held object (Sims'
/// water); empty without a fluid.
std::vector<DragCoefficients> fluidDrag(const BodyPlan& plan, const Environment& environment);
/// What is wrong with held object `h` of `plan` (a part it cannot name, no mass); empty if nothing.
std::string heldObjectProblem(const BodyPlan& plan, std::size_t h);
/// The pairs of parts (user indices >= 0) touching each other in the dispatcher's manifolds, each
/// (lower, higher), sorted, without repeats.
void touchingPartPairs(btDispatcher& dispatcher, std::vector<std::pair<int, int>>& pairs);
/// What of `plan` only the rigid-body world builds (carried colliders, parts without a collider,
/// position effectors), in words; empty when nothing.
std::string rigidBodyOnly(const BodyPlan& plan);
/// The world pose of a body.
Transform poseOf(const btCollisionObject& body);
/// The unit direction from a body towards the world point `point`, in the body's frame.
Vec3 directionIn(const btCollisionObject& body, Vec3 point);
/// Height of the lowest point of parts `plans` whose bodies are `bodies` (same order), m.
template <class Bodies>
double lowestPointOf(const std::vector<PartPlan>& plans, const Bodies& bodies) {
  double lowest = 0;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    // the centre minus how far the part reaches down
    const btTransform& transform = bodies[i]->getWorldTransform();
    const double z = transform.getOrigin().z() - reachDown(plans[i], transform.getBasis());
    if (i == 0 || z < lowest)
      lowest = z;
  }
  return lowest;
}

/// The environment's ground in a Bullet world: the terrain of a heightfield with a plane under
/// its lowest point, or the plane alone, or nothing. Removes itself from the world it was added
/// to when destroyed.
struct BulletGround {
  btStaticPlaneShape plane_shape{btVector3(0, 0, 1), 0};
  btCollisionObject plane;
  std::unique_ptr<btHeightfieldTerrainShape> terrain_shape;
  btCollisionObject terrain;
  btCollisionWorld* world = nullptr;  // where it was added
  bool has_plane = false, has_terrain = false;

  /// Adds the environment's ground (terrain first, then the plane) to `into`.
  void add(btCollisionWorld& into, const Environment& environment, const PhysicsSettings& physics);
  /// The ground's friction coefficient from now on; its contact points are made anew at the next
  /// step (a point keeps the friction it was made with).
  void setFriction(double friction);
  ~BulletGround();
};

/// Rigid bodies that are not parts — the environment's objects, then what the creature holds —
/// with their shapes and motion states; the owner removes them from its world first.
struct FreeBodies {
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  /// A body of `shape` and full `size` (mass 0: fixed) at `start`, user index objectIndex(its
  /// index); not yet in a world.
  btRigidBody& add(PartShape shape, Vec3 size, double mass, const Material& material,
                   const btTransform& start, const PhysicsSettings& physics);
  /// Adds every object of `environment` to `world` (on hills as high above the ground under it as
  /// above z = 0).
  void addObjects(btDynamicsWorld& world, const Environment& environment,
                  const PhysicsSettings& physics);
};

/// Per part, the faces touched (World::contacts): every touching point of every manifold marks,
/// on each part it joins, the face that looks most nearly towards the other body.
void markContactFaces(btDispatcher& dispatcher, std::vector<std::uint8_t>& faces);
/// Per part, 1 when it touches the ground (World::groundContacts).
void markGroundContacts(btDispatcher& dispatcher, std::vector<std::uint8_t>& touching);
/// Runs collision detection on the birth pose and describes the first overlap deeper than
/// `tolerance` between two parts or a part and a held object (held objects are the user indices
/// objectIndex(held_first) .. objectIndex(held_first + held_count - 1)); empty when none.
std::string birthOverlap(btCollisionWorld& world, int held_first, int held_count, double tolerance);
/// Drops the part-part pairs (and their contact manifolds) the broadphase holds.
void dropPartPairs(btCollisionWorld& world);
/// Applies the fluid's drag over a step of `substep` s to a free rigid body (none when fixed).
void applyFluidDrag(btRigidBody& body, const DragCoefficients& drag, double substep);
/// A rigid body's kinetic energy plus m g z at its centre, J.
double rigidBodyEnergy(const btRigidBody& body, double gravity);

}  // namespace cambrian
