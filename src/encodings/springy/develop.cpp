// cambrian: a springy organism as a body plan and its muscles' controller.
#include "encodings/springy/develop.hpp"

#include "brain/length_sinusoids.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace cambrian::springy {

namespace {

// a body of Algorithm B.1: a node's main body or one of its proxies
struct Body {
  int node = 0;
  bool proxy = false;
};

// a joint between two bodies
struct BodyJoint {
  int a = 0, b = 0;
  JointType type = JointType::fixed;
  int tube = 0;  // the tube it belongs to (a proxy's universal joint: the proxy's tube)
};

// m a slider's stops lie beyond the muscle's range
constexpr double kStopMargin = 0.05;
// no limit on a degree of freedom
constexpr double kFree = std::numeric_limits<double>::infinity();

// Algorithms B.1 and B.2: the bodies and joints, with the bodies that carry each tube
struct Layout {
  std::vector<Body> bodies;  // node n's main body is body n
  std::vector<BodyJoint> joints;
  std::vector<std::array<int, 2>> tube_bodies;  // per tube, its bodies at node a and node b
};

Layout layOut(const Organism& organism) {
  Layout layout;
  const int node_count = static_cast<int>(organism.nodes.size());
  for (int n = 0; n < node_count; ++n)
    layout.bodies.push_back({n, false});
  layout.tube_bodies.assign(organism.tubes.size(), {-1, -1});
  std::vector<bool> connected(organism.nodes.size(), false);
  // rods first, between main bodies
  for (std::size_t t = 0; t < organism.tubes.size(); ++t) {
    const Tube& tube = organism.tubes[t];
    if (tube.kind != TubeKind::rod)
      continue;
    layout.joints.push_back({tube.a, tube.b, JointType::fixed, static_cast<int>(t)});
    layout.tube_bodies[t] = {tube.a, tube.b};
    connected[tube.a] = connected[tube.b] = true;
  }
  // then muscles: the first joint at a node on its main body, every later one on a proxy
  auto attach = [&](int node, int tube) {
    if (!connected[node]) {
      connected[node] = true;
      return node;
    }
    layout.bodies.push_back({node, true});
    const int proxy = static_cast<int>(layout.bodies.size()) - 1;
    layout.joints.push_back({node, proxy, JointType::spherical, tube});
    return proxy;
  };
  for (std::size_t t = 0; t < organism.tubes.size(); ++t) {
    const Tube& tube = organism.tubes[t];
    if (tube.kind != TubeKind::muscle)
      continue;
    const int a = attach(tube.a, static_cast<int>(t)), b = attach(tube.b, static_cast<int>(t));
    layout.joints.push_back({a, b, JointType::prismatic, static_cast<int>(t)});
    layout.tube_bodies[t] = {a, b};
  }
  return layout;
}

// the rotation that turns +x onto the unit vector `to`
Quat turnXOnto(Vec3 to) {
  const Vec3 x{1, 0, 0};
  const double c = dot(x, to);
  if (c < -1 + 1e-12)
    return {0, 0, 0, 1};  // half a turn about z
  const Vec3 axis = cross(x, to);
  const double w = 1 + c;
  const double n = std::sqrt(w * w + dot(axis, axis));
  return {w / n, axis.x / n, axis.y / n, axis.z / n};
}

// two unit vectors across the unit vector `along`, making a right-handed frame with it last
std::array<Vec3, 3> acrossFrame(Vec3 along) {
  const Vec3 helper = std::abs(along.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  Vec3 first = cross(helper, along);
  first = first * (1 / norm(first));
  return {first, cross(along, first), along};
}

// the unit vector from a tube's node a to its node b
Vec3 unitAlong(const Organism& organism, const Tube& tube) {
  const Vec3 along = organism.nodes[tube.b].position - organism.nodes[tube.a].position;
  return along * (1 / norm(along));
}

// a proxy's universal joint as a spherical joint whose middle axis, along the tube (`along`), is
// locked: the tube does not spin about itself on its node and swings freely about the two axes
// across it. Those are the first and last of Bullet's Euler angles, which turn without bound (a
// free middle angle, as JointType::universal has, stops at a quarter turn); in the frame of
// either body, both born unturned
void makeUniversal(Vec3 along, std::array<Vec3, 3>& axes, Vec3& limit) {
  const Vec3 across = acrossFrame(along)[0];
  axes = {across, along, cross(across, along)};
  limit = {kFree, 0, kFree};
}

// whether a muscle's length changes (A > 0 and f > 0); one that does not keeps its initial length
bool moves(const Muscle& muscle) {
  return muscle.amplitude > 0 && muscle.frequency > 0;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

BodyCounts countBodies(const Organism& organism) {
  const Layout layout = layOut(organism);
  BodyCounts counts;
  for (const Body& body : layout.bodies)
    (body.proxy ? counts.proxies : counts.main_bodies) += 1;
  for (const BodyJoint& joint : layout.joints) {
    counts.universal_joints += joint.type == JointType::spherical ? 1 : 0;
    counts.sliders += joint.type == JointType::prismatic ? 1 : 0;
    counts.fixed_joints += joint.type == JointType::fixed ? 1 : 0;
  }
  return counts;
}

Creature developOrganism(const Organism& organism, const BodySettings& settings) {
  const Layout layout = layOut(organism);
  const int body_count = static_cast<int>(layout.bodies.size());
  auto centre = [&](int body) { return organism.nodes[layout.bodies[body].node].position; };

  // the node's mass split evenly over its main body and its proxies
  std::vector<int> shares(organism.nodes.size(), 0);
  for (const Body& body : layout.bodies)
    ++shares[body.node];

  // a spanning tree holding every slider (they share no body, so they make no cycle), then the
  // universal joints, then the rods; the other joints close loops
  std::vector<int> order(layout.joints.size());
  std::iota(order.begin(), order.end(), 0);
  auto rank = [](JointType type) {
    return type == JointType::prismatic ? 0 : type == JointType::spherical ? 1 : 2;
  };
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    return rank(layout.joints[i].type) < rank(layout.joints[j].type);
  });
  std::vector<int> set(body_count);
  std::iota(set.begin(), set.end(), 0);
  std::vector<bool> in_tree(layout.joints.size(), false);
  for (int j : order) {
    const int ra = findRoot(set, layout.joints[j].a), rb = findRoot(set, layout.joints[j].b);
    if (ra != rb) {
      set[ra] = rb;
      in_tree[j] = true;
    }
  }

  // the parts in breadth-first order from node 0's main body, each joined to its parent by the
  // tree joint that reached it
  std::vector<int> part_of(body_count, -1), parent_joint(body_count, -1), bodies_in_order{0};
  part_of[0] = 0;
  for (std::size_t k = 0; k < bodies_in_order.size(); ++k) {
    const int body = bodies_in_order[k];
    for (std::size_t j = 0; j < layout.joints.size(); ++j) {
      const BodyJoint& joint = layout.joints[j];
      if (!in_tree[j] || (joint.a != body && joint.b != body))
        continue;
      const int other = joint.a == body ? joint.b : joint.a;
      if (part_of[other] >= 0)
        continue;
      part_of[other] = static_cast<int>(bodies_in_order.size());
      parent_joint[other] = static_cast<int>(j);
      bodies_in_order.push_back(other);
    }
  }

  // a slider's travel: as far as its muscle's sinusoid goes from the initial length either way,
  // and a margin (Bullet's slider stop brakes a joint that nears it; a muscle that does not move
  // is locked)
  auto travel = [&](const Tube& tube) {
    const double initial = initialLength(organism, tube);
    const Muscle& m = tube.muscle;
    const double range =
        std::max(m.rest_length + m.amplitude - initial, initial - (m.rest_length - m.amplitude));
    return m.amplitude > 0 ? range + kStopMargin : 0.0;
  };

  Creature creature;
  BodyPlan& plan = creature.body;
  const Vec3 origin = organism.nodes[0].position;
  for (int body : bodies_in_order) {
    const Node& node = organism.nodes[layout.bodies[body].node];
    PartPlan part;
    part.node = layout.bodies[body].node;
    part.shape = PartShape::sphere;
    part.size = {node.diameter, node.diameter, node.diameter};
    part.mass = node.mass / shares[layout.bodies[body].node];
    part.material.friction = settings.friction;
    part.pose.position = node.position - origin;
    part.solid = !layout.bodies[body].proxy;
    part.contact_group = layout.bodies[body].node;
    part.joint_damping = {0, 0, 0};
    if (parent_joint[body] >= 0) {
      const BodyJoint& joint = layout.joints[parent_joint[body]];
      const int parent = joint.a == body ? joint.b : joint.a;
      part.parent = part_of[parent];
      part.depth = plan.parts[part.parent].depth + 1;
      part.joint = joint.type;
      part.connection = parent_joint[body];
      const Vec3 apart = centre(body) - centre(parent);
      if (joint.type == JointType::prismatic) {
        // along the tube from the parent's node to this one: the travel is L - L_i
        part.pivot_in_parent = apart;
        part.axes = acrossFrame(apart * (1 / norm(apart)));
        std::rotate(part.axes.begin(), part.axes.begin() + 2, part.axes.end());
        part.joint_limit = {travel(organism.tubes[joint.tube]), 0, 0};
        part.strength = settings.muscle_force;
      } else if (joint.type == JointType::spherical) {
        makeUniversal(unitAlong(organism, organism.tubes[joint.tube]), part.axes, part.joint_limit);
      } else {
        part.pivot_in_parent = apart * 0.5;
        part.pivot_in_child = apart * -0.5;
      }
    }
    plan.parts.push_back(part);
  }

  // the joints outside the tree close loops
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    if (in_tree[j])
      continue;
    const BodyJoint& joint = layout.joints[j];
    LoopJoint loop;
    loop.part_a = part_of[joint.a];
    loop.part_b = part_of[joint.b];
    loop.joint = joint.type;
    const Vec3 apart = centre(joint.b) - centre(joint.a);
    loop.pivot_in_a = apart * 0.5;
    loop.pivot_in_b = apart * -0.5;
    if (joint.type == JointType::spherical)
      makeUniversal(unitAlong(organism, organism.tubes[joint.tube]), loop.axes, loop.joint_limit);
    plan.loops.push_back(loop);
  }

  // the capsules: a rod's from node a's centre to node b's, on node a's main body; a muscle's in
  // two halves, one on each of its bodies, from the node's centre towards the other node as far
  // as the muscle's shortest length allows without passing the other node's centre (the halves
  // overlap while the muscle is short; past twice its shortest length a gap opens between them)
  auto carry = [&](int body, Vec3 along, double reach, int tube_a, int tube_b) {
    ColliderPlan collider;
    collider.part = part_of[body];
    collider.shape = PartShape::capsule;
    collider.size = {reach + organism.tube_diameter, organism.tube_diameter,
                     organism.tube_diameter};
    collider.pose.position = along * (0.5 * reach);
    collider.pose.rotation = turnXOnto(along);
    collider.groups = {tube_a, tube_b};
    plan.colliders.push_back(collider);
  };
  for (std::size_t t = 0; t < organism.tubes.size(); ++t) {
    const Tube& tube = organism.tubes[t];
    const Vec3 along = unitAlong(organism, tube);
    const double length = initialLength(organism, tube);
    if (tube.kind == TubeKind::rod) {
      carry(tube.a, along, length, tube.a, tube.b);
      continue;
    }
    const Muscle& m = tube.muscle;
    const double shortest = moves(m) ? m.rest_length - m.amplitude : length;
    const double longest = moves(m) ? m.rest_length + m.amplitude : length;
    const double reach = std::min(shortest, 0.5 * longest);
    carry(layout.tube_bodies[t][0], along, reach, tube.a, tube.b);
    carry(layout.tube_bodies[t][1], along * -1.0, reach, tube.a, tube.b);
  }

  // a position effector per muscle on its slider, the child of the two bodies, and the
  // sinusoid that drives it: 0 commands the initial length, 1 the slider's whole travel
  auto sinusoids = std::make_shared<LengthSinusoidsPlan>();
  for (const BodyJoint& joint : layout.joints) {
    if (joint.type != JointType::prismatic)
      continue;
    const Tube& tube = organism.tubes[joint.tube];
    const double initial = initialLength(organism, tube);
    plan.effectors.push_back(
        {std::max(part_of[joint.a], part_of[joint.b]), 0, EffectorKind::position});
    LengthSinusoid sinusoid;
    sinusoid.middle = moves(tube.muscle) ? tube.muscle.rest_length : initial;
    sinusoid.amplitude = moves(tube.muscle) ? tube.muscle.amplitude : 0;
    sinusoid.angular_frequency = 2 * std::numbers::pi * tube.muscle.frequency;
    sinusoid.phase = musclePhase(tube.muscle, initial);
    sinusoid.zero = initial;
    sinusoid.scale = travel(tube);
    sinusoids->sinusoids.push_back(sinusoid);
  }
  creature.controller = std::move(sinusoids);
  return creature;
}

}  // namespace cambrian::springy
