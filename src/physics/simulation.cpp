#include "physics/simulation.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cambrian {

namespace {

btVector3 toBt(Vec3 v) {
  return btVector3(v.x, v.y, v.z);
}
Vec3 fromBt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}
btQuaternion toBt(Quat q) {
  return btQuaternion(q.x, q.y, q.z, q.w);
}
Quat fromBt(const btQuaternion& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

// a part's collider: collides with the ground and, while `self_contacts` is set, with the
// creature's other parts except its parent and children (the joint neighbours), also across
// the virtual links of multi-degree-of-freedom joints
class PartCollider : public btMultiBodyLinkCollider {
 public:
  PartCollider(btMultiBody* body, int link, int part, int parent_part, const bool* self_contacts)
      : btMultiBodyLinkCollider(body, link),
        part_(part),
        parent_part_(parent_part),
        self_contacts_(self_contacts) {}

  bool checkCollideWithOverride(const btCollisionObject* other_object) const override {
    const auto* other = dynamic_cast<const PartCollider*>(other_object);
    if (!other || other->m_multiBody != m_multiBody)
      return true;
    if (!*self_contacts_)
      return false;
    return other->part_ != parent_part_ && other->parent_part_ != part_;
  }

  int part_, parent_part_;
  const bool* self_contacts_;
};

// box inertia about its centre
btVector3 boxInertia(Vec3 size, double mass) {
  btVector3 inertia;
  btBoxShape shape(toBt(size * 0.5));
  shape.calculateLocalInertia(mass, inertia);
  return inertia;
}

}  // namespace

// collision memory pools sized for one creature (at most a few dozen parts): Bullet's default
// pools (4,096 manifolds and algorithms) cost more to set up than a birth check itself; a pool
// that runs out falls back to the heap, which changes no result
btDefaultCollisionConstructionInfo creaturePools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 256;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 256;
  return info;
}

// the Bullet objects of one world, destroyed in reverse order of creation
struct BulletWorld {
  btDefaultCollisionConfiguration configuration{creaturePools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btStaticPlaneShape ground_shape{btVector3(0, 0, 1), 0};
  btCollisionObject ground;
  std::vector<std::unique_ptr<btBoxShape>> shapes;
  std::vector<std::unique_ptr<PartCollider>> colliders;  // one per part, BodyPlan order
  std::vector<std::unique_ptr<btMultiBodyJointLimitConstraint>> limits;
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;  // one per effector (or null)
  std::unique_ptr<btMultiBody> body;
  bool self_contacts = true;  // parts touch each other (always at the birth check)

  ~BulletWorld() {
    for (auto& motor : motors)
      if (motor)
        world.removeMultiBodyConstraint(motor.get());
    for (auto& limit : limits)
      world.removeMultiBodyConstraint(limit.get());
    for (auto& collider : colliders)
      world.removeCollisionObject(collider.get());
    if (body)
      world.removeMultiBody(body.get());
    world.removeCollisionObject(&ground);
  }
};

Simulation::Simulation(const BodyPlan& plan, const PhysicsSettings& settings, Vec3 target,
                       double birth_height)
    : plan_(plan), settings_(settings), target_(target), brain_(plan, settings.time_step) {
  build(birth_height);
  if (status_ == EvalStatus::ok)
    checkBirthPenetration();
  if (!settings_.self_collision)
    stopSelfContacts();
}

void Simulation::stopSelfContacts() {
  BulletWorld& b = *bullet_;
  b.self_contacts = false;

  // drop the part-part pairs (and their contact manifolds) the birth check found
  btOverlappingPairCache* pairs = b.world.getBroadphase()->getOverlappingPairCache();
  btBroadphasePairArray& array = pairs->getOverlappingPairArray();
  for (int i = array.size() - 1; i >= 0; --i) {
    btBroadphasePair& pair = array[i];
    const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    const auto* c = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (a->getUserIndex() >= 0 && c->getUserIndex() >= 0)
      pairs->removeOverlappingPair(pair.m_pProxy0, pair.m_pProxy1, b.world.getDispatcher());
  }
}

Simulation::~Simulation() = default;

void Simulation::fail(EvalStatus status, std::string message) {
  if (status_ != EvalStatus::ok)
    return;
  status_ = status;
  message_ = std::move(message);
}

void Simulation::build(double birth_height) {
  bullet_ = std::make_unique<BulletWorld>();
  BulletWorld& b = *bullet_;
  const int part_count = static_cast<int>(plan_.parts.size());
  if (part_count == 0) {
    fail(EvalStatus::invalid_body, "the body plan has no parts");
    return;
  }

  // world: gravity, fixed-step solver settings, ground plane
  b.world.setGravity(btVector3(0, 0, -settings_.gravity));
  b.world.getSolverInfo().m_numIterations = settings_.solver_iterations;
  b.ground.setCollisionShape(&b.ground_shape);
  b.ground.setFriction(settings_.ground_friction);
  b.ground.setRestitution(settings_.restitution);
  b.ground.setUserIndex(-1);
  b.world.addCollisionObject(&b.ground, btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);

  // count Bullet links: a k-DoF joint is k revolute links (k-1 virtual), rigid is one fixed link
  int link_count = 0;
  for (int i = 1; i < part_count; ++i) {
    link_count += std::max(1, degreesOfFreedom(plan_.parts[i].joint));
  }

  // place the creature: lowest corner at z = birth_height
  double lowest = 0;
  bool first = true;
  for (const PartPlan& part : plan_.parts) {
    Vec3 half = part.size * 0.5;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3 local{(corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y,
                 (corner & 4) ? half.z : -half.z};
      double z = apply(part.pose, local).z;
      if (first || z < lowest)
        lowest = z;
      first = false;
    }
  }
  const PartPlan& root = plan_.parts[0];
  Vec3 base_position = root.pose.position + Vec3{0, 0, birth_height - lowest};

  // the multibody: root part is the floating base
  b.body = std::make_unique<btMultiBody>(link_count, root.mass, boxInertia(root.size, root.mass),
                                         false, false);
  btMultiBody& body = *b.body;
  body.setBasePos(toBt(base_position));
  body.setWorldToBaseRot(toBt(conjugate(root.pose.rotation)));
  body.setHasSelfCollision(true);
  body.setLinearDamping(0);
  body.setAngularDamping(0);
  body.setMaxCoordinateVelocity(100);

  // links: walk the parts in plan order (parents first)
  dof_link_.assign(part_count, {-1, -1, -1});
  max_torque_.assign(part_count, 0);
  std::vector<int> part_link(part_count, -1);  // Bullet link carrying each part's box
  int next_link = 0;
  for (int i = 1; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    int parent_link = part_link[part.parent];
    btQuaternion parent_to_this = toBt(conjugate(part.parent_to_child));
    btVector3 parent_offset = toBt(part.pivot_in_parent);
    btVector3 com_offset = toBt(-part.pivot_in_child);
    btVector3 inertia = boxInertia(part.size, part.mass);
    int dofs = degreesOfFreedom(part.joint);
    max_torque_[i] = settings_.strength_per_area * part.cross_section;

    if (dofs == 0) {
      body.setupFixed(next_link, part.mass, inertia, parent_link, parent_to_this, parent_offset,
                      com_offset, true);
      part_link[i] = next_link++;
      continue;
    }

    // a chain of revolute links: virtual ones at the pivot, the real box last
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
    }
    part_link[i] = next_link - 1;
  }
  body.finalizeMultiDof();
  b.world.addMultiBody(&body);

  // colliders: one box per part
  for (int i = 0; i < part_count; ++i) {
    const PartPlan& part = plan_.parts[i];
    b.shapes.push_back(std::make_unique<btBoxShape>(toBt(part.size * 0.5)));
    auto collider =
        std::make_unique<PartCollider>(&body, part_link[i], i, part.parent, &b.self_contacts);
    collider->setCollisionShape(b.shapes.back().get());
    collider->setFriction(1.0);
    collider->setRestitution(settings_.restitution);
    collider->setUserIndex(i);
    if (i == 0) {
      body.setBaseCollider(collider.get());
    } else {
      body.getLink(part_link[i]).m_collider = collider.get();
    }
    b.world.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter,
                               btBroadphaseProxy::AllFilter);
    b.colliders.push_back(std::move(collider));
  }

  // joint limits on every degree of freedom
  for (int i = 1; i < part_count; ++i) {
    for (int d = 0; d < 3; ++d) {
      int link = dof_link_[i][d];
      if (link < 0)
        continue;
      double limit = plan_.parts[i].joint_limit[d];
      b.limits.push_back(
          std::make_unique<btMultiBodyJointLimitConstraint>(&body, link, -limit, limit));
      b.world.addMultiBodyConstraint(b.limits.back().get());
    }
  }

  // saturated motors: one per effector, idle (no impulse) until the brain drives it
  if (settings_.actuation == Actuation::saturated_motor) {
    for (const EffectorPlan& effector : plan_.effectors) {
      int link = dof_link_[effector.part][effector.dof];
      if (link < 0) {
        b.motors.push_back(nullptr);
        continue;
      }
      b.motors.push_back(std::make_unique<btMultiBodyJointMotor>(&body, link, 0.0, 0.0));
      b.world.addMultiBodyConstraint(b.motors.back().get());
    }
  }

  // collider transforms from the zero pose
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  body.updateCollisionObjectWorldTransforms(world_to_local, local_origin);

  // monitor state
  contact_.assign(part_count, 0);
  birth_position_.resize(part_count);
  for (int i = 0; i < part_count; ++i) {
    birth_position_[i] = fromBt(b.colliders[i]->getWorldTransform().getOrigin());
  }
  previous_position_ = birth_position_;
}

void Simulation::checkBirthPenetration() {
  BulletWorld& b = *bullet_;

  // run collision detection once on the birth pose
  b.world.performDiscreteCollisionDetection();
  btDispatcher* dispatcher = b.world.getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    int part_a = manifold->getBody0()->getUserIndex();
    int part_b = manifold->getBody1()->getUserIndex();
    if (part_a < 0 || part_b < 0)
      continue;  // the ground
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      double depth = manifold->getContactPoint(c).getDistance();
      if (depth < -settings_.penetration_tolerance) {
        std::ostringstream message;
        message << "parts " << std::min(part_a, part_b) << " and " << std::max(part_a, part_b)
                << " overlap by " << -depth << " m at birth";
        fail(EvalStatus::self_penetration, message.str());
        return;
      }
    }
  }
}

void Simulation::readSensors() {
  BulletWorld& b = *bullet_;
  const btMultiBody& body = *b.body;

  // contacts: every manifold with a touching point marks both parts
  std::fill(contact_.begin(), contact_.end(), 0);
  btDispatcher* dispatcher = b.world.getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    bool touching = false;
    for (int c = 0; c < manifold->getNumContacts() && !touching; ++c) {
      touching = manifold->getContactPoint(c).getDistance() <= 0.001;
    }
    if (!touching)
      continue;
    int part_a = manifold->getBody0()->getUserIndex();
    int part_b = manifold->getBody1()->getUserIndex();
    if (part_a >= 0)
      contact_[part_a] = 1;
    if (part_b >= 0)
      contact_[part_b] = 1;
  }

  // photosensor direction in the root frame
  const btTransform& root = b.colliders[0]->getWorldTransform();
  btVector3 to_target = root.getBasis().transpose() * (toBt(target_) - root.getOrigin());
  double distance = to_target.length();
  if (distance > 1e-9)
    to_target /= distance;

  // write every sensor slot
  std::span<double> sensors = brain_.sensors();
  for (std::size_t s = 0; s < plan_.sensors.size(); ++s) {
    const SensorPlan& sensor = plan_.sensors[s];
    switch (sensor.kind) {
      case SensorKind::joint_angle: {
        int link = dof_link_[sensor.part][sensor.axis];
        double limit = std::max(0.1, plan_.parts[sensor.part].joint_limit[sensor.axis]);
        sensors[s] = link < 0 ? 0.0 : body.getJointPos(link) / limit;
        break;
      }
      case SensorKind::contact:
        sensors[s] = contact_[sensor.part];
        break;
      case SensorKind::photo:
        sensors[s] = to_target[sensor.axis];
        break;
    }
  }
}

void Simulation::applyTorques(bool brain_on, double substep) {
  btMultiBody& body = *bullet_->body;

  // passive damping on every revolute link
  for (int link : damped_links_) {
    body.addJointTorque(link, -settings_.joint_damping * body.getJointVel(link));
  }

  // saturated motors: the command's sign picks the target speed, its size the torque budget
  std::span<const double> commands = brain_.effectors();
  if (settings_.actuation == Actuation::saturated_motor) {
    for (std::size_t e = 0; e < bullet_->motors.size(); ++e) {
      btMultiBodyJointMotor* motor = bullet_->motors[e].get();
      if (!motor)
        continue;
      double command = brain_on ? commands[e] : 0.0;
      int part = plan_.effectors[e].part;
      motor->setVelocityTarget(command < 0 ? -settings_.motor_speed : settings_.motor_speed);
      motor->setMaxAppliedImpulse(std::abs(command) * max_torque_[part] * substep);
    }
    return;
  }
  if (!brain_on)
    return;

  // explicit torques: effector commands scaled by each joint's strength
  for (std::size_t e = 0; e < plan_.effectors.size(); ++e) {
    const EffectorPlan& effector = plan_.effectors[e];
    int link = dof_link_[effector.part][effector.dof];
    if (link < 0)
      continue;
    body.addJointTorque(link, commands[e] * max_torque_[effector.part]);
  }
}

void Simulation::monitor() {
  const double max_step = settings_.max_speed * settings_.time_step;
  const double max_displacement_sq = settings_.max_displacement * settings_.max_displacement;
  for (std::size_t i = 0; i < bullet_->colliders.size(); ++i) {
    Vec3 position = fromBt(bullet_->colliders[i]->getWorldTransform().getOrigin());

    // non-finite state
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
      fail(EvalStatus::non_finite, "part " + std::to_string(i) + " has a non-finite position");
      return;
    }

    // numerical explosion: too fast or too far
    Vec3 moved = position - previous_position_[i];
    if (dot(moved, moved) > max_step * max_step) {
      std::ostringstream message;
      message << "part " << i << " moved at " << norm(moved) / settings_.time_step
              << " m/s (physics.max_speed " << settings_.max_speed << ") at step " << steps_;
      fail(EvalStatus::exploded, message.str());
      return;
    }
    Vec3 from_birth = position - birth_position_[i];
    if (dot(from_birth, from_birth) > max_displacement_sq) {
      std::ostringstream message;
      message << "part " << i << " is " << norm(from_birth)
              << " m from where it was born (physics.max_displacement "
              << settings_.max_displacement << ") at step " << steps_;
      fail(EvalStatus::exploded, message.str());
      return;
    }
    previous_position_[i] = position;
  }
}

void Simulation::step(bool brain_on) {
  if (status_ != EvalStatus::ok)
    return;

  // sense, think
  readSensors();
  if (brain_on)
    brain_.step();

  // act through `substeps` equal Bullet steps (maxSubSteps = 0: exactly one internal step
  // each); Bullet clears applied torques after every internal step, so they are re-applied
  const double substep = settings_.time_step / settings_.substeps;
  for (int k = 0; k < settings_.substeps; ++k) {
    applyTorques(brain_on, substep);
    bullet_->world.stepSimulation(substep, 0);
  }
  ++steps_;
  monitor();
}

Vec3 Simulation::centerOfMass() const {
  Vec3 weighted;
  double mass = 0;
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    Vec3 position = fromBt(bullet_->colliders[i]->getWorldTransform().getOrigin());
    weighted = weighted + position * plan_.parts[i].mass;
    mass += plan_.parts[i].mass;
  }
  return mass > 0 ? weighted * (1.0 / mass) : weighted;
}

double Simulation::lowestPoint() const {
  double lowest = 0;
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    // lowest corner of a box: centre minus the projection of its half extents on z
    const btTransform& transform = bullet_->colliders[i]->getWorldTransform();
    const btMatrix3x3& basis = transform.getBasis();
    Vec3 half = plan_.parts[i].size * 0.5;
    double reach = std::abs(basis[2][0]) * half.x + std::abs(basis[2][1]) * half.y +
                   std::abs(basis[2][2]) * half.z;
    double z = transform.getOrigin().z() - reach;
    if (i == 0 || z < lowest)
      lowest = z;
  }
  return lowest;
}

void Simulation::partPoses(std::vector<Transform>& poses) const {
  poses.resize(plan_.parts.size());
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    const btTransform& transform = bullet_->colliders[i]->getWorldTransform();
    poses[i] = {fromBt(transform.getOrigin()), fromBt(transform.getRotation())};
  }
}

const char* bulletPrecision() {
  return sizeof(btScalar) == 8 ? "float64" : "float32";
}

}  // namespace cambrian
