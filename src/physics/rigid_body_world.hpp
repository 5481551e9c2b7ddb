// cambrian: the Bullet constrained rigid-body world — every part its own btRigidBody, every
// joint (the tree's and the closed loops') a btGeneric6DofSpring2Constraint whose free axes are
// the joint's degrees of freedom, the way Minemonics builds its creatures; the environment's
// ground and free objects as in the Featherstone world (bullet_scene.hpp).
#pragma once

#include "physics/viscous_drag.hpp"
#include "physics/world.hpp"

#include <array>
#include <memory>

class btCollisionShape;
class btGeneric6DofSpring2Constraint;

namespace cambrian {

struct RigidBodyObjects;  // the Bullet objects, private to rigid_body_world.cpp

/// See the file comment. Built from the same BodyPlan as the Featherstone world, it gives the
/// same parts (masses, inertias, poses at birth), joint axes and limits; the joints are solved
/// as constraints (soft, iterative) rather than as coordinates, so closed loops are allowed.
/// Multi-degree-of-freedom joints are Euler angles in the order of the plan's axes (x, y, z of
/// the constraint frame), which is the Featherstone world's chain of revolute joints; the middle
/// angle of a spherical joint is limited to less than 90 degrees either way by construction.
class RigidBodyWorld : public World {
 public:
  /// The registered name.
  static constexpr const char* kName = "rigid_bodies";

  RigidBodyWorld(const BodyPlan& plan, const Environment& environment,
                 const PhysicsSettings& physics, double birth_height);
  ~RigidBodyWorld() override;
  RigidBodyWorld(const RigidBodyWorld&) = delete;
  RigidBodyWorld& operator=(const RigidBodyWorld&) = delete;

  EvalStatus birthStatus() const override { return birth_status_; }
  const std::string& birthMessage() const override { return birth_message_; }
  void step(std::span<const double> commands) override;
  Vec3 partPosition(int part) const override;
  Transform partPose(int part) const override;
  double jointPosition(int part, int dof) const override;
  JointSpeed fastestJoint() const override;
  Vec3 jointAxis(int part, int dof) const override;
  double partMass(int part) const override;
  Vec3 partInertia(int part) const override;
  const std::vector<std::uint8_t>& contacts() override;
  const std::vector<std::uint8_t>& groundContacts() override;
  const std::vector<std::pair<int, int>>& partContacts() override;
  double largestJointError() const override;
  Vec3 directionInPart(int part, Vec3 point) const override;
  double lowestPoint() const override;
  void setGroundFriction(double friction) override;
  int brokenJoint() const override;
  Transform objectPose(int object) const override;
  Transform heldPose(int held) const override;
  bool released(int held) const override { return released_.at(static_cast<std::size_t>(held)); }
  double mechanicalEnergy() const override;
  double effectorWorkBound() const override { return work_bound_; }
  /// Steps the direct solve (physics.constraint_solver = dantzig) left to sequential impulses.
  int directSolveFallbacks() const;

 private:
  void build(double birth_height);
  btCollisionShape* partShape(int part);
  void addJoints();
  bool drivesJoint(const EffectorPlan& effector) const;
  void soften(btGeneric6DofSpring2Constraint& joint) const;  // the soft rows' ERP on its axes
  void addHeldObjects();
  void release(std::span<const double> commands);
  void applyTorques(std::span<const double> commands);
  double jointSpeed(int part, int dof) const;
  void refuse(EvalStatus status, std::string message);

  const BodyPlan& plan_;
  const Environment& environment_;
  PhysicsSettings physics_;
  std::unique_ptr<RigidBodyObjects> bullet_;
  EvalStatus birth_status_ = EvalStatus::ok;
  std::string birth_message_;

  std::vector<double> max_torque_;  // per part: its joint's torque limit
  std::vector<std::uint8_t> contact_;
  std::vector<std::uint8_t> ground_contact_;
  std::vector<std::pair<int, int>> part_contacts_;  // partContacts()
  double soft_erp_ = 0;                             // soft rows' ERP per substep (0: rigid rows)
  int substeps_left_ = 1;               // the substeps left in this step, this one included
  std::vector<DragCoefficients> drag_;  // per part, then per object and held object: in a fluid
  std::size_t held_first_ = 0;          // the first held object's index among the free bodies
  std::vector<bool> released_;          // per held object: let go
  double work_bound_ = 0;               // effectorWorkBound()
  double gravity_ = 0;                  // m/s^2 down
};

}  // namespace cambrian
