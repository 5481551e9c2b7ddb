// cambrian: what the Bullet worlds share around a creature.
#include "physics/bullet_scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cambrian {

std::unique_ptr<btCollisionShape> shapeOf(PartShape shape, Vec3 size) {
  const double radius = 0.5 * size.y;
  switch (shape) {
    case PartShape::box:
      break;
    case PartShape::sphere:
      return std::make_unique<btSphereShape>(0.5 * size.x);
    case PartShape::capsule:
      return std::make_unique<btCapsuleShapeX>(radius, std::max(0.0, size.x - 2 * radius));
    case PartShape::cylinder:
      return std::make_unique<btCylinderShapeX>(btVector3(0.5 * size.x, radius, radius));
  }
  return std::make_unique<btBoxShape>(toBt(size * 0.5));
}

btVector3 inertiaOf(PartShape shape, Vec3 size, double mass) {
  btVector3 inertia;
  if (shape == PartShape::capsule) {
    // a solid capsule along x, exactly: Bullet gives its bounding box's inertia
    const double r = 0.5 * size.y, h = std::max(0.0, size.x - 2 * r);
    const double middle = h, ends = 4.0 / 3.0 * r;  // volumes over pi r^2
    const double m_middle = mass * middle / (middle + ends), m_ends = mass - m_middle;
    const double along = m_middle * r * r / 2 + m_ends * 2 * r * r / 5;
    const double across =
        m_middle * (h * h / 12 + r * r / 4) + m_ends * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8);
    inertia.setValue(along, across, across);
    return inertia;
  }
  shapeOf(shape, size)->calculateLocalInertia(mass, inertia);
  return inertia;
}

double reachDown(const PartPlan& part, const btMatrix3x3& basis) {
  Vec3 half = part.size * 0.5;
  const double along = std::abs(basis[2][0]);
  const double radius = 0.5 * part.size.y;
  switch (part.shape) {
    case PartShape::box:
      break;
    case PartShape::sphere:
      return half.x;
    case PartShape::capsule:
      return along * std::max(0.0, half.x - radius) + radius;
    case PartShape::cylinder:
      return along * half.x + radius * std::sqrt(std::max(0.0, 1 - along * along));
  }
  return std::abs(basis[2][0]) * half.x + std::abs(basis[2][1]) * half.y +
         std::abs(basis[2][2]) * half.z;
}

btDefaultCollisionConstructionInfo creaturePools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 256;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 256;
  return info;
}

void setSolverInfo(btContactSolverInfo& solver, const PhysicsSettings& physics) {
  solver.m_numIterations = physics.solver_iterations;
  solver.m_leastSquaresResidualThreshold = physics.solver_tolerance * physics.solver_tolerance;
  solver.m_erp = physics.joint_erp;
  solver.m_erp2 = physics.contact_erp;
  solver.m_linearSlop = physics.contact_slop;
}

double highestGroundUnder(const Environment& environment, const std::vector<PartPlan>& parts) {
  double x_low = 0, x_high = 0, y_low = 0, y_high = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const PartPlan& part = parts[i];
    const Vec3 at = part.pose.position;
    auto reach = [&](Vec3 direction) {
      return shapeReach(part.shape, part.size, part.pose.rotation, direction);
    };
    const double xl = at.x - reach({-1, 0, 0}), xh = at.x + reach({1, 0, 0});
    const double yl = at.y - reach({0, -1, 0}), yh = at.y + reach({0, 1, 0});
    x_low = i == 0 ? xl : std::min(x_low, xl);
    x_high = i == 0 ? xh : std::max(x_high, xh);
    y_low = i == 0 ? yl : std::min(y_low, yl);
    y_high = i == 0 ? yh : std::max(y_high, yh);
  }
  return environment.ground.highestIn(x_low, x_high, y_low, y_high);
}

Vec3 birthPosition(const BodyPlan& plan, const Environment& environment, double birth_height) {
  double lowest = 0;
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const double z = lowestZ(plan.parts[i], plan.parts[i].pose);
    if (i == 0 || z < lowest)
      lowest = z;
  }
  Vec3 position = plan.parts[0].pose.position + Vec3{0, 0, birth_height - lowest};
  if (environment.ground.kind == Ground::Kind::heightfield)
    position.z += highestGroundUnder(environment, plan.parts);
  return position;
}

std::vector<DragCoefficients> fluidDrag(const BodyPlan& plan, const Environment& environment) {
  std::vector<DragCoefficients> drag;
  const double viscosity = environment.fluid.viscosity;
  if (!(viscosity > 0))
    return drag;
  for (const PartPlan& part : plan.parts)
    drag.push_back(viscousDrag(part.shape, part.size, viscosity));
  for (const FreeObject& object : environment.objects)
    drag.push_back(viscousDrag(object.shape, object.size, viscosity));
  for (const HeldObject& held : plan.held)
    drag.push_back(viscousDrag(held.shape, held.size, viscosity));
  return drag;
}

std::string rigidBodyOnly(const BodyPlan& plan) {
  if (!plan.colliders.empty())
    return "colliders carried by parts (the first on part " +
           std::to_string(plan.colliders[0].part) + ")";
  for (std::size_t i = 0; i < plan.parts.size(); ++i)
    if (!plan.parts[i].solid)
      return "parts without a collider of their own (part " + std::to_string(i) + ")";
  for (const EffectorPlan& effector : plan.effectors)
    if (effector.kind == EffectorKind::position)
      return "position effectors (on part " + std::to_string(effector.part) + ")";
  return {};
}

std::string heldObjectProblem(const BodyPlan& plan, std::size_t h) {
  const HeldObject& held = plan.held[h];
  if (held.part >= 0 && held.part < static_cast<int>(plan.parts.size()) && held.mass > 0)
    return {};
  return "held object " + std::to_string(h) + " names part " + std::to_string(held.part) +
         " or has no mass";
}

Transform poseOf(const btCollisionObject& body) {
  const btTransform& transform = body.getWorldTransform();
  return {fromBt(transform.getOrigin()), fromBt(transform.getRotation())};
}

Vec3 directionIn(const btCollisionObject& body, Vec3 point) {
  const btTransform& frame = body.getWorldTransform();
  btVector3 to_point = frame.getBasis().transpose() * (toBt(point) - frame.getOrigin());
  const double distance = to_point.length();
  if (distance > 1e-9)
    to_point /= distance;
  return fromBt(to_point);
}

void anchorFriction(btCollisionObject& object, PartShape shape, const PhysicsSettings& physics) {
  if (physics.friction_anchors && shape == PartShape::box)
    object.setCollisionFlags(object.getCollisionFlags() |
                             btCollisionObject::CF_HAS_FRICTION_ANCHOR);
}

void BulletGround::add(btCollisionWorld& into, const Environment& environment,
                       const PhysicsSettings& physics) {
  world = &into;
  plane.setCollisionShape(&plane_shape);
  plane.setFriction(environment.ground.friction);
  plane.setRestitution(environment.ground.restitution);
  plane.setUserIndex(kGroundIndex);
  if (environment.ground.kind == Ground::Kind::heightfield) {
    // the terrain, and the plane under its lowest point to catch what leaves it
    const Heightfield& field = environment.ground.heightfield;
    const auto [low, high] = std::minmax_element(field.heights->begin(), field.heights->end());
    terrain_shape = std::make_unique<btHeightfieldTerrainShape>(
        field.samples, field.samples, field.heights->data(), btScalar(*low), btScalar(*high), 2,
        false);
    terrain_shape->setLocalScaling(btVector3(field.spacing, field.spacing, 1));
    terrain.setCollisionShape(terrain_shape.get());
    // Bullet centres the shape on its bounds' middle height
    terrain.setWorldTransform(
        btTransform(btQuaternion::getIdentity(), btVector3(0, 0, (*low + *high) / 2)));
    terrain.setFriction(environment.ground.friction);
    terrain.setRestitution(environment.ground.restitution);
    terrain.setUserIndex(kGroundIndex);
    into.addCollisionObject(&terrain, btBroadphaseProxy::StaticFilter,
                            btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    has_terrain = true;
    plane.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, *low)));
  }
  if (environment.ground.kind != Ground::Kind::none) {
    into.addCollisionObject(&plane, btBroadphaseProxy::StaticFilter,
                            btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    has_plane = true;
  }
}

void BulletGround::setFriction(double friction) {
  plane.setFriction(friction);
  terrain.setFriction(friction);
  if (!world)
    return;
  btDispatcher& dispatcher = *world->getDispatcher();
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(i);
    const auto ground = [this](const btCollisionObject* o) { return o == &plane || o == &terrain; };
    if (ground(manifold.getBody0()) || ground(manifold.getBody1()))
      manifold.clearManifold();
  }
}

BulletGround::~BulletGround() {
  if (has_terrain)
    world->removeCollisionObject(&terrain);
  if (has_plane)
    world->removeCollisionObject(&plane);
}

btRigidBody& FreeBodies::add(PartShape shape_kind, Vec3 size, double mass, const Material& material,
                             const btTransform& start, const PhysicsSettings& physics) {
  shapes.push_back(shapeOf(shape_kind, size));
  btCollisionShape* shape = shapes.back().get();
  btVector3 inertia(0, 0, 0);
  if (mass > 0)
    shape->calculateLocalInertia(mass, inertia);
  states.push_back(std::make_unique<btDefaultMotionState>(start));
  btRigidBody::btRigidBodyConstructionInfo info(mass, states.back().get(), shape, inertia);
  info.m_friction = material.friction;
  info.m_restitution = material.restitution < 0 ? physics.restitution : material.restitution;
  bodies.push_back(std::make_unique<btRigidBody>(info));
  btRigidBody& body = *bodies.back();
  body.setUserIndex(objectIndex(static_cast<int>(bodies.size() - 1)));
  anchorFriction(body, shape_kind, physics);
  return body;
}

void FreeBodies::addObjects(btDynamicsWorld& world, const Environment& environment,
                            const PhysicsSettings& physics) {
  for (const FreeObject& object : environment.objects) {
    Vec3 position = object.pose.position;
    if (environment.ground.kind == Ground::Kind::heightfield) {
      PartPlan footprint;
      footprint.shape = object.shape;
      footprint.size = object.size;
      footprint.pose = object.pose;
      position.z += highestGroundUnder(environment, {footprint});
    }
    const btTransform start(toBt(object.pose.rotation), toBt(position));
    world.addRigidBody(
        &add(object.shape, object.size, object.mass, object.material, start, physics));
  }
}

void markContactFaces(btDispatcher& dispatcher, std::vector<std::uint8_t>& faces) {
  // the face that looks most nearly towards the other body: the contact normal in the part's
  // frame (a box's corner lies on three faces, its normal picks the one pressed)
  std::fill(faces.begin(), faces.end(), 0);
  auto mark = [&faces](const btCollisionObject& object, const btVector3& towards_other) {
    const int part = object.getUserIndex();
    if (part < 0)
      return;  // the ground or an object
    const btVector3 local = object.getWorldTransform().getBasis().transpose() * towards_other;
    const int axis = local.closestAxis();
    faces[part] |= static_cast<std::uint8_t>(1u << (2 * axis + (local[axis] < 0 ? 1 : 0)));
  };
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      const btManifoldPoint& point = manifold->getContactPoint(c);
      if (point.getDistance() > 0.001)
        continue;
      mark(*manifold->getBody0(), -point.m_normalWorldOnB);  // the normal on B points towards A
      mark(*manifold->getBody1(), point.m_normalWorldOnB);
    }
  }
}

void markGroundContacts(btDispatcher& dispatcher, std::vector<std::uint8_t>& touching) {
  std::fill(touching.begin(), touching.end(), 0);
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const int a = manifold->getBody0()->getUserIndex();
    const int b = manifold->getBody1()->getUserIndex();
    const int part = a == kGroundIndex ? b : b == kGroundIndex ? a : -1;
    if (part < 0)
      continue;
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      if (manifold->getContactPoint(c).getDistance() <= 0.001) {
        touching[part] = 1;
        break;
      }
    }
  }
}

void touchingPartPairs(btDispatcher& dispatcher, std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const int a = manifold->getBody0()->getUserIndex();
    const int b = manifold->getBody1()->getUserIndex();
    if (a < 0 || b < 0)
      continue;
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      if (manifold->getContactPoint(c).getDistance() <= 0.001) {
        pairs.emplace_back(std::min(a, b), std::max(a, b));
        break;
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

std::string birthOverlap(btCollisionWorld& world, int held_first, int held_count,
                         double tolerance) {
  auto held = [&](int user_index) {
    const int h = -2 - user_index - held_first;
    return user_index <= -2 && h >= 0 && h < held_count ? h : -1;
  };
  world.performDiscreteCollisionDetection();
  btDispatcher* dispatcher = world.getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const int part_a = manifold->getBody0()->getUserIndex();
    const int part_b = manifold->getBody1()->getUserIndex();
    // parts with parts, and held objects with parts (the ground and the environment's objects
    // do not count)
    const int held_a = held(part_a), held_b = held(part_b);
    if ((part_a < 0 && held_a < 0) || (part_b < 0 && held_b < 0) || (held_a >= 0 && held_b >= 0))
      continue;
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      const double depth = manifold->getContactPoint(c).getDistance();
      if (depth < -tolerance) {
        std::ostringstream message;
        if (held_a >= 0 || held_b >= 0)
          message << "held object " << std::max(held_a, held_b) << " and part "
                  << std::max(part_a, part_b) << " overlap by " << -depth << " m at birth";
        else
          message << "parts " << std::min(part_a, part_b) << " and " << std::max(part_a, part_b)
                  << " overlap by " << -depth << " m at birth";
        return message.str();
      }
    }
  }
  return {};
}

void dropPartPairs(btCollisionWorld& world) {
  btOverlappingPairCache* pairs = world.getBroadphase()->getOverlappingPairCache();
  btBroadphasePairArray& array = pairs->getOverlappingPairArray();
  for (int i = array.size() - 1; i >= 0; --i) {
    btBroadphasePair& pair = array[i];
    const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    const auto* c = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (a->getUserIndex() >= 0 && c->getUserIndex() >= 0)
      pairs->removeOverlappingPair(pair.m_pProxy0, pair.m_pProxy1, world.getDispatcher());
  }
}

void applyFluidDrag(btRigidBody& body, const DragCoefficients& drag, double substep) {
  if (body.getInvMass() == 0)
    return;
  const btMatrix3x3& basis = body.getWorldTransform().getBasis();
  const btVector3 inverse_inertia = body.getInvInertiaDiagLocal();
  auto invert = [](double value) { return value > 0 ? 1 / value : 0.0; };
  const Vec3 inertia{invert(inverse_inertia.x()), invert(inverse_inertia.y()),
                     invert(inverse_inertia.z())};
  const Wrench wrench = dragOverStep(
      drag, 1 / body.getInvMass(), inertia, fromBt(basis.transpose() * body.getLinearVelocity()),
      fromBt(basis.transpose() * body.getAngularVelocity()), substep);
  body.applyCentralForce(basis * toBt(wrench.force));
  body.applyTorque(basis * toBt(wrench.torque));
}

double rigidBodyEnergy(const btRigidBody& body, double gravity) {
  const double mass = 1 / body.getInvMass();
  const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
  const btVector3 inverse = body.getInvInertiaDiagLocal();
  return 0.5 * mass * body.getLinearVelocity().length2() +
         0.5 * (w.x() * w.x() / inverse.x() + w.y() * w.y() / inverse.y() +
                w.z() * w.z() / inverse.z()) +
         mass * gravity * body.getWorldTransform().getOrigin().z();
}

}  // namespace cambrian
