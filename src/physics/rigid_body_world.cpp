// cambrian: the Bullet constrained rigid-body world.
#include "physics/rigid_body_world.hpp"

#include "physics/bullet_scene.hpp"
#include "physics/soft_constraints.hpp"

#include <BulletCollision/CollisionDispatch/btCompoundCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCompoundCompoundCollisionAlgorithm.h>
#include <BulletDynamics/ConstraintSolver/btFixedConstraint.h>
#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>

namespace cambrian {

namespace {

// a part's body: collides with the ground, the objects and, while `self_contacts` is set, with
// the creature's other parts except those a joint ties it to (Bullet skips those pairs of
// constrained bodies). Its user index is its part.
class PartBody : public btRigidBody {
 public:
  PartBody(const btRigidBodyConstructionInfo& info, int part, const bool* self_contacts)
      : btRigidBody(info), self_contacts_(self_contacts) {
    setUserIndex(part);
  }
  bool checkCollideWithOverride(const btCollisionObject* other) const override {
    if (other->getUserIndex() >= 0 && !*self_contacts_)
      return false;
    return btRigidBody::checkCollideWithOverride(other);
  }

 private:
  const bool* self_contacts_;
};

// Bullet's child-shape filter for compound parts: shapes that share a contact group never touch
// (ColliderPlan::groups, carried as each shape's two user indices; -1 on every other shape)
bool shareNoGroup(const btCollisionShape* a, const btCollisionShape* b) {
  const int b0 = b->getUserIndex(), b1 = b->getUserIndex2();
  auto shares = [&](int group) { return group >= 0 && (group == b0 || group == b1); };
  return !shares(a->getUserIndex()) && !shares(a->getUserIndex2());
}

// the rotation whose columns are the joint's axes, made orthonormal in their order (the
// directed graph's already are)
btMatrix3x3 axesFrame(const std::array<Vec3, 3>& axes) {
  btVector3 x = toBt(axes[0]).normalized();
  btVector3 y = toBt(axes[1]) - x * x.dot(toBt(axes[1]));
  if (y.length2() < 1e-12)
    y = x.cross(std::abs(x.z()) < 0.9 ? btVector3(0, 0, 1) : btVector3(1, 0, 0));
  y.normalize();
  const btVector3 z = x.cross(y);
  return btMatrix3x3(x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z());
}

// The joint's turning degrees of freedom are Bullet's Euler angles in the order RO_ZYX: the
// child's frame relative to the parent's is R(x, -a0) R(y', -a1) R(z'', -a2) for Bullet's angles
// a0, a1, a2 (its decomposition reads the transpose), so the joint coordinate q_d is -a_d, turning
// first about the parent-fixed x axis and last about the child-fixed z axis — the Featherstone
// chain. The rotation axes of the coordinates in world terms: x of the parent's joint frame,
// z of the child's, and the line of nodes between them.
std::array<btVector3, 3> eulerAxes(const btGeneric6DofSpring2Constraint& joint) {
  const btVector3 first = joint.getCalculatedTransformA().getBasis().getColumn(0);
  const btVector3 last = joint.getCalculatedTransformB().getBasis().getColumn(2);
  btVector3 middle = last.cross(first);
  const double length = middle.length();
  middle =
      length > 1e-12 ? middle / length : joint.getCalculatedTransformB().getBasis().getColumn(1);
  return {first, middle, last};
}

// The dual of Euler axis `dof` (d . a_k / volume = 1 when k = dof, else 0), and the volume of
// the three axes (1 at gimbal lock, where the dual is the Euler axis itself). The relative
// angular velocity dotted with d / volume is the coordinate's rate, and a torque u along
// d / volume is the generalised force u on that coordinate alone, a Featherstone joint torque
// (along the Euler axis the torque would push the other coordinates too once the joint is bent).
struct DualAxis {
  btVector3 axis;
  double volume = 1;
};
DualAxis dualAxis(const btGeneric6DofSpring2Constraint& joint, int dof) {
  const auto [a0, a1, a2] = eulerAxes(joint);
  const double volume = a0.dot(a1.cross(a2));
  if (std::abs(volume) < 1e-9)
    return {dof == 0 ? a0 : dof == 1 ? a1 : a2, 1};
  return {dof == 0 ? a1.cross(a2) : dof == 1 ? a2.cross(a0) : a0.cross(a1), volume};
}

// constraint axis index (Bullet: 0-2 linear, 3-5 angular) of degree of freedom `dof`
int constraintAxis(JointType joint, int dof) {
  return joint == JointType::prismatic ? dof : 3 + dof;
}

}  // namespace

// the Bullet objects of one world, destroyed in reverse order of creation
struct RigidBodyObjects {
  explicit RigidBodyObjects(ConstraintSolver constraint_solver)
      : direct(constraint_solver == ConstraintSolver::dantzig ? std::make_unique<SoftDirectSolver>()
                                                              : nullptr),
        iterative(direct ? nullptr : std::make_unique<SoftConstraintSolver>()),
        world(&dispatcher, &broadphase,
              direct ? static_cast<btConstraintSolver*>(direct.get()) : iterative.get(),
              &configuration) {}

  btDefaultCollisionConfiguration configuration{creaturePools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  // physics.constraint_solver: one of the two
  std::unique_ptr<SoftDirectSolver> direct;
  std::unique_ptr<SoftConstraintSolver> iterative;
  btDiscreteDynamicsWorld world;
  BulletGround ground;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<PartBody>> parts;  // BodyPlan order
  // per part its tree joint (null for the root), then the loop joints
  std::vector<std::unique_ptr<btGeneric6DofSpring2Constraint>> joints, loops;
  FreeBodies objects;                                     // Environment::objects, then held
  std::vector<std::unique_ptr<btFixedConstraint>> holds;  // per held object, null: let go
  bool self_contacts = true;  // parts touch each other (always at the birth check)

  ~RigidBodyObjects() {
    for (auto& hold : holds)
      if (hold)
        world.removeConstraint(hold.get());
    for (auto& object : objects.bodies)
      world.removeRigidBody(object.get());
    for (auto& loop : loops)
      world.removeConstraint(loop.get());
    for (auto& joint : joints)
      if (joint)
        world.removeConstraint(joint.get());
    for (auto& part : parts)
      world.removeRigidBody(part.get());
  }
};

RigidBodyWorld::RigidBodyWorld(const BodyPlan& plan, const Environment& environment,
                               const PhysicsSettings& physics, double birth_height)
    : plan_(plan), environment_(environment), physics_(physics) {
  build(birth_height);
  if (birth_status_ == EvalStatus::ok) {
    std::string overlap =
        birthOverlap(bullet_->world, static_cast<int>(held_first_),
                     static_cast<int>(plan_.held.size()), physics_.penetration_tolerance);
    if (!overlap.empty())
      refuse(EvalStatus::self_penetration, std::move(overlap));
  }
  if (!bullet_->parts.empty() && !physics_.self_collision) {
    bullet_->self_contacts = false;
    dropPartPairs(bullet_->world);
  }
}

RigidBodyWorld::~RigidBodyWorld() = default;

void RigidBodyWorld::refuse(EvalStatus status, std::string message) {
  if (birth_status_ != EvalStatus::ok)
    return;
  birth_status_ = status;
  birth_message_ = std::move(message);
}

void RigidBodyWorld::build(double birth_height) {
  bullet_ = std::make_unique<RigidBodyObjects>(physics_.constraint_solver);
  RigidBodyObjects& b = *bullet_;
  const int part_count = static_cast<int>(plan_.parts.size());
  if (part_count == 0) {
    refuse(EvalStatus::invalid_body, "the body plan has no parts");
    return;
  }
  for (int i = 0; i < part_count; ++i) {
    if (!(plan_.parts[i].mass > 0)) {
      refuse(EvalStatus::invalid_body, "part " + std::to_string(i) + " has no mass");
      return;
    }
  }

  // world: the environment's gravity, fixed-step solver settings, the ground
  if (physics_.ground_contact_corners)
    b.configuration.setPlaneConvexMultipointIterations();
  gravity_ = environment_.gravity.value_or(physics_.gravity);
  b.world.setGravity(btVector3(0, 0, -gravity_));
  setSolverInfo(b.world.getSolverInfo(), physics_);
  // ODE's soft rows: the same springs and dampers at any substep (Bullet treats the contacts'
  // normal rows' m_globalCfm as ODE does; the solver mixes the joint and friction rows)
  const double substep = physics_.time_step / physics_.substeps;
  const SoftRows soft =
      softRowsAt(physics_.global_cfm, physics_.global_erp, physics_.time_step, substep);
  if (soft.cfm > 0) {
    btContactSolverInfo& info = b.world.getSolverInfo();
    info.m_globalCfm = soft.cfm;
    info.m_erp = info.m_erp2 = soft.erp;
    if (b.direct)
      b.direct->soften(soft.cfm, substep);
    else
      b.iterative->soften(soft.cfm, substep);
    soft_erp_ = soft.erp;
  }
  // friction along both tangent directions of every contact: with one (Bullet's default for
  // rigid bodies) a resting body jitters against its friction anchors and never comes to rest
  b.world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  b.ground.add(b.world, environment_, physics_);

  // place the creature as the Featherstone world does: lowest point at z = birth_height (on
  // hills above the highest ground under it), each child where its joint puts it
  const Vec3 base_position = birthPosition(plan_, environment_, birth_height);
  std::vector<btTransform> start(part_count);
  start[0] = btTransform(toBt(plan_.parts[0].pose.rotation), toBt(base_position));
  for (int i = 1; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    const btTransform& parent = start[part.parent];
    const btQuaternion rotation = parent.getRotation() * toBt(part.parent_to_child);
    const btVector3 pivot = parent * toBt(part.pivot_in_parent);
    start[i] = btTransform(rotation, pivot - quatRotate(rotation, toBt(part.pivot_in_child)));
  }

  // the parts, each with its material
  for (const ColliderPlan& collider : plan_.colliders) {
    if (collider.part < 0 || collider.part >= part_count) {
      refuse(EvalStatus::invalid_body, "a collider is carried by part " +
                                           std::to_string(collider.part) + " of " +
                                           std::to_string(part_count));
      return;
    }
  }
  max_torque_.assign(part_count, 0);
  for (int i = 0; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    btRigidBody::btRigidBodyConstructionInfo info(part.mass, nullptr, partShape(i),
                                                  inertiaOf(part.shape, part.size, part.mass));
    info.m_startWorldTransform = start[i];
    info.m_friction = part.material.friction;
    info.m_restitution =
        part.material.restitution < 0 ? physics_.restitution : part.material.restitution;
    b.parts.push_back(std::make_unique<PartBody>(info, i, &b.self_contacts));
    PartBody& body = *b.parts.back();
    body.setActivationState(DISABLE_DEACTIVATION);
    anchorFriction(body, part.shape, physics_);
    b.world.addRigidBody(&body);
    max_torque_[i] = jointStrength(part, physics_);
  }
  addJoints();
  contact_.assign(part_count, 0);
  ground_contact_.assign(part_count, 0);

  // the environment's free objects, after the creature, then what the creature holds
  b.objects.addObjects(b.world, environment_, physics_);
  addHeldObjects();

  drag_ = fluidDrag(plan_, environment_);  // Sims' water
}

btCollisionShape* RigidBodyWorld::partShape(int i) {
  // the part's own shape; a compound of it (when solid) and the colliders it carries when it
  // carries any, is not solid or has a contact group (whose shapes the group filter reads)
  RigidBodyObjects& b = *bullet_;
  const PartPlan& part = plan_.parts[i];
  const bool carries = std::any_of(plan_.colliders.begin(), plan_.colliders.end(),
                                   [i](const ColliderPlan& c) { return c.part == i; });
  if (part.solid && !carries && part.contact_group < 0) {
    b.shapes.push_back(shapeOf(part.shape, part.size));
    return b.shapes.back().get();
  }
  gCompoundChildShapePairCallback = shareNoGroup;
  gCompoundCompoundChildShapePairCallback = shareNoGroup;
  auto compound = std::make_unique<btCompoundShape>();
  auto add = [&](PartShape shape, Vec3 size, const btTransform& pose, int group_a, int group_b) {
    b.shapes.push_back(shapeOf(shape, size));
    b.shapes.back()->setUserIndex(group_a);
    b.shapes.back()->setUserIndex2(group_b);
    compound->addChildShape(pose, b.shapes.back().get());
  };
  if (part.solid)
    add(part.shape, part.size, btTransform::getIdentity(), part.contact_group, -1);
  for (const ColliderPlan& c : plan_.colliders) {
    if (c.part == i)
      add(c.shape, c.size, btTransform(toBt(c.pose.rotation), toBt(c.pose.position)), c.groups[0],
          c.groups[1]);
  }
  b.shapes.push_back(std::move(compound));
  return b.shapes.back().get();
}

void RigidBodyWorld::addJoints() {
  // a 6-DoF constraint per joint: the frame's axes are the joint's, its free axes the joint's
  // degrees of freedom within their limits, every other axis locked; joint damping as a spring
  // of no stiffness (Bullet bounds its damping so it cannot reverse a light limb); saturated
  // motors on the effectors' axes, idle until the controller drives them
  RigidBodyObjects& b = *bullet_;
  auto make = [&](btRigidBody& a, btRigidBody& c, const btTransform& in_a, const btTransform& in_c,
                  JointType joint, Vec3 limit, Vec3 damping) {
    auto constraint = std::make_unique<btGeneric6DofSpring2Constraint>(a, c, in_a, in_c, RO_ZYX);
    for (int axis = 0; axis < 6; ++axis)
      constraint->setLimit(axis, 0, 0);
    const int dofs = degreesOfFreedom(joint);
    for (int d = 0; d < dofs; ++d) {
      const int axis = constraintAxis(joint, d);
      if (std::isinf(limit[d]))
        constraint->setLimit(axis, 1, -1);  // Bullet's free axis: no limit rows at all
      else
        constraint->setLimit(axis, -limit[d], limit[d]);
      const double own = damping[d] < 0 ? physics_.joint_damping : damping[d];
      if (physics_.implicit_damping && own > 0) {
        constraint->enableSpring(axis, true);
        constraint->setStiffness(axis, 0);
        constraint->setDamping(axis, own);
      }
    }
    soften(*constraint);
    b.world.addConstraint(constraint.get(), true);
    return constraint;
  };

  b.joints.push_back(nullptr);  // the root's
  for (std::size_t i = 1; i < plan_.parts.size(); ++i) {
    const PartPlan& part = plan_.parts[i];
    const btMatrix3x3 frame = axesFrame(part.axes);
    const btTransform in_child(frame, toBt(part.pivot_in_child));
    const btTransform in_parent(btMatrix3x3(toBt(part.parent_to_child)) * frame,
                                toBt(part.pivot_in_parent));
    b.joints.push_back(make(*b.parts[part.parent], *b.parts[i], in_parent, in_child, part.joint,
                            part.joint_limit, part.joint_damping));
    // Walking with Dinosaurs' dismemberment: Bullet disables a joint one of whose rows needs a
    // larger impulse in a substep than the breaking load would give
    if (physics_.joint_breaking > 0)
      b.joints.back()->setBreakingImpulseThreshold(physics_.joint_breaking *
                                                   jointStrength(part, physics_) *
                                                   physics_.time_step / physics_.substeps);
  }
  for (const LoopJoint& loop : plan_.loops) {
    const int part_count = static_cast<int>(plan_.parts.size());
    if (loop.part_a < 0 || loop.part_b < 0 || loop.part_a >= part_count ||
        loop.part_b >= part_count || loop.part_a == loop.part_b) {
      refuse(EvalStatus::invalid_body, "a loop joint joins parts " + std::to_string(loop.part_a) +
                                           " and " + std::to_string(loop.part_b) +
                                           ", not two different parts of the body");
      return;
    }
    btRigidBody& a = *b.parts[loop.part_a];
    btRigidBody& c = *b.parts[loop.part_b];
    const btMatrix3x3 frame = axesFrame(loop.axes);
    const btTransform in_b(frame, toBt(loop.pivot_in_b));
    const btMatrix3x3 b_in_a =
        a.getWorldTransform().getBasis().transpose() * c.getWorldTransform().getBasis();
    const btTransform in_a(b_in_a * frame, toBt(loop.pivot_in_a));
    b.loops.push_back(make(a, c, in_a, in_b, loop.joint, loop.joint_limit, Vec3{-1, -1, -1}));
  }
  // motors: on every position effector's axis, and on the joint effectors' when saturated
  for (const EffectorPlan& effector : plan_.effectors) {
    if (!drivesJoint(effector) ||
        (effector.kind == EffectorKind::joint && physics_.actuation != Actuation::saturated_motor))
      continue;
    const PartPlan& part = plan_.parts[static_cast<std::size_t>(effector.part)];
    b.joints[effector.part]->enableMotor(constraintAxis(part.joint, effector.dof), true);
  }
}

void RigidBodyWorld::soften(btGeneric6DofSpring2Constraint& joint) const {
  // a locked or limited axis corrects its error at the soft rows' rate (the global ERP)
  if (soft_erp_ > 0)
    for (int axis = 0; axis < 6; ++axis)
      joint.setParam(BT_CONSTRAINT_STOP_ERP, soft_erp_, axis);
}

bool RigidBodyWorld::drivesJoint(const EffectorPlan& effector) const {
  return (effector.kind == EffectorKind::joint || effector.kind == EffectorKind::position) &&
         effector.part > 0 && effector.part < static_cast<int>(plan_.parts.size()) &&
         effector.dof <
             degreesOfFreedom(plan_.parts[static_cast<std::size_t>(effector.part)].joint);
}

void RigidBodyWorld::addHeldObjects() {
  // each a free body at its place on the holding part, fixed to it by a constraint (which keeps
  // the two from colliding while held)
  RigidBodyObjects& b = *bullet_;
  held_first_ = b.objects.bodies.size();
  released_.assign(plan_.held.size(), false);
  for (std::size_t h = 0; h < plan_.held.size(); ++h) {
    const HeldObject& held = plan_.held[h];
    if (std::string problem = heldObjectProblem(plan_, h); !problem.empty()) {
      refuse(EvalStatus::invalid_body, std::move(problem));
      return;
    }
    btRigidBody& holder = *b.parts[static_cast<std::size_t>(held.part)];
    const btTransform in_part(toBt(held.pose.rotation), toBt(held.pose.position));
    btRigidBody& object = b.objects.add(held.shape, held.size, held.mass, held.material,
                                        holder.getWorldTransform() * in_part, physics_);
    object.setActivationState(DISABLE_DEACTIVATION);
    b.world.addRigidBody(&object);
    b.holds.push_back(
        std::make_unique<btFixedConstraint>(holder, object, in_part, btTransform::getIdentity()));
    soften(*b.holds.back());
    b.world.addConstraint(b.holds.back().get(), true);
  }
}

void RigidBodyWorld::release(std::span<const double> commands) {
  RigidBodyObjects& b = *bullet_;
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    if (effector.kind != EffectorKind::release || !(commands[e] > kReleaseCommand))
      continue;
    const auto h = static_cast<std::size_t>(effector.dof);
    if (h >= b.holds.size() || !b.holds[h])
      continue;
    b.world.removeConstraint(b.holds[h].get());  // and the two collide again
    b.holds[h].reset();
    released_[h] = true;
  }
}

void RigidBodyWorld::applyTorques(std::span<const double> commands) {
  RigidBodyObjects& b = *bullet_;
  const bool explicit_damping = !physics_.implicit_damping;
  const bool torques = physics_.actuation == Actuation::torque && !commands.empty();
  // a generalised force on one joint coordinate, on the child and against the parent: a force
  // along a slider's axis, a torque along the dual of a turning coordinate's Euler axis
  auto push = [&](int part, int dof, double amount) {
    const PartPlan& plan = plan_.parts[static_cast<std::size_t>(part)];
    btRigidBody& child = *b.parts[static_cast<std::size_t>(part)];
    btRigidBody& parent = *b.parts[static_cast<std::size_t>(plan.parent)];
    if (plan.joint == JointType::prismatic) {
      const btVector3 axis = toBt(jointAxis(part, dof));
      child.applyCentralForce(amount * axis);
      parent.applyCentralForce(-amount * axis);
    } else {
      const DualAxis dual = dualAxis(*b.joints[static_cast<std::size_t>(part)], dof);
      const btVector3 torque = amount / dual.volume * dual.axis;
      child.applyTorque(torque);
      parent.applyTorque(-torque);
    }
  };
  if (explicit_damping) {
    for (std::size_t i = 1; i < plan_.parts.size(); ++i) {
      for (int d = 0; d < degreesOfFreedom(plan_.parts[i].joint); ++d) {
        const double damping = jointDamping(plan_.parts[i], d, physics_.joint_damping);
        if (damping > 0)
          push(static_cast<int>(i), d, -damping * jointSpeed(static_cast<int>(i), d));
      }
    }
  }

  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    if (!drivesJoint(effector))
      continue;
    const PartPlan& part = plan_.parts[static_cast<std::size_t>(effector.part)];
    const double command = commands.empty() ? 0.0 : commands[e];
    if (effector.kind == EffectorKind::position) {
      // the speed that reaches the commanded position by the end of the step, with the joint's
      // whole strength (a controller that is off holds the position of birth)
      btGeneric6DofSpring2Constraint& joint = *b.joints[effector.part];
      const int axis = constraintAxis(part.joint, effector.dof);
      const double target = command * part.joint_limit[effector.dof];
      const double speed = (target - jointPosition(effector.part, effector.dof)) /
                           (physics_.time_step / physics_.substeps * substeps_left_);
      joint.setTargetVelocity(axis, -speed);
      joint.setMaxMotorForce(axis, max_torque_[effector.part]);
    } else if (physics_.actuation == Actuation::saturated_motor) {
      // the command's sign picks the target speed, its size the torque budget (Bullet's 6-DoF
      // motor drives the parent relative to the child: the sign is turned)
      btGeneric6DofSpring2Constraint& joint = *b.joints[effector.part];
      const int axis = constraintAxis(part.joint, effector.dof);
      const double speed = command < 0 ? -physics_.motor_speed : physics_.motor_speed;
      joint.setTargetVelocity(axis, -speed);
      joint.setMaxMotorForce(axis, std::abs(command) * max_torque_[effector.part]);
    } else if (torques) {
      push(effector.part, effector.dof, command * max_torque_[effector.part]);
    }
  }
}

void RigidBodyWorld::step(std::span<const double> commands) {
  const double substep = physics_.time_step / physics_.substeps;
  if (!plan_.held.empty() && !commands.empty())
    release(commands);
  RigidBodyObjects& b = *bullet_;
  for (int k = 0; k < physics_.substeps; ++k) {
    substeps_left_ = physics_.substeps - k;
    applyTorques(commands);
    if (!drag_.empty()) {
      for (std::size_t i = 0; i < b.parts.size(); ++i)
        applyFluidDrag(*b.parts[i], drag_[i], substep);
      for (std::size_t k2 = 0; k2 < b.objects.bodies.size(); ++k2)
        applyFluidDrag(*b.objects.bodies[k2], drag_[b.parts.size() + k2], substep);
    }
    b.world.stepSimulation(substep, 0);
    // the joints' frames, angles and axes where the step left the parts (Bullet's are from
    // before it): what the readings, the next substep's torques and the work bound use
    for (auto& joint : b.joints)
      if (joint)
        joint->calculateTransforms();
    // no effector pushes harder than its limit x |command|, at the speed the step ended with
    if (!commands.empty()) {
      // (a position effector has its whole strength whatever its command)
      for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
        const EffectorPlan& effector = plan_.effectors[e];
        if (!drivesJoint(effector))
          continue;
        const double share = effector.kind == EffectorKind::position ? 1.0 : std::abs(commands[e]);
        work_bound_ += share * max_torque_[effector.part] *
                       std::abs(jointSpeed(effector.part, effector.dof)) * substep;
      }
    }
  }
}

double RigidBodyWorld::jointSpeed(int part, int dof) const {
  // the rate of the joint coordinate: for a slider the child's pivot speed along the axis, for
  // turning joints the relative angular velocity in the dual basis of the Euler axes
  const RigidBodyObjects& b = *bullet_;
  const PartPlan& plan = plan_.parts[static_cast<std::size_t>(part)];
  const btRigidBody& child = *b.parts[static_cast<std::size_t>(part)];
  const btRigidBody& parent = *b.parts[static_cast<std::size_t>(plan.parent)];
  const btGeneric6DofSpring2Constraint& joint = *b.joints[static_cast<std::size_t>(part)];
  if (plan.joint == JointType::prismatic) {
    const btVector3 pivot = joint.getCalculatedTransformB().getOrigin();
    const btVector3 relative =
        child.getVelocityInLocalPoint(pivot - child.getCenterOfMassPosition()) -
        parent.getVelocityInLocalPoint(pivot - parent.getCenterOfMassPosition());
    return relative.dot(joint.getCalculatedTransformA().getBasis().getColumn(0));
  }
  const btVector3 spin = child.getAngularVelocity() - parent.getAngularVelocity();
  const DualAxis dual = dualAxis(joint, dof);
  return spin.dot(dual.axis) / dual.volume;
}

double RigidBodyWorld::jointPosition(int part, int dof) const {
  if (part <= 0 || dof >= degreesOfFreedom(plan_.parts[static_cast<std::size_t>(part)].joint))
    return 0;
  const btGeneric6DofSpring2Constraint& joint = *bullet_->joints[static_cast<std::size_t>(part)];
  return plan_.parts[static_cast<std::size_t>(part)].joint == JointType::prismatic
             ? joint.getRelativePivotPosition(dof)
             : -joint.getAngle(dof);
}

JointSpeed RigidBodyWorld::fastestJoint() const {
  JointSpeed fastest;
  for (std::size_t i = 1; i < plan_.parts.size(); ++i) {
    for (int d = 0; d < degreesOfFreedom(plan_.parts[i].joint); ++d) {
      const double speed = std::abs(jointSpeed(static_cast<int>(i), d));
      if (speed > fastest.speed)
        fastest = {static_cast<int>(i), d, speed};
    }
  }
  return fastest;
}

Vec3 RigidBodyWorld::jointAxis(int part, int dof) const {
  if (part <= 0 || dof >= degreesOfFreedom(plan_.parts[static_cast<std::size_t>(part)].joint))
    return {};
  const btGeneric6DofSpring2Constraint& joint = *bullet_->joints[static_cast<std::size_t>(part)];
  if (plan_.parts[static_cast<std::size_t>(part)].joint == JointType::prismatic)
    return fromBt(joint.getCalculatedTransformA().getBasis().getColumn(0));
  return fromBt(eulerAxes(joint)[static_cast<std::size_t>(dof)]);
}

double RigidBodyWorld::partMass(int part) const {
  return 1 / bullet_->parts[static_cast<std::size_t>(part)]->getInvMass();
}

Vec3 RigidBodyWorld::partInertia(int part) const {
  const btVector3 inverse =
      bullet_->parts[static_cast<std::size_t>(part)]->getInvInertiaDiagLocal();
  return {1 / inverse.x(), 1 / inverse.y(), 1 / inverse.z()};
}

const std::vector<std::uint8_t>& RigidBodyWorld::contacts() {
  markContactFaces(*bullet_->world.getDispatcher(), contact_);
  return contact_;
}

const std::vector<std::uint8_t>& RigidBodyWorld::groundContacts() {
  markGroundContacts(*bullet_->world.getDispatcher(), ground_contact_);
  return ground_contact_;
}

const std::vector<std::pair<int, int>>& RigidBodyWorld::partContacts() {
  touchingPartPairs(*bullet_->world.getDispatcher(), part_contacts_);
  return part_contacts_;
}

int RigidBodyWorld::directSolveFallbacks() const {
  return bullet_->direct ? bullet_->direct->fallbacks() : 0;
}

double RigidBodyWorld::largestJointError() const {
  // each watched joint's frame on each of its bodies, where the bodies are now: the distance
  // between the two frames' origins
  double largest = 0;
  auto measure = [&largest](const btGeneric6DofSpring2Constraint& joint) {
    const btTransform a = joint.getRigidBodyA().getWorldTransform() * joint.getFrameOffsetA();
    const btTransform c = joint.getRigidBodyB().getWorldTransform() * joint.getFrameOffsetB();
    largest = std::max(largest, static_cast<double>((c.getOrigin() - a.getOrigin()).length()));
  };
  // only joints that hold a point and let their bodies turn about it (the thesis watches its
  // proxies' universal joints): a slider's or fixed joint's frames part by a lever arm's drift
  // when its bodies turn fast, which the spin monitor watches
  auto watched = [](JointType type) {
    return type != JointType::prismatic && type != JointType::fixed;
  };
  for (std::size_t i = 1; i < plan_.parts.size(); ++i)
    if (watched(plan_.parts[i].joint))
      measure(*bullet_->joints[i]);
  for (std::size_t k = 0; k < plan_.loops.size(); ++k)
    if (watched(plan_.loops[k].joint))
      measure(*bullet_->loops[k]);
  return largest;
}

Vec3 RigidBodyWorld::directionInPart(int part, Vec3 point) const {
  return directionIn(*bullet_->parts[static_cast<std::size_t>(part)], point);
}

Vec3 RigidBodyWorld::partPosition(int part) const {
  return fromBt(bullet_->parts[static_cast<std::size_t>(part)]->getWorldTransform().getOrigin());
}

Transform RigidBodyWorld::partPose(int part) const {
  return poseOf(*bullet_->parts[static_cast<std::size_t>(part)]);
}

void RigidBodyWorld::setGroundFriction(double friction) {
  bullet_->ground.setFriction(friction);
}

int RigidBodyWorld::brokenJoint() const {
  // (Bullet disables a joint whose row needed more than its breaking impulse)
  for (std::size_t i = 0; i < bullet_->joints.size(); ++i) {
    if (bullet_->joints[i] && !bullet_->joints[i]->isEnabled())
      return static_cast<int>(i);
  }
  return -1;
}

double RigidBodyWorld::lowestPoint() const {
  // the parts' own shapes, then the colliders they carry
  double lowest = lowestPointOf(plan_.parts, bullet_->parts);
  for (const ColliderPlan& collider : plan_.colliders) {
    PartPlan shape;
    shape.shape = collider.shape;
    shape.size = collider.size;
    const btTransform pose =
        bullet_->parts[static_cast<std::size_t>(collider.part)]->getWorldTransform() *
        btTransform(toBt(collider.pose.rotation), toBt(collider.pose.position));
    lowest = std::min(lowest, pose.getOrigin().z() - reachDown(shape, pose.getBasis()));
  }
  return lowest;
}

Transform RigidBodyWorld::objectPose(int object) const {
  return poseOf(*bullet_->objects.bodies.at(static_cast<std::size_t>(object)));
}

Transform RigidBodyWorld::heldPose(int held) const {
  return objectPose(static_cast<int>(held_first_) + held);
}

double RigidBodyWorld::mechanicalEnergy() const {
  double energy = 0;
  for (const auto& part : bullet_->parts)
    energy += rigidBodyEnergy(*part, gravity_);
  for (std::size_t k = held_first_; k < bullet_->objects.bodies.size(); ++k)
    energy += rigidBodyEnergy(*bullet_->objects.bodies[k], gravity_);
  return energy;
}

}  // namespace cambrian
