// cambrian: a Walking with Dinosaurs creature as a body and its layered network.
#include "encodings/wwd/develop.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace cambrian::wwd {

namespace {

// the rotation by `angle` about unit axis `axis`
Quat axisAngle(Vec3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * axis.x, s * axis.y, s * axis.z};
}

// the shortest rotation taking unit vector `from` onto unit vector `to` (both along axes here);
// opposite vectors turn half about the next axis
Quat turnOnto(Vec3 from, Vec3 to, int from_axis) {
  const double d = dot(from, to);
  if (d > 1 - 1e-12)
    return {};
  if (d < -1 + 1e-12) {
    Vec3 across;
    across[(from_axis + 1) % 3] = 1;
    return {0, across.x, across.y, across.z};
  }
  const Vec3 c = cross(from, to);
  const double n = std::sqrt((1 + d) * (1 + d) + dot(c, c));
  return {(1 + d) / n, c.x / n, c.y / n, c.z / n};
}

Quat normalized(Quat q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// the area of a box's face across `axis`
double faceArea(Vec3 size, int axis) {
  return size[(axis + 1) % 3] * size[(axis + 2) % 3];
}

// a node with its input genes resolved over a previous layer of `previous` values and `sensors`
// sensors: indices modulo their count; a sensor node without sensors reads 0, inputs without a
// previous layer are left out (each function's missing-input default)
LayeredNode resolve(const NodeGenes& genes, int previous, int sensors) {
  LayeredNode node;
  node.function = genes.function;
  node.value = genes.value;
  if (genes.function == LayeredFunction::constant)
    return node;
  if (genes.function == LayeredFunction::sensor) {
    if (sensors == 0) {
      node.function = LayeredFunction::constant;
      node.value = 0;
      return node;
    }
    node.input_count = 1;
    node.inputs[0] = {genes.inputs[0] % sensors, genes.weights[0]};
    return node;
  }
  if (previous == 0)
    return node;
  node.input_count = genes.input_count;
  for (int i = 0; i < genes.input_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    node.inputs[k] = {genes.inputs[k] % previous, genes.weights[k]};
  }
  return node;
}

// a net's layers resolved, its first layer over `first_previous` values
LayeredNet resolve(const NetGenes& genes, int first_previous, int sensors) {
  LayeredNet net;
  int previous = first_previous;
  for (const auto& layer_genes : genes.layers) {
    std::vector<LayeredNode> layer;
    layer.reserve(layer_genes.size());
    for (const NodeGenes& node : layer_genes)
      layer.push_back(resolve(node, previous, sensors));
    previous = static_cast<int>(layer.size());
    net.layers.push_back(std::move(layer));
  }
  return net;
}

}  // namespace

FaceFrame faceFrame(Vec3 size, const FacePoint& point) {
  FaceFrame f;
  f.axis = point.side / 2;
  const double sign = point.side % 2 == 0 ? 1 : -1;
  const int u = (f.axis + 1) % 3, v = (f.axis + 2) % 3;
  f.normal[f.axis] = sign;
  f.point[f.axis] = sign * size[f.axis] / 2;
  f.point[u] = point.u * size[u] / 2;
  f.point[v] = point.v * size[v] / 2;
  return f;
}

Creature developCreature(const CreatureGenes& genes, const BodySettings& settings) {
  Creature creature;
  BodyPlan& plan = creature.body;
  plan.truncated = genes.truncated;

  // the boxes, each child turned so its POST face meets the parent's PRE face, then screwed
  // about the parent face's normal
  for (std::size_t i = 0; i < genes.boxes.size(); ++i) {
    const BoxGenes& box = genes.boxes[i];
    PartPlan part;
    part.node = static_cast<int>(i);
    part.size = box.size;
    part.mass = settings.density * box.size.x * box.size.y * box.size.z;
    part.material.density = settings.density;
    part.material.friction = settings.friction;
    if (i > 0) {
      const JointGenes& joint = genes.joints[i - 1];
      const PartPlan& parent = plan.parts[static_cast<std::size_t>(joint.parent)];
      const FaceFrame pre = faceFrame(parent.size, joint.pre);
      const FaceFrame post = faceFrame(box.size, joint.post);
      const Quat rotation = normalized(axisAngle(pre.normal, joint.screw) *
                                       turnOnto(post.normal, -pre.normal, post.axis));
      part.parent = joint.parent;
      part.connection = static_cast<int>(i - 1);
      part.depth = parent.depth + 1;
      part.joint = JointType::spherical;
      part.pivot_in_parent = pre.point;
      part.pivot_in_child = post.point;
      part.parent_to_child = rotation;
      for (int k = 0; k < 3; ++k) {
        Vec3 axis;
        axis[(post.axis + 1 + k) % 3] = 1;
        part.axes[static_cast<std::size_t>(k)] = axis;
      }
      part.joint_limit = joint.limit;
      part.cross_section = std::min(faceArea(parent.size, pre.axis), faceArea(box.size, post.axis));
      part.strength = settings.strength_per_area * part.cross_section;
      const Transform local{pre.point - rotate(rotation, post.point), rotation};
      part.pose = compose(parent.pose, local);
      part.pose.rotation = normalized(part.pose.rotation);
    }
    plan.parts.push_back(part);
  }

  // sensors: each box's pressure sensor, then its joint's three angles; effectors: three a joint
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const int part = static_cast<int>(i);
    if (genes.boxes[i].pressure_sensor)
      plan.sensors.push_back({SensorKind::contact, part, 0});
    if (i > 0) {
      for (int axis = 0; axis < 3; ++axis) {
        plan.sensors.push_back({SensorKind::joint_angle, part, axis});
        plan.effectors.push_back({part, axis, EffectorKind::joint});
      }
    }
  }

  // the network: the main net over the sensors, each joint's subnet over the main net's last
  // layer, each joint's muscles on three nodes of its subnet's last layer
  auto network = std::make_shared<LayeredNetworkPlan>();
  const int sensors = static_cast<int>(plan.sensors.size());
  network->sensor_count = plan.sensors.size();
  network->main = resolve(genes.main, sensors, sensors);
  const int main_outputs = static_cast<int>(network->main.layers.back().size());
  for (std::size_t j = 0; j < genes.joints.size(); ++j) {
    const JointGenes& joint = genes.joints[j];
    network->subnets.push_back(resolve(joint.subnet, main_outputs, sensors));
    const int outputs = static_cast<int>(network->subnets.back().layers.back().size());
    LayeredMuscles muscles;
    muscles.subnet = static_cast<int>(j);
    for (int k = 0; k < 3; ++k)
      muscles.nodes[static_cast<std::size_t>(k)] =
          joint.effector[static_cast<std::size_t>(k)] % outputs;
    muscles.strength = plan.parts[j + 1].strength;
    network->joints.push_back(muscles);
  }
  creature.controller = std::move(network);
  return creature;
}

}  // namespace cambrian::wwd
