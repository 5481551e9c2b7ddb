// cambrian: the Bullet Featherstone world — a creature as one btMultiBody (the root part the
// floating base) on the environment's ground (or in its water), with the environment's free
// objects as rigid bodies. Multi-degree-of-freedom joints are chains of revolute joints through
// light virtual links. Builds tree-shaped bodies only: a plan with closed-loop joints is refused
// (invalid_body).
#pragma once

#include "physics/viscous_drag.hpp"
#include "physics/world.hpp"

#include <array>
#include <memory>

class btCollisionObject;
class btRigidBody;
class btTransform;

namespace cambrian {

struct FeatherstoneObjects;  // the Bullet objects, private to featherstone_world.cpp

/// See the file comment. The creature is born with its lowest point `birth_height` m above the
/// ground; a body overlapping itself at birth has birthStatus() self_penetration. Unless
/// physics.self_collision, parts touch only the ground and the objects afterwards.
class FeatherstoneWorld : public World {
 public:
  /// The registered name.
  static constexpr const char* kName = "featherstone";

  FeatherstoneWorld(const BodyPlan& plan, const Environment& environment,
                    const PhysicsSettings& physics, double birth_height);
  ~FeatherstoneWorld() override;
  FeatherstoneWorld(const FeatherstoneWorld&) = delete;
  FeatherstoneWorld& operator=(const FeatherstoneWorld&) = delete;

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
  double largestJointError() const override { return 0; }
  Vec3 directionInPart(int part, Vec3 point) const override;
  double lowestPoint() const override;
  void setGroundFriction(double friction) override;
  Transform objectPose(int object) const override;
  Transform heldPose(int held) const override;
  bool released(int held) const override { return released_.at(static_cast<std::size_t>(held)); }
  double mechanicalEnergy() const override;
  double effectorWorkBound() const override { return work_bound_; }
  int brokenJoint() const override { return broken_joint_; }

 private:
  void build(double birth_height);
  void addHeldObjects();
  void release(std::span<const double> commands);
  void checkBirthPenetration();
  void stopSelfContacts();
  void applyTorques(std::span<const double> commands, double substep);
  void applyDrag(double substep);
  void correctMomentum(double substep);
  void addEffectorWorkBound(std::span<const double> commands, double substep);
  double jointLoad(int part, std::span<const double> commands, double substep) const;
  void findBrokenJoint(std::span<const double> commands, double substep);
  void refuse(EvalStatus status, std::string message);

  const BodyPlan& plan_;
  const Environment& environment_;
  PhysicsSettings physics_;
  std::unique_ptr<FeatherstoneObjects> bullet_;
  EvalStatus birth_status_ = EvalStatus::ok;
  std::string birth_message_;

  // per part: Bullet link of each degree of freedom (-1 none) and the joint's torque limit
  std::vector<std::array<int, 3>> dof_link_;
  std::vector<double> max_torque_;
  std::vector<std::uint8_t> contact_;
  std::vector<std::uint8_t> ground_contact_;        // groundContacts()
  std::vector<std::pair<int, int>> part_contacts_;  // partContacts()
  std::vector<int> part_link_;          // per part: the Bullet link carrying it (-1: the base)
  std::vector<DragCoefficients> drag_;  // per part, then per object and held object: in a fluid
  std::size_t held_first_ = 0;          // the first held object's index among the rigid bodies
  std::vector<bool> released_;          // per held object: let go
  std::vector<int> damped_links_;       // every revolute or prismatic link, real or virtual
  std::vector<double> link_damping_;    // and its joint damping (PartPlan::joint_damping)
  std::vector<int> virtual_link_part_;  // per Bullet link: the part whose pivot holds it (virtual
                                        // links of multi-DoF joints), or -1 (the part's own link)
  double work_bound_ = 0;               // effectorWorkBound()
  std::vector<int> link_effector_;      // per Bullet link: the effector driving it, or -1
  int broken_joint_ = -1;               // brokenJoint()
  double gravity_ = 0;                  // m/s^2 down: the environment's, else physics.gravity
  bool correct_momentum_ = false;       // physics.momentum_correction, where it applies
  double total_mass_ = 0;               // of every body, virtual links included
  Vec3 centre_;                         // where the momentum has carried the centre of mass
  Vec3 momentum_, angular_momentum_;    // what the outside forces gave (about the centre)
  Vec3 drag_force_, drag_torque_;       // this Bullet step's drag: sum, moment about the centre
};

}  // namespace cambrian
