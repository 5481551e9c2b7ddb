// cambrian: the Bullet Featherstone multibody world.
#include "physics/featherstone_world.hpp"

#include "physics/bullet_scene.hpp"

#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cambrian {

namespace {

// a part's collider: collides with the ground and, while `self_contacts` is set, with the
// creature's other parts except its parent and children (the joint neighbours), also across
// the virtual links of multi-degree-of-freedom joints. Its user index is its part, its second
// user index its parent part (read without a dynamic_cast: this test runs for every pair)
class PartCollider : public btMultiBodyLinkCollider {
 public:
  PartCollider(btMultiBody* body, int link, int part, int parent_part, const bool* self_contacts)
      : btMultiBodyLinkCollider(body, link), self_contacts_(self_contacts) {
    setUserIndex(part);
    setUserIndex2(parent_part);
  }

  bool checkCollideWithOverride(const btCollisionObject* other_object) const override {
    const btMultiBodyLinkCollider* other = btMultiBodyLinkCollider::upcast(other_object);
    if (!other || other->m_multiBody != m_multiBody)
      return true;
    if (!*self_contacts_)
      return false;
    return other->getUserIndex() != getUserIndex2() && other->getUserIndex2() != getUserIndex();
  }

 private:
  const bool* self_contacts_;
};

// the body's velocity response to a unit impulse along each joint coordinate, made at most once
// per Bullet step and shared by the damping, the motors and the limits: it depends only on the
// articulated inertia, which the forward dynamics (solveExternalForces) makes before the solve
// and nothing changes until the next step. The same call on the same inputs: the same bits.
class JointResponses {
 public:
  explicit JointResponses(btMultiBody& body) : body_(body) {}
  // forget them: the forward dynamics has moved the body (each Bullet step)
  void clear() { std::fill(made_.begin(), made_.end(), 0); }
  // the response to a unit impulse along velocity coordinate `axis` (6 + the dof offset)
  const double* along(int axis) {
    const int dofs = body_.getNumDofs() + 6;
    if (made_.size() != static_cast<std::size_t>(dofs)) {
      made_.assign(dofs, 0);
      responses_.assign(static_cast<std::size_t>(dofs) * dofs, 0.0);
      unit_.assign(dofs, 0.0);
    }
    double* response = &responses_[static_cast<std::size_t>(axis) * dofs];
    if (!made_[axis]) {
      unit_[axis] = 1;
      body_.calcAccelerationDeltasMultiDof(unit_.data(), response, scratch_r_, scratch_v_);
      unit_[axis] = 0;
      made_[axis] = 1;
    }
    return response;
  }

 private:
  btMultiBody& body_;
  std::vector<char> made_;  // per coordinate: its response is made this step
  std::vector<double> responses_, unit_;
  btAlignedObjectArray<double> scratch_r_;
  btAlignedObjectArray<btVector3> scratch_v_;
};

// a solver row of one joint coordinate, filled on the body's side only (Bullet's joint
// constraints fill the same body a second time as the other side, with a zero Jacobian: that
// changes no number and costs a solve of the whole body): the Jacobian `direction` (+1 or -1)
// along `axis`, the response the shared one times the direction (negation is exact), the
// inverse inertia, and the joint's speed along the row. Returns the speed (Bullet's rel_vel).
double fillJointRow(btMultiBodySolverConstraint& row, btMultiBodyJacobianData& data,
                    btMultiBodyConstraint* constraint, int dof_index, btMultiBody* body, int link,
                    double direction, JointResponses& responses) {
  const int dofs = body->getNumDofs() + 6;
  const int axis = 6 + body->getLink(link).m_dofOffset;
  row.m_multiBodyA = body;
  row.m_multiBodyB = nullptr;
  row.m_linkA = link;
  row.m_linkB = -1;
  row.m_solverBodyIdA = -1;
  row.m_solverBodyIdB = -1;
  row.m_orgConstraint = constraint;
  row.m_orgDofIndex = dof_index;
  row.m_originalContactPoint = nullptr;

  // the body's slot of velocity changes, shared by all its rows in this solve
  row.m_deltaVelAindex = body->getCompanionId();
  if (row.m_deltaVelAindex < 0) {
    row.m_deltaVelAindex = data.m_deltaVelocities.size();
    body->setCompanionId(row.m_deltaVelAindex);
    data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + dofs);
  }

  // Jacobian and response
  row.m_jacAindex = data.m_jacobians.size();
  data.m_jacobians.resize(row.m_jacAindex + dofs);
  data.m_deltaVelocitiesUnitImpulse.resize(row.m_jacAindex + dofs);
  double* jacobian = &data.m_jacobians[row.m_jacAindex];
  std::fill(jacobian, jacobian + dofs, 0.0);
  jacobian[axis] = direction;
  const double* unit = responses.along(axis);
  double* response = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
  for (int d = 0; d < dofs; ++d)
    response[d] = direction > 0 ? unit[d] : -unit[d];

  // a row Bullet would disable stays inert
  const double inverse_inertia = unit[axis];
  row.m_jacDiagABInv = inverse_inertia > SIMD_EPSILON ? 1.0 / inverse_inertia : 0.0;
  row.m_friction = 0;
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  row.m_cfm = 0;
  const double speed = body->getVelocityVector()[axis];
  return direction > 0 ? speed : -speed;
}

// the island Bullet solves a joint's motor and limit rows in: that of the collider of the part
// the joint moves (Bullet's own choice, the colliders of the link and of its parent, is none for
// the middle link of a spherical joint, whose rows are then never solved); null: Bullet's choice
int islandOf(const btCollisionObject* part_collider, int bullet_island) {
  return part_collider ? part_collider->getIslandTag() : bullet_island;
}

// a saturated motor on one joint degree of freedom: a solver row towards the target speed,
// bounded by the torque budget, none while the budget is zero (a row bounded to [0, 0] changes
// no velocity, and setting it up costs a solve of the whole body). Filled on the body's side
// only, with Bullet's arithmetic (btMultiBodyJointMotor and
// btMultiBodyConstraint::fillMultiBodyConstraint): the same bits as Bullet's motor.
class BudgetMotor : public btMultiBodyJointMotor {
 public:
  // (finalized here: the solver writes each row's impulse back into the motor's storage)
  BudgetMotor(btMultiBody* body, int link, JointResponses& responses,
              const btCollisionObject* part_collider)
      : btMultiBodyJointMotor(body, link, 0.0, 0.0),
        responses_(responses),
        part_collider_(part_collider) {
    btMultiBodyJointMotor::finalizeMultiDof();
  }
  int getIslandIdA() const override {
    return islandOf(part_collider_, btMultiBodyJointMotor::getIslandIdA());
  }
  int getIslandIdB() const override {
    return islandOf(part_collider_, btMultiBodyJointMotor::getIslandIdB());
  }
  // the target speed and torque budget for the next Bullet step
  void setCommand(double target_speed, double max_impulse) {
    target_speed_ = target_speed;
    setMaxAppliedImpulse(max_impulse);
  }
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;

 private:
  JointResponses& responses_;
  const btCollisionObject* part_collider_;  // islandOf
  double target_speed_ = 0;
};

void BudgetMotor::createConstraintRows(btMultiBodyConstraintArray& rows,
                                       btMultiBodyJacobianData& data, const btContactSolverInfo&) {
  internalSetAppliedImpulse(0, 0);  // read by the joint loads: none without a row
  const double bound = getMaxAppliedImpulse();
  if (bound <= 0)
    return;
  btMultiBody* body = getMultiBodyA();
  const int link = getLinkA();
  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  const double speed = fillJointRow(row, data, this, 0, body, link, 1.0, responses_);
  // Bullet's motor: its target, then the velocity error (kp = 0, kd = 1)
  const double desired = speed + (target_speed_ - speed);
  row.m_rhs = (desired - speed) * row.m_jacDiagABInv;
  row.m_rhsPenetration = 0;
  row.m_lowerLimit = -bound;
  row.m_upperLimit = bound;

  // the joint torque or force the row applies, for Bullet's constraint-force bookkeeping
  const btMultibodyLink& joint = body->getLink(link);
  const btQuaternion& rotation = joint.m_cachedWorldTransform.getRotation();
  const bool prismatic = joint.m_jointType == btMultibodyLink::ePrismatic;
  row.m_contactNormal1 =
      prismatic ? quatRotate(rotation, joint.m_axes[0].m_bottomVec) : btVector3(0, 0, 0);
  row.m_contactNormal2 = -row.m_contactNormal1;
  row.m_relpos1CrossNormal =
      prismatic ? btVector3(0, 0, 0) : quatRotate(rotation, joint.m_axes[0].m_topVec);
  row.m_relpos2CrossNormal = -row.m_relpos1CrossNormal;
}

// the lower and upper limit of one joint coordinate: a row for each bound the joint is at or
// past, filled on the body's side only, with Bullet's arithmetic
// (btMultiBodyJointLimitConstraint::createConstraintRows): the same bits as Bullet's limit
class JointLimit : public btMultiBodyJointLimitConstraint {
 public:
  JointLimit(btMultiBody* body, int link, double lower, double upper, JointResponses& responses,
             const btCollisionObject* part_collider)
      : btMultiBodyJointLimitConstraint(body, link, lower, upper),
        responses_(responses),
        part_collider_(part_collider) {
    // (the storage of the bounds' positions and impulses)
    btMultiBodyJointLimitConstraint::finalizeMultiDof();
  }
  int getIslandIdA() const override {
    return islandOf(part_collider_, btMultiBodyJointLimitConstraint::getIslandIdA());
  }
  int getIslandIdB() const override {
    return islandOf(part_collider_, btMultiBodyJointLimitConstraint::getIslandIdB());
  }
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;

 private:
  JointResponses& responses_;
  const btCollisionObject* part_collider_;  // islandOf
};

void JointLimit::createConstraintRows(btMultiBodyConstraintArray& rows,
                                      btMultiBodyJacobianData& data,
                                      const btContactSolverInfo& info) {
  btMultiBody* body = m_bodyA;
  const int link = m_linkA;
  const btMultibodyLink& joint = body->getLink(link);
  internalSetAppliedImpulse(0, 0);  // read by the joint loads: none for a bound not reached
  internalSetAppliedImpulse(1, 0);
  setPosition(0, body->getJointPos(link) - m_lowerBound);
  setPosition(1, m_upperBound - body->getJointPos(link));
  for (int bound = 0; bound < 2; ++bound) {
    const double penetration = getPosition(bound);
    if (penetration > 0)
      continue;
    const double direction = bound ? -1 : 1;
    btMultiBodySolverConstraint& row = rows.expandNonInitializing();
    const double speed = fillJointRow(row, data, this, bound, body, link, direction, responses_);
    row.m_lowerLimit = 0;
    row.m_upperLimit = m_maxAppliedImpulse;

    const btVector3 axis = direction * quatRotate(joint.m_cachedWorldTransform.getRotation(),
                                                  joint.m_jointType == btMultibodyLink::ePrismatic
                                                      ? joint.m_axes[0].m_bottomVec
                                                      : joint.m_axes[0].m_topVec);
    if (joint.m_jointType == btMultibodyLink::ePrismatic) {
      row.m_contactNormal1 = axis;
      row.m_contactNormal2 = -axis;
      row.m_relpos1CrossNormal.setZero();
      row.m_relpos2CrossNormal.setZero();
    } else {
      row.m_contactNormal1.setZero();
      row.m_contactNormal2.setZero();
      row.m_relpos1CrossNormal = axis;
      row.m_relpos2CrossNormal = -axis;
    }

    // Bullet's limit: the velocity error, and the position error with erp (erp2 only when
    // split impulse is on and the bound is passed by more than its threshold)
    const bool combined =
        !info.m_splitImpulse || penetration > info.m_splitImpulsePenetrationThreshold;
    const double erp = combined ? info.m_erp : info.m_erp2;
    const double positional_error = -penetration * erp / info.m_timeStep;
    const double velocity_error = -speed;
    const double penetration_impulse = positional_error * row.m_jacDiagABInv;
    const double velocity_impulse = velocity_error * row.m_jacDiagABInv;
    if (combined) {
      row.m_rhs = penetration_impulse + velocity_impulse;
      row.m_rhsPenetration = 0;
    } else {
      row.m_rhs = velocity_impulse;
      row.m_rhsPenetration = penetration_impulse;
    }
  }
}

// the joint damping of a body, solved implicitly (backward Euler) for all its jointed degrees of
// freedom at once: after gravity and the joint torques, before the contacts, limits and motors,
// the joint speeds become v' with M (v' - v) = -damping x step x v', so the damping only takes
// energy out, however light a limb (an explicit torque -damping x v reverses a light limb's
// speed each step once damping x step exceeds its inertia about the joint, and pumps energy).
// With R the block of the inverse joint-space inertia over the damped coordinates (one response
// of the body per coordinate) and D their dampings, the impulses p solve
// ((D x step)^-1 + R) p = -v.
class ImplicitJointDamping {
 public:
  // `damping[k]` is link `links[k]`'s; links without damping are left out
  ImplicitJointDamping(btMultiBody& body, const std::vector<int>& links,
                       const std::vector<double>& damping, JointResponses& responses)
      : body_(body), responses_(responses) {
    for (std::size_t k = 0; k < links.size(); ++k) {
      if (damping[k] > 0) {
        axes_.push_back(6 + body.getLink(links[k]).m_dofOffset);
        damping_.push_back(damping[k]);
      }
    }
  }

  // (built only for a body with jointed links and damping > 0; the vectors keep their capacity,
  // so after the first step nothing is allocated)
  void apply(double step) {
    const int n = static_cast<int>(axes_.size());
    const int dofs = body_.getNumDofs() + 6;
    system_.assign(static_cast<std::size_t>(n) * n, 0.0);
    impulse_.assign(n, 0.0);
    response_.resize(n);
    for (int j = 0; j < n; ++j)
      response_[j] = responses_.along(axes_[j]);
    // the system, symmetric positive definite; its Cholesky factor in place (lower triangle)
    for (int i = 0; i < n; ++i) {
      const double compliance = 1.0 / (damping_[i] * step);
      for (int j = 0; j <= i; ++j)
        system_[i * n + j] =
            0.5 * (response_[j][axes_[i]] + response_[i][axes_[j]]) + (i == j ? compliance : 0.0);
    }
    for (int j = 0; j < n; ++j) {
      double diagonal = system_[j * n + j];
      for (int k = 0; k < j; ++k)
        diagonal -= system_[j * n + k] * system_[j * n + k];
      if (!(diagonal > 0))
        return;  // not positive definite (a degenerate body): leave the speeds alone
      const double root = std::sqrt(diagonal);
      system_[j * n + j] = root;
      for (int i = j + 1; i < n; ++i) {
        double value = system_[i * n + j];
        for (int k = 0; k < j; ++k)
          value -= system_[i * n + k] * system_[j * n + k];
        system_[i * n + j] = value / root;
      }
    }
    // p = -(L L^T)^-1 v, then v += sum_j p_j response_j
    const double* speed = body_.getVelocityVector();
    for (int i = 0; i < n; ++i) {
      double value = -speed[axes_[i]];
      for (int k = 0; k < i; ++k)
        value -= system_[i * n + k] * impulse_[k];
      impulse_[i] = value / system_[i * n + i];
    }
    for (int i = n - 1; i >= 0; --i) {
      double value = impulse_[i];
      for (int k = i + 1; k < n; ++k)
        value -= system_[k * n + i] * impulse_[k];
      impulse_[i] = value / system_[i * n + i];
    }
    change_.assign(dofs, 0.0);
    for (int j = 0; j < n; ++j)
      for (int d = 0; d < dofs; ++d)
        change_[d] += impulse_[j] * response_[j][d];
    body_.applyDeltaVeeMultiDof(change_.data(), 1);
  }

 private:
  btMultiBody& body_;
  JointResponses& responses_;
  std::vector<int> axes_;        // index of each damped coordinate in the body's velocity vector
  std::vector<double> damping_;  // and its damping, N m s / rad
  std::vector<const double*> response_;  // this step's response along each of them
  std::vector<double> system_, impulse_, change_;
};

// Bullet's multibody world with the implicit joint damping between the external forces and the
// constraint solve, and the joint responses made afresh after the forward dynamics
// (btMultiBodyDynamicsWorld::solveConstraints otherwise)
class DampedWorld : public btMultiBodyDynamicsWorld {
 public:
  using btMultiBodyDynamicsWorld::btMultiBodyDynamicsWorld;
  void setDamping(ImplicitJointDamping* damping) { damping_ = damping; }
  void setResponses(JointResponses* responses) { responses_ = responses; }
  void solveConstraints(btContactSolverInfo& info) override {
    solveExternalForces(info);
    if (responses_)
      responses_->clear();
    if (damping_)
      damping_->apply(info.m_timeStep);
    buildIslands();
    solveInternalConstraints(info);
  }

 private:
  ImplicitJointDamping* damping_ = nullptr;
  JointResponses* responses_ = nullptr;
};

}  // namespace

// the Bullet objects of one world, destroyed in reverse order of creation
struct FeatherstoneObjects {
  btDefaultCollisionConfiguration configuration{creaturePools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  DampedWorld world{&dispatcher, &broadphase, &solver, &configuration};
  BulletGround ground;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<PartCollider>> colliders;  // one per part, BodyPlan order
  std::unique_ptr<JointResponses> responses;             // shared by damping, limits and motors
  std::vector<std::unique_ptr<JointLimit>> limits;
  std::vector<std::unique_ptr<BudgetMotor>> motors;  // one per effector (or null)
  std::vector<JointLimit*> link_limits;              // per Bullet link: its limit (or null)
  std::unique_ptr<ImplicitJointDamping> damping;     // with physics.implicit_damping
  std::unique_ptr<btMultiBody> body;
  FreeBodies objects;  // Environment::objects, then BodyPlan::held
  std::vector<std::unique_ptr<btMultiBodyFixedConstraint>> holds;  // per held object, null: let go
  bool self_contacts = true;  // parts touch each other (always at the birth check)
  mutable btAlignedObjectArray<btVector3> omega, velocity;  // linkVelocities()
  // correctMomentum's scratch: each body's mass, centre, velocity, spin and world inertia
  struct BodyState {
    double mass = 0;
    btVector3 centre, velocity, spin;
    btMatrix3x3 inertia;
  };
  std::vector<BodyState> states;
  btAlignedObjectArray<btQuaternion> world_to_local;  // collider updates' scratch
  btAlignedObjectArray<btVector3> local_origin;

  ~FeatherstoneObjects() {
    for (auto& hold : holds)
      if (hold)
        world.removeMultiBodyConstraint(hold.get());
    for (auto& object : objects.bodies)
      world.removeRigidBody(object.get());
    world.setDamping(nullptr);
    world.setResponses(nullptr);
    for (auto& motor : motors)
      if (motor)
        world.removeMultiBodyConstraint(motor.get());
    for (auto& limit : limits)
      world.removeMultiBodyConstraint(limit.get());
    for (auto& collider : colliders)
      world.removeCollisionObject(collider.get());
    if (body)
      world.removeMultiBody(body.get());
  }
};

// every body's angular and linear velocity in its own frame into omega and velocity (index 0 the
// base, k + 1 link k; Bullet's link frames sit at the bodies' centres)
void linkVelocities(const FeatherstoneObjects& b) {
  const int links = b.body->getNumLinks();
  b.omega.resize(links + 1);
  b.velocity.resize(links + 1);
  b.body->compTreeLinkVelocities(&b.omega[0], &b.velocity[0]);
}

FeatherstoneWorld::FeatherstoneWorld(const BodyPlan& plan, const Environment& environment,
                                     const PhysicsSettings& physics, double birth_height)
    : plan_(plan), environment_(environment), physics_(physics) {
  build(birth_height);
  if (birth_status_ == EvalStatus::ok)
    checkBirthPenetration();
  if (bullet_->body && !physics_.self_collision)
    stopSelfContacts();
}

FeatherstoneWorld::~FeatherstoneWorld() = default;

void FeatherstoneWorld::refuse(EvalStatus status, std::string message) {
  if (birth_status_ != EvalStatus::ok)
    return;
  birth_status_ = status;
  birth_message_ = std::move(message);
}

void FeatherstoneWorld::stopSelfContacts() {
  bullet_->self_contacts = false;
  dropPartPairs(bullet_->world);  // the pairs (and contact manifolds) the birth check found
}

void FeatherstoneWorld::build(double birth_height) {
  bullet_ = std::make_unique<FeatherstoneObjects>();
  FeatherstoneObjects& b = *bullet_;
  const int part_count = static_cast<int>(plan_.parts.size());

  // bodies this world cannot build
  if (part_count == 0) {
    refuse(EvalStatus::invalid_body, "the body plan has no parts");
    return;
  }
  if (!plan_.loops.empty()) {
    std::ostringstream message;
    message << "physics.world = featherstone builds tree-shaped bodies only, and this body has "
            << plan_.loops.size() << " closed-loop joint(s) (the first between parts "
            << plan_.loops[0].part_a << " and " << plan_.loops[0].part_b
            << "); a world that builds closed loops is needed";
    refuse(EvalStatus::invalid_body, message.str());
    return;
  }
  if (std::string missing = rigidBodyOnly(plan_); !missing.empty()) {
    refuse(EvalStatus::invalid_body, "physics.world = featherstone does not build " + missing +
                                         "; physics.world = rigid_bodies does");
    return;
  }

  // world: the environment's gravity, fixed-step solver settings, ground plane (if any)
  if (physics_.ground_contact_corners)
    b.configuration.setPlaneConvexMultipointIterations();
  gravity_ = environment_.gravity.value_or(physics_.gravity);
  b.world.setGravity(btVector3(0, 0, -gravity_));
  setSolverInfo(b.world.getSolverInfo(), physics_);
  b.ground.add(b.world, environment_, physics_);

  // count Bullet links: a k-DoF joint is k links (k-1 virtual), fixed is one fixed link
  int link_count = 0;
  for (int i = 1; i < part_count; ++i)
    link_count += std::max(1, degreesOfFreedom(plan_.parts[i].joint));

  // place the creature: lowest point at z = birth_height (on hills above the ground under it)
  const PartPlan& root = plan_.parts[0];
  const Vec3 base_position = birthPosition(plan_, environment_, birth_height);

  // the multibody: root part is the floating base
  b.body = std::make_unique<btMultiBody>(link_count, root.mass,
                                         inertiaOf(root.shape, root.size, root.mass), false, false);
  btMultiBody& body = *b.body;
  body.setBasePos(toBt(base_position));
  body.setWorldToBaseRot(toBt(conjugate(root.pose.rotation)));
  body.setHasSelfCollision(true);
  body.setLinearDamping(0);
  body.setAngularDamping(0);
  body.setMaxCoordinateVelocity(physics_.joint_speed_clamp);

  // links: walk the parts in plan order (parents first)
  dof_link_.assign(part_count, {-1, -1, -1});
  virtual_link_part_.assign(link_count, -1);
  max_torque_.assign(part_count, 0);
  part_link_.assign(part_count, -1);
  std::vector<int>& part_link = part_link_;
  int next_link = 0;
  for (int i = 1; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    int parent_link = part_link[part.parent];
    btQuaternion parent_to_this = toBt(conjugate(part.parent_to_child));
    btVector3 parent_offset = toBt(part.pivot_in_parent);
    btVector3 com_offset = toBt(-part.pivot_in_child);
    btVector3 inertia = inertiaOf(part.shape, part.size, part.mass);
    int dofs = degreesOfFreedom(part.joint);
    max_torque_[i] = jointStrength(part, physics_);

    if (dofs == 0) {
      body.setupFixed(next_link, part.mass, inertia, parent_link, parent_to_this, parent_offset,
                      com_offset, true);
      part_link[i] = next_link++;
      continue;
    }
    if (part.joint == JointType::prismatic) {
      body.setupPrismatic(next_link, part.mass, inertia, parent_link, parent_to_this,
                          toBt(part.axes[0]), parent_offset, com_offset, true);
      dof_link_[i][0] = next_link;
      damped_links_.push_back(next_link);
      link_damping_.push_back(jointDamping(part, 0, physics_.joint_damping));
      part_link[i] = next_link++;
      continue;
    }

    // a chain of revolute links: virtual ones at the pivot, the real part last
    double virtual_mass = 0.2 * part.mass;
    double radius = 0.5 * std::min({part.size.x, part.size.y, part.size.z});
    double virtual_inertia = 0.4 * virtual_mass * radius * radius;
    for (int d = 0; d < dofs; ++d) {
      bool last = d == dofs - 1;
      int link = next_link++;
      body.setupRevolute(
          link, last ? part.mass : virtual_mass,
          last ? inertia : btVector3(virtual_inertia, virtual_inertia, virtual_inertia),
          d == 0 ? parent_link : link - 1, d == 0 ? parent_to_this : btQuaternion::getIdentity(),
          toBt(part.axes[d]), d == 0 ? parent_offset : btVector3(0, 0, 0),
          last ? com_offset : btVector3(0, 0, 0), true);
      dof_link_[i][d] = link;
      damped_links_.push_back(link);
      link_damping_.push_back(jointDamping(part, d, physics_.joint_damping));
      if (!last)
        virtual_link_part_[link] = i;
    }
    part_link[i] = next_link - 1;
  }
  body.finalizeMultiDof();
  b.world.addMultiBody(&body);
  b.responses = std::make_unique<JointResponses>(body);
  b.world.setResponses(b.responses.get());

  // colliders: one shape per part, with the part's material
  for (int i = 0; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    b.shapes.push_back(shapeOf(part.shape, part.size));
    auto collider =
        std::make_unique<PartCollider>(&body, part_link[i], i, part.parent, &b.self_contacts);
    collider->setCollisionShape(b.shapes.back().get());
    collider->setFriction(part.material.friction);
    collider->setRestitution(part.material.restitution < 0 ? physics_.restitution
                                                           : part.material.restitution);
    anchorFriction(*collider, part.shape, physics_);
    if (i == 0) {
      body.setBaseCollider(collider.get());
    } else {
      body.getLink(part_link[i]).m_collider = collider.get();
    }
    b.world.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter,
                               btBroadphaseProxy::AllFilter);
    b.colliders.push_back(std::move(collider));
  }

  // the collider whose island a joint's rows are solved in (physics.solve_every_dof)
  auto islandPart = [&](int part) -> const btCollisionObject* {
    return physics_.solve_every_dof ? b.colliders[static_cast<std::size_t>(part)].get() : nullptr;
  };

  // joint limits on every degree of freedom
  b.link_limits.assign(static_cast<std::size_t>(link_count), nullptr);
  for (int i = 1; i < part_count; ++i) {
    for (int d = 0; d < 3; ++d) {
      int link = dof_link_[i][d];
      if (link < 0)
        continue;
      double limit = plan_.parts[i].joint_limit[d];
      b.limits.push_back(
          std::make_unique<JointLimit>(&body, link, -limit, limit, *b.responses, islandPart(i)));
      b.world.addMultiBodyConstraint(b.limits.back().get());
      b.link_limits[static_cast<std::size_t>(link)] = b.limits.back().get();
    }
  }

  // the effector driving each Bullet link (the joint loads)
  link_effector_.assign(static_cast<std::size_t>(link_count), -1);
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    if (effector.kind == EffectorKind::joint && dof_link_[effector.part][effector.dof] >= 0)
      link_effector_[static_cast<std::size_t>(dof_link_[effector.part][effector.dof])] =
          static_cast<int>(e);
  }

  // saturated motors: one per effector, idle (no impulse) until the controller drives it
  if (physics_.actuation == Actuation::saturated_motor) {
    for (const EffectorPlan& effector : plan_.effectors) {
      int link = effector.kind == EffectorKind::joint ? dof_link_[effector.part][effector.dof] : -1;
      if (link < 0) {
        b.motors.push_back(nullptr);
        continue;
      }
      b.motors.push_back(
          std::make_unique<BudgetMotor>(&body, link, *b.responses, islandPart(effector.part)));
      b.world.addMultiBodyConstraint(b.motors.back().get());
    }
  }

  // the joint damping, solved implicitly before the constraints (else a torque, applyTorques)
  const bool damped = std::any_of(link_damping_.begin(), link_damping_.end(),
                                  [](double damping) { return damping > 0; });
  if (physics_.implicit_damping && damped) {
    b.damping =
        std::make_unique<ImplicitJointDamping>(body, damped_links_, link_damping_, *b.responses);
    b.world.setDamping(b.damping.get());
  }

  // collider transforms from the zero pose
  body.updateCollisionObjectWorldTransforms(b.world_to_local, b.local_origin);
  contact_.assign(part_count, 0);
  ground_contact_.assign(part_count, 0);

  // the environment's free objects, after the creature, then what the creature holds
  b.objects.addObjects(b.world, environment_, physics_);
  addHeldObjects();

  // the momentum kept to what the outside forces give, where they are all known
  correct_momentum_ = physics_.momentum_correction &&
                      environment_.ground.kind == Ground::Kind::none &&
                      environment_.objects.empty() && plan_.held.empty();
  total_mass_ = body.getBaseMass();
  for (int link = 0; link < body.getNumLinks(); ++link)
    total_mass_ += body.getLinkMass(link);
  if (correct_momentum_)
    correctMomentum(0);  // the centre and the momentum at birth

  drag_ = fluidDrag(plan_, environment_);  // Sims' water
}

void FeatherstoneWorld::addHeldObjects() {
  // each a free body at its place on the holding part, fixed to it by a constraint, not
  // colliding with it while held
  FeatherstoneObjects& b = *bullet_;
  held_first_ = b.objects.bodies.size();
  released_.assign(plan_.held.size(), false);
  for (std::size_t h = 0; h < plan_.held.size(); ++h) {
    const HeldObject& held = plan_.held[h];
    if (std::string problem = heldObjectProblem(plan_, h); !problem.empty()) {
      refuse(EvalStatus::invalid_body, std::move(problem));
      return;
    }
    PartCollider& holder = *b.colliders[static_cast<std::size_t>(held.part)];
    const btTransform in_part(toBt(held.pose.rotation), toBt(held.pose.position));
    btRigidBody& object = b.objects.add(held.shape, held.size, held.mass, held.material,
                                        holder.getWorldTransform() * in_part, physics_);
    object.setActivationState(DISABLE_DEACTIVATION);
    object.setIgnoreCollisionCheck(&holder, true);
    b.world.addRigidBody(&object);
    const btMatrix3x3 frame_in_part = in_part.getBasis();
    b.holds.push_back(std::make_unique<btMultiBodyFixedConstraint>(
        b.body.get(), part_link_[static_cast<std::size_t>(held.part)], &object, in_part.getOrigin(),
        btVector3(0, 0, 0), frame_in_part, btMatrix3x3::getIdentity()));
    b.holds.back()->setMaxAppliedImpulse(BT_LARGE_FLOAT);
    b.world.addMultiBodyConstraint(b.holds.back().get());
  }
}

void FeatherstoneWorld::release(std::span<const double> commands) {
  // a release effector over its threshold lets go for good: the hold goes, contacts come back
  FeatherstoneObjects& b = *bullet_;
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    if (effector.kind != EffectorKind::release || !(commands[e] > kReleaseCommand))
      continue;
    const auto h = static_cast<std::size_t>(effector.dof);
    if (h >= b.holds.size() || !b.holds[h])
      continue;
    b.world.removeMultiBodyConstraint(b.holds[h].get());
    b.holds[h].reset();
    released_[h] = true;
    btRigidBody& object = *b.objects.bodies[held_first_ + h];
    object.setIgnoreCollisionCheck(b.colliders[static_cast<std::size_t>(plan_.held[h].part)].get(),
                                   false);
  }
}

Transform FeatherstoneWorld::heldPose(int held) const {
  return objectPose(static_cast<int>(held_first_) + held);
}

void FeatherstoneWorld::checkBirthPenetration() {
  std::string overlap =
      birthOverlap(bullet_->world, static_cast<int>(held_first_),
                   static_cast<int>(plan_.held.size()), physics_.penetration_tolerance);
  if (!overlap.empty())
    refuse(EvalStatus::self_penetration, std::move(overlap));
}

const std::vector<std::uint8_t>& FeatherstoneWorld::contacts() {
  markContactFaces(*bullet_->world.getDispatcher(), contact_);
  return contact_;
}

const std::vector<std::uint8_t>& FeatherstoneWorld::groundContacts() {
  markGroundContacts(*bullet_->world.getDispatcher(), ground_contact_);
  return ground_contact_;
}

const std::vector<std::pair<int, int>>& FeatherstoneWorld::partContacts() {
  touchingPartPairs(*bullet_->world.getDispatcher(), part_contacts_);
  return part_contacts_;
}

double FeatherstoneWorld::jointPosition(int part, int dof) const {
  int link = dof_link_[part][dof];
  return link < 0 ? 0.0 : bullet_->body->getJointPos(link);
}

JointSpeed FeatherstoneWorld::fastestJoint() const {
  // every degree of freedom is one Bullet link (virtual links of multi-DoF joints included)
  JointSpeed fastest;
  for (std::size_t i = 1; i < dof_link_.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      int link = dof_link_[i][static_cast<std::size_t>(d)];
      double speed = link < 0 ? 0.0 : std::abs(bullet_->body->getJointVel(link));
      if (speed > fastest.speed)
        fastest = {static_cast<int>(i), d, speed};
    }
  }
  return fastest;
}

Vec3 FeatherstoneWorld::jointAxis(int part, int dof) const {
  const int link = dof_link_[part][dof];
  if (link < 0)
    return {};
  const btMultibodyLink& joint = bullet_->body->getLink(link);
  const btVector3& axis = joint.m_jointType == btMultibodyLink::ePrismatic ? joint.getAxisBottom(0)
                                                                           : joint.getAxisTop(0);
  return fromBt(bullet_->body->localDirToWorld(link, axis));
}

double FeatherstoneWorld::partMass(int part) const {
  const int link = part_link_[part];
  return link < 0 ? bullet_->body->getBaseMass() : bullet_->body->getLinkMass(link);
}

Vec3 FeatherstoneWorld::partInertia(int part) const {
  const int link = part_link_[part];
  return fromBt(link < 0 ? bullet_->body->getBaseInertia() : bullet_->body->getLinkInertia(link));
}

Vec3 FeatherstoneWorld::directionInPart(int part, Vec3 point) const {
  return directionIn(*bullet_->colliders[part], point);
}

void FeatherstoneWorld::applyTorques(std::span<const double> commands, double substep) {
  btMultiBody& body = *bullet_->body;

  // passive damping on every jointed link, when not solved implicitly
  if (!physics_.implicit_damping) {
    for (std::size_t k = 0; k < damped_links_.size(); ++k)
      body.addJointTorque(damped_links_[k], -link_damping_[k] * body.getJointVel(damped_links_[k]));
  }

  // saturated motors: the command's sign picks the target speed, its size the torque budget
  if (physics_.actuation == Actuation::saturated_motor) {
    for (std::size_t e = 0; e < bullet_->motors.size(); ++e) {
      BudgetMotor* motor = bullet_->motors[e].get();
      if (!motor)
        continue;
      double command = commands.empty() ? 0.0 : commands[e];
      int part = plan_.effectors[e].part;
      motor->setCommand(command < 0 ? -physics_.motor_speed : physics_.motor_speed,
                        std::abs(command) * max_torque_[part] * substep);
    }
    return;
  }
  if (commands.empty())
    return;

  // explicit torques: effector commands scaled by each joint's strength
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    int link = effector.kind == EffectorKind::joint ? dof_link_[effector.part][effector.dof] : -1;
    if (link < 0)
      continue;
    body.addJointTorque(link, commands[e] * max_torque_[effector.part]);
  }
}

void FeatherstoneWorld::step(std::span<const double> commands) {
  // `substeps` equal Bullet steps (maxSubSteps = 0: exactly one internal step each); Bullet
  // clears applied torques after every internal step, so they are re-applied
  const double substep = physics_.time_step / physics_.substeps;
  if (!plan_.held.empty() && !commands.empty())
    release(commands);
  for (int k = 0; k < physics_.substeps; ++k) {
    applyTorques(commands, substep);
    if (!drag_.empty())
      applyDrag(substep);
    bullet_->world.stepSimulation(substep, 0);
    if (correct_momentum_)
      correctMomentum(substep);
    addEffectorWorkBound(commands, substep);
    if (physics_.joint_breaking > 0 && broken_joint_ < 0)
      findBrokenJoint(commands, substep);
  }
}

double FeatherstoneWorld::jointLoad(int part, std::span<const double> commands,
                                    double substep) const {
  // per degree of freedom: the muscle's torque (the explicit one, or the motor row's impulse over
  // the step) plus the limit rows' (lower bound pushing up, upper pushing down); their norm
  FeatherstoneObjects& b = *bullet_;
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    const int link = dof_link_[static_cast<std::size_t>(part)][d];
    if (link < 0)
      continue;
    double torque = 0;
    if (JointLimit* limit = b.link_limits[static_cast<std::size_t>(link)])
      torque += (limit->getAppliedImpulse(0) - limit->getAppliedImpulse(1)) / substep;
    const int e = link_effector_[static_cast<std::size_t>(link)];
    if (e >= 0 && physics_.actuation == Actuation::saturated_motor)
      torque += b.motors[static_cast<std::size_t>(e)]->getAppliedImpulse(0) / substep;
    else if (e >= 0 && !commands.empty())
      torque += commands[static_cast<std::size_t>(e)] * max_torque_[static_cast<std::size_t>(part)];
    sum += torque * torque;
  }
  return std::sqrt(sum);
}

void FeatherstoneWorld::findBrokenJoint(std::span<const double> commands, double substep) {
  // Walking with Dinosaurs' dismemberment: a joint breaks once its load passes
  // physics.joint_breaking x its strength (the muscle alone never does: it is held to 1 x)
  for (std::size_t i = 1; i < plan_.parts.size(); ++i) {
    const double strength = max_torque_[i];
    if (jointLoad(static_cast<int>(i), commands, substep) > physics_.joint_breaking * strength) {
      broken_joint_ = static_cast<int>(i);
      return;
    }
  }
}

void FeatherstoneWorld::applyDrag(double substep) {
  // each part's velocities in its own frame (Bullet's link frames are the parts' frames, at their
  // centres): the drag there, turned into the world frame Bullet's applied forces are in
  FeatherstoneObjects& b = *bullet_;
  btMultiBody& body = *b.body;
  linkVelocities(b);
  const std::size_t parts = plan_.parts.size();
  drag_force_ = drag_torque_ = Vec3{};
  for (std::size_t i = 0; i < parts; ++i) {
    const int link = part_link_[i];
    const bool base = link < 0;
    const double mass = base ? body.getBaseMass() : body.getLinkMass(link);
    const Vec3 inertia = fromBt(base ? body.getBaseInertia() : body.getLinkInertia(link));
    const Wrench drag = dragOverStep(drag_[i], mass, inertia, fromBt(b.velocity[link + 1]),
                                     fromBt(b.omega[link + 1]), substep);
    const btTransform& frame = b.colliders[i]->getWorldTransform();
    const btVector3 force = frame.getBasis() * toBt(drag.force);
    const btVector3 torque = frame.getBasis() * toBt(drag.torque);
    if (base) {
      body.addBaseForce(force);
      body.addBaseTorque(torque);
    } else {
      body.addLinkForce(link, force);
      body.addLinkTorque(link, torque);
    }
    // the sum and its moment about the centre (what the momentum correction keeps to)
    drag_force_ = drag_force_ + fromBt(force);
    drag_torque_ = drag_torque_ + fromBt(torque + (frame.getOrigin() - toBt(centre_)).cross(force));
  }
  // the free objects: the same in their own frames (fixed ones do not move)
  for (std::size_t k = 0; k < b.objects.bodies.size(); ++k)
    applyFluidDrag(*b.objects.bodies[k], drag_[parts + k], substep);
}

void FeatherstoneWorld::correctMomentum(double substep) {
  // every body's mass, centre, velocity, angular velocity and world inertia, gathered once
  FeatherstoneObjects& b = *bullet_;
  btMultiBody& body = *b.body;
  const int links = body.getNumLinks();
  linkVelocities(b);
  b.states.resize(links + 1);
  for (int k = 0; k <= links; ++k) {
    FeatherstoneObjects::BodyState& state = b.states[k];
    btMatrix3x3 basis;
    btVector3 principal;
    if (k == 0) {
      state.mass = body.getBaseMass();
      state.centre = body.getBasePos();
      state.velocity = body.getBaseVel();
      state.spin = body.getBaseOmega();
      basis = btMatrix3x3(body.getWorldToBaseRot().inverse());
      principal = body.getBaseInertia();
    } else {
      const int link = k - 1;
      state.mass = body.getLinkMass(link);
      state.centre = body.localPosToWorld(link, btVector3(0, 0, 0));
      state.velocity = body.localDirToWorld(link, b.velocity[k]);
      state.spin = body.localDirToWorld(link, b.omega[k]);
      for (int axis = 0; axis < 3; ++axis) {
        btVector3 unit(0, 0, 0);
        unit[axis] = 1;
        const btVector3 column = body.localDirToWorld(link, unit);
        for (int row = 0; row < 3; ++row)
          basis[row][axis] = column[row];
      }
      principal = body.getLinkInertia(link);
    }
    state.inertia = basis.scaled(principal) * basis.transpose();
  }

  // the centre of mass and the momentum
  btVector3 centre(0, 0, 0), momentum(0, 0, 0);
  for (const FeatherstoneObjects::BodyState& state : b.states) {
    centre += state.mass * state.centre;
    momentum += state.mass * state.velocity;
  }
  centre /= total_mass_;

  // the angular momentum about the centre and the inertia of the whole body about it
  btVector3 angular(0, 0, 0);
  btMatrix3x3 inertia(0, 0, 0, 0, 0, 0, 0, 0, 0);
  for (const FeatherstoneObjects::BodyState& state : b.states) {
    const btVector3 r = state.centre - centre;
    angular += state.mass * r.cross(state.velocity) + state.inertia * state.spin;
    const btMatrix3x3 offset(r.dot(r) - r.x() * r.x(), -r.x() * r.y(), -r.x() * r.z(),
                             -r.y() * r.x(), r.dot(r) - r.y() * r.y(), -r.y() * r.z(),
                             -r.z() * r.x(), -r.z() * r.y(), r.dot(r) - r.z() * r.z());
    for (int row = 0; row < 3; ++row)
      inertia[row] += state.inertia[row] + state.mass * offset[row];
  }
  if (substep == 0) {  // birth: the state to keep to
    centre_ = fromBt(centre);
    momentum_ = fromBt(momentum);
    angular_momentum_ = fromBt(angular);
    return;
  }

  // what gravity and the drag gave over the step; a rigid motion of the whole body (a velocity
  // and a rotation about the centre) that makes the body's momenta those, the joints untouched;
  // then the centre moved by the momentum (symplectic Euler: x' = x + step v')
  momentum_ = momentum_ + (drag_force_ + Vec3{0, 0, -gravity_ * total_mass_}) * substep;
  angular_momentum_ = angular_momentum_ + drag_torque_ * substep;
  const btVector3 added_velocity = (toBt(momentum_) - momentum) / total_mass_;
  const btVector3 added_spin = inertia.inverse() * (toBt(angular_momentum_) - angular);
  body.setBaseVel(body.getBaseVel() + added_velocity +
                  added_spin.cross(body.getBasePos() - centre));
  body.setBaseOmega(body.getBaseOmega() + added_spin);
  centre_ = centre_ + momentum_ * (substep / total_mass_);
  body.setBasePos(body.getBasePos() + toBt(centre_) - centre);
  body.updateCollisionObjectWorldTransforms(b.world_to_local, b.local_origin);
}

void FeatherstoneWorld::addEffectorWorkBound(std::span<const double> commands, double substep) {
  // no effector pushes harder than its limit x |command|, at the speed the step integrated with
  if (commands.empty())
    return;
  const btMultiBody& body = *bullet_->body;
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    int link = effector.kind == EffectorKind::joint ? dof_link_[effector.part][effector.dof] : -1;
    if (link >= 0) {
      work_bound_ += std::abs(commands[e]) * max_torque_[effector.part] *
                     std::abs(body.getJointVel(link)) * substep;
    }
  }
}

double FeatherstoneWorld::mechanicalEnergy() const {
  // the velocities of every body in its own frame (index 0 the base, k + 1 link k)
  const FeatherstoneObjects& b = *bullet_;
  const btMultiBody& body = *b.body;
  const int links = body.getNumLinks();
  linkVelocities(b);
  auto kinetic = [&](int k, double mass, const btVector3& inertia) {
    const btVector3& w = b.omega[k];
    return 0.5 * (mass * b.velocity[k].length2() + w.x() * w.x() * inertia.x() +
                  w.y() * w.y() * inertia.y() + w.z() * w.z() * inertia.z());
  };

  // kinetic, and m g z at each body's centre: a part's own, a virtual link's at its joint pivot
  const double g = gravity_;
  double energy = kinetic(0, body.getBaseMass(), body.getBaseInertia()) +
                  body.getBaseMass() * g * partPosition(0).z;
  for (int link = 0; link < links; ++link) {
    const double mass = body.getLinkMass(link);
    energy += kinetic(link + 1, mass, body.getLinkInertia(link));
    int pivot_part = virtual_link_part_[link];
    if (pivot_part < 0) {
      const btMultiBodyLinkCollider* collider = body.getLink(link).m_collider;
      energy += mass * g * (collider ? collider->getWorldTransform().getOrigin().z() : 0.0);
    } else {
      const btTransform& frame = b.colliders[pivot_part]->getWorldTransform();
      energy += mass * g * (frame * toBt(plan_.parts[pivot_part].pivot_in_child)).z();
    }
  }
  // what the creature holds or has thrown is its own
  for (std::size_t k = held_first_; k < b.objects.bodies.size(); ++k)
    energy += rigidBodyEnergy(*b.objects.bodies[k], g);
  return energy;
}

Vec3 FeatherstoneWorld::partPosition(int part) const {
  return fromBt(bullet_->colliders[part]->getWorldTransform().getOrigin());
}

Transform FeatherstoneWorld::partPose(int part) const {
  return poseOf(*bullet_->colliders[part]);
}

void FeatherstoneWorld::setGroundFriction(double friction) {
  bullet_->ground.setFriction(friction);
}

double FeatherstoneWorld::lowestPoint() const {
  return lowestPointOf(plan_.parts, bullet_->colliders);
}

Transform FeatherstoneWorld::objectPose(int object) const {
  return poseOf(*bullet_->objects.bodies.at(static_cast<std::size_t>(object)));
}

}  // namespace cambrian
