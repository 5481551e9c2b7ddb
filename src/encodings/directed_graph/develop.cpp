// cambrian: embryogenesis — walks the directed-graph genome from the root node and makes the
// BodyPlan: parts and joints (recursion, terminal-only connections, reflection, scaling), then
// sensors, neurons and effectors wired as Sims describes. See docs/development-and-brain.md.
#include "cambrian/body_plan.hpp"
#include "cambrian/error.hpp"
#include "cambrian/math.hpp"

#include "brain/controller_sum.hpp"
#include "brain/sine_oscillators.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace cambrian::graph {
namespace {

// a reflection bit whose position component is smaller than this makes no copy
constexpr double kReflectionEpsilon = 1e-9;
// the axis across which a handed (mirror-image) part's own frame is reflected
constexpr int kHandedAxis = 1;

// what development needs to know about a part instance beyond its PartPlan
struct Instance {
  std::vector<int> path_counts;  // instances of each node on the path root..this, inclusive
  double scale = 1;              // product of connection scales along the path
  bool handed = false;           // this part's frame is a mirror image of the original's
};

// the unit quaternion of a half turn about axis k (a reflection across plane k, up to sign)
Quat halfTurn(int k) {
  if (k == 0) {
    return {0, 1, 0, 0};
  }
  return k == 1 ? Quat{0, 0, 1, 0} : Quat{0, 0, 0, 1};
}

// rotation taking +x onto the outward normal of face (axis k, sign s)
Quat faceRotation(int k, double s) {
  const double h = std::sqrt(0.5);
  if (k == 0) {
    return s > 0 ? Quat{1, 0, 0, 0} : Quat{0, 0, 0, 1};
  }
  if (k == 1) {
    return s > 0 ? Quat{h, 0, 0, h} : Quat{h, 0, 0, -h};
  }
  return s > 0 ? Quat{h, 0, -h, 0} : Quat{h, 0, h, 0};
}

// rotation taking +x onto the unit vector n: a box face's normal exactly as faceRotation
Quat rotationFromXTo(Vec3 n) {
  for (int k = 0; k < 3; ++k) {
    if (std::fabs(n[k]) == 1)
      return faceRotation(k, n[k]);
  }
  // half way between +x and n: (1 + x.n, x cross n), normalised
  const double w = 1 + n.x, length = std::sqrt(w * w + n.y * n.y + n.z * n.z);
  return {w / length, 0, -n.z / length, n.y / length};
}

// scales a quaternion back to unit length (it drifts when products compound along a path)
Quat normalized(Quat q) {
  double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// mass of a part: a box's as it always was, other shapes by their volume
double partMass(PartShape shape, Vec3 size, double density) {
  if (shape == PartShape::box)
    return density * size.x * size.y * size.z;
  return density * shapeVolume(shape, size);
}

// the part's own material: its density and the morphogene's friction and restitution
Material materialOf(const PartGene& node) {
  Material material;
  material.density = node.density;
  material.friction = node.friction;
  material.restitution = node.restitution;
  return material;
}

// one instance a connection makes: Sims' mirror copies (bit k: across the parent's plane k) and
// Minemonics' flipped copy (a half turn about the parent's x axis)
struct Copy {
  int mirror = 0;
  bool flipped = false;
};

// where a catapult's arm (the root, of `arm`'s size) holds the projectile: the position pushed
// to the arm's surface, the block against that face, aligned with the arm
HeldObject heldProjectile(const ProjectileGene& gene, const PartPlan& arm,
                          const GenomeLimits& limits) {
  HeldObject held;
  held.part = 0;
  held.shape = PartShape::box;
  for (int k = 0; k < 3; ++k)
    held.size[k] = std::clamp(gene.dimensions[k], limits.min_part_size, limits.max_part_size);
  held.mass = gene.density * held.size.x * held.size.y * held.size.z;
  held.material.density = gene.density;
  Vec3 p = gene.position;
  const int k = dominantAxis(p);
  const double face_sign = p[k] < 0 ? -1.0 : 1.0;
  p[k] = face_sign;
  Vec3 centre = hadamard(p, arm.size * 0.5);
  centre[k] += face_sign * 0.5 * held.size[k];
  held.pose = Transform{centre, Quat{1, 0, 0, 0}};
  return held;
}

// structural checks that development itself needs (validateGenome checks the rest)
void checkGenome(const Genome& genome, const GenomeLimits& limits) {
  if (genome.nodes.empty()) {
    throw GenomeError("develop: genome.nodes is empty (a genome needs a root node 0)");
  }
  const std::size_t nodes = genome.nodes.size();
  for (std::size_t c = 0; c < genome.connections.size(); ++c) {
    const ConnectionGene& connection = genome.connections[c];
    if (connection.from >= nodes || connection.to >= nodes) {
      throw GenomeError("develop: connections[" + std::to_string(c) +
                        "] from = " + std::to_string(connection.from) +
                        ", to = " + std::to_string(connection.to) + " out of range (" +
                        std::to_string(nodes) + " nodes)");
    }
  }
  if (limits.max_parts < 1) {
    throw ConfigError("develop: limits.max_parts = " + std::to_string(limits.max_parts) +
                      " must be >= 1");
  }
  if (!(limits.min_part_size > 0) || !(limits.min_part_size <= limits.max_part_size)) {
    throw ConfigError("develop: limits.min_part_size = " + std::to_string(limits.min_part_size) +
                      ", max_part_size = " + std::to_string(limits.max_part_size) +
                      " must satisfy 0 < min <= max");
  }
}

// node dimensions times the path scale, each side clamped to the limits
Vec3 partSize(const PartGene& node, double scale, const GenomeLimits& limits) {
  Vec3 size = node.dimensions * scale;
  for (int k = 0; k < 3; ++k) {
    size[k] = std::clamp(size[k], limits.min_part_size, limits.max_part_size);
  }
  return size;
}

// the parts and joints of the creature, breadth-first
class Embryo {
 public:
  Embryo(const Genome& genome, const GenomeLimits& limits)
      : genome_(genome), limits_(limits), outgoing_(genome.nodes.size()) {
    // connections leaving each node, in genome order
    for (std::size_t c = 0; c < genome.connections.size(); ++c) {
      outgoing_[genome.connections[c].from].push_back(static_cast<int>(c));
    }
  }

  // grows the body into plan.parts; returns first_child[part][connection] (-1 = none)
  std::vector<std::vector<int>> grow(BodyPlan& plan) {
    // the root: node 0, identity pose at the origin, rigid joint
    PartPlan root;
    root.node = 0;
    root.size = partSize(genome_.nodes[0], 1.0, limits_);
    root.shape = genome_.nodes[0].shape;
    root.mass = partMass(root.shape, root.size, genome_.nodes[0].density);
    root.material = materialOf(genome_.nodes[0]);
    root.joint = JointType::fixed;
    root.axes = jointAxes(false);
    plan.parts.push_back(root);
    Instance root_instance;
    root_instance.path_counts.assign(genome_.nodes.size(), 0);
    root_instance.path_counts[0] = 1;
    instances_.push_back(root_instance);
    first_child_.emplace_back(genome_.connections.size(), -1);

    // parents precede children: expanding parts in index order is breadth-first
    for (std::size_t i = 0; i < plan.parts.size() && !plan.truncated; ++i) {
      expand(plan, static_cast<int>(i));
    }
    return std::move(first_child_);
  }

 private:
  // joint axes in the child's frame, per degree of freedom: y, z, x (twist); a handed part's
  // axes are mirrored so the same command makes the mirror-image motion
  static std::array<Vec3, 3> jointAxes(bool handed) {
    if (handed) {
      return {Vec3{0, 1, 0}, Vec3{0, 0, -1}, Vec3{-1, 0, 0}};
    }
    return {Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 0}};
  }

  // follows every applicable connection leaving part `index`
  void expand(BodyPlan& plan, int index) {
    const int node = plan.parts[index].node;
    for (int c : outgoing_[node]) {
      const ConnectionGene& connection = genome_.connections[c];
      const Instance& here = instances_[index];
      // the recursive limit of the child's node along this path
      const int to_limit =
          std::max(1, static_cast<int>(genome_.nodes[connection.to].recursive_limit));
      if (here.path_counts[connection.to] >= to_limit) {
        continue;
      }
      // terminal-only connections apply only at the last repetition of `from`
      const int from_limit = std::max(1, static_cast<int>(genome_.nodes[node].recursive_limit));
      if (connection.terminal_only && here.path_counts[node] != from_limit) {
        continue;
      }
      // one child per combination of the effective reflection bits, the original first, then
      // Minemonics' flipped and mirrored copies
      int bits = 0;
      for (int k = 0; k < 3; ++k) {
        if (((connection.reflection >> k) & 1) &&
            std::fabs(connection.position[k]) >= kReflectionEpsilon) {
          bits |= 1 << k;
        }
      }
      std::vector<Copy> copies;
      for (int mirror = 0; mirror < 8; ++mirror) {
        if ((mirror & ~bits) == 0)
          copies.push_back(Copy{mirror, false});
      }
      const PartPlan& up = plan.parts[index];
      const Vec3 at = surfacePoint(up.shape, up.size, connection.position).point;
      // a half turn about x leaves a point on the x axis where it was: no copy
      if (connection.flip &&
          (std::fabs(at.y) >= kReflectionEpsilon || std::fabs(at.z) >= kReflectionEpsilon))
        copies.push_back(Copy{0, true});
      if (connection.mirror && bits != 7)
        copies.push_back(Copy{7, false});
      for (const Copy& copy : copies) {
        if (static_cast<int>(plan.parts.size()) >= limits_.max_parts) {
          plan.truncated = true;
          return;
        }
        addChild(plan, index, c, copy);
      }
    }
  }

  // makes one child of part `parent` through connection c as `copy` says
  void addChild(BodyPlan& plan, int parent, int c, Copy copy) {
    const ConnectionGene& connection = genome_.connections[c];
    const PartGene& node = genome_.nodes[connection.to];
    const PartPlan& up = plan.parts[parent];
    const Instance& up_instance = instances_[parent];

    // all reflections in the parent's frame: this copy's plus the parent's own handedness
    const int reflect = copy.mirror ^ (up_instance.handed ? 1 << kHandedAxis : 0);

    // attachment on the parent's surface, in the frame whose x axis is the outward normal there;
    // a flipped copy turned a half turn about the parent's x axis, then the mirrors
    const SurfacePoint at = surfacePoint(up.shape, up.size, connection.position);
    Vec3 pivot = at.point;
    Quat rotation = rotationFromXTo(at.normal) * quatFromEuler(connection.orientation);
    if (copy.flipped) {
      pivot.y = -pivot.y;
      pivot.z = -pivot.z;
      rotation = halfTurn(0) * rotation;
    }
    Quat reflection{1, 0, 0, 0};
    int flips = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if ((reflect >> axis) & 1) {
        pivot[axis] = -pivot[axis];
        reflection = reflection * halfTurn(axis);
        ++flips;
      }
    }

    // the child's size, and its anchor: the point of its surface that meets the parent, turned
    // to face it (the default anchor, -x, needs no turn)
    Instance instance;
    instance.path_counts = up_instance.path_counts;
    instance.path_counts[connection.to] += 1;
    instance.scale = up_instance.scale * connection.scale * genome_.nodes[up.node].segment_shrink;
    const Vec3 size = partSize(node, instance.scale, limits_);
    SurfacePoint anchor = surfacePoint(node.shape, size, node.anchor);
    Quat turn{1, 0, 0, 0};
    const bool turned = anchor.normal != Vec3{-1, 0, 0};
    if (turned) {
      turn = conjugate(rotationFromXTo(anchor.normal * -1.0));
      rotation = rotation * turn;
    }

    // an odd number of mirrors is not a rotation: reflect the child's own frame too
    const bool handed = flips % 2 == 1;
    rotation = reflection * rotation;
    if (handed) {
      rotation = rotation * halfTurn(kHandedAxis);
      if (anchor.point.y != 0)
        anchor.point.y = -anchor.point.y;
    }
    // the joint's axes: those of the attachment frame, in the child's (mirrored when handed)
    std::array<Vec3, 3> axes = jointAxes(handed);
    if (turned) {
      axes = jointAxes(false);
      for (Vec3& axis : axes) {
        axis = rotate(conjugate(turn), axis);
        if (handed)
          axis = Vec3{-axis.x, axis.y, -axis.z};
      }
    }
    rotation = normalized(rotation);
    instance.handed = handed;

    // the child, its joint and its pose
    PartPlan part;
    part.node = connection.to;
    part.parent = parent;
    part.connection = c;
    part.depth = up.depth + 1;
    part.size = size;
    part.shape = node.shape;
    part.mass = partMass(node.shape, part.size, node.density);
    part.material = materialOf(node);
    part.joint = node.joint_type;
    part.pivot_in_parent = pivot;
    part.pivot_in_child = anchor.point;
    part.parent_to_child = rotation;
    part.axes = axes;
    part.joint_limit = node.joint_limit;
    part.joint_damping = node.joint_damping;
    const double parent_face = sectionArea(up.shape, up.size, dominantAxis(at.normal));
    const double child_face = sectionArea(node.shape, part.size, dominantAxis(anchor.normal));
    part.cross_section = limits_.strength_section == StrengthSection::larger
                             ? std::max(parent_face, child_face)
                             : std::min(parent_face, child_face);
    part.reflected = copy.mirror != 0 || copy.flipped;
    const Transform local{part.pivot_in_parent - rotate(rotation, part.pivot_in_child), rotation};
    part.pose = compose(up.pose, local);
    part.pose.rotation = normalized(part.pose.rotation);

    // the first instance through each connection is the one child_neuron inputs read
    const int index = static_cast<int>(plan.parts.size());
    if (first_child_[parent][c] < 0) {
      first_child_[parent][c] = index;
    }
    plan.parts.push_back(part);
    instances_.push_back(std::move(instance));
    first_child_.emplace_back(genome_.connections.size(), -1);
  }

  const Genome& genome_;
  const GenomeLimits& limits_;
  std::vector<std::vector<int>> outgoing_;
  std::vector<Instance> instances_;
  std::vector<std::vector<int>> first_child_;
};

// index ranges of the sensors and neurons each part instance owns
struct Ranges {
  std::vector<int> sensor_first, sensor_count, neuron_first, neuron_count;
  int photo_first = 0;
  int brain_first = 0, brain_count = 0;
};

// resolves genome inputs to wires over the BodyPlan's signal layout
class Wiring {
 public:
  Wiring(const Genome& genome, const BodyPlan& plan, const Ranges& ranges,
         const std::vector<std::vector<int>>& first_child)
      : genome_(genome), plan_(plan), ranges_(ranges), first_child_(first_child) {}

  // an input of a neuron or effector of part instance `part`
  Wire partInput(const NeuronInput& input, int part) const {
    const int node = plan_.parts[part].node;
    switch (input.source) {
      case SignalSource::constant:
        return Wire{-1, input.weight};
      case SignalSource::local_sensor:
        return sensor(ranges_.sensor_first[part], ranges_.sensor_count[part], input);
      case SignalSource::local_neuron:
        return neuron(ranges_.neuron_first[part], ranges_.neuron_count[part], input);
      case SignalSource::parent_neuron: {
        const int parent = plan_.parts[part].parent;
        if (parent < 0) {
          return Wire{};
        }
        return neuron(ranges_.neuron_first[parent], ranges_.neuron_count[parent], input);
      }
      case SignalSource::child_neuron: {
        const int child = childOf(part, node, input.slot);
        if (child < 0) {
          return Wire{};
        }
        return neuron(ranges_.neuron_first[child], ranges_.neuron_count[child], input);
      }
      case SignalSource::brain_neuron:
        return neuron(ranges_.brain_first, ranges_.brain_count, input);
      case SignalSource::brain_sensor:
        return sensor(ranges_.photo_first, 3, input);
    }
    return Wire{};
  }

  // an input of a brain neuron: sensors are the creature's, neighbours are the root's
  Wire brainInput(const NeuronInput& input) const {
    switch (input.source) {
      case SignalSource::constant:
        return Wire{-1, input.weight};
      case SignalSource::local_sensor:
        return sensor(0, static_cast<int>(plan_.sensors.size()), input);
      case SignalSource::local_neuron:
      case SignalSource::brain_neuron:
        return neuron(ranges_.brain_first, ranges_.brain_count, input);
      case SignalSource::parent_neuron:
      case SignalSource::child_neuron:
        return neuron(ranges_.neuron_first[0], ranges_.neuron_count[0], input);
      case SignalSource::brain_sensor:
        return sensor(ranges_.photo_first, 3, input);
    }
    return Wire{};
  }

 private:
  // the first child instance made through the slot-th connection leaving `node`, or -1
  int childOf(int part, int node, int slot) const {
    int leaving = 0;
    for (const ConnectionGene& connection : genome_.connections) {
      leaving += connection.from == node ? 1 : 0;
    }
    if (leaving == 0) {
      return -1;
    }
    int wanted = slot % leaving;
    for (std::size_t c = 0; c < genome_.connections.size(); ++c) {
      if (genome_.connections[c].from != node) {
        continue;
      }
      if (wanted-- == 0) {
        return first_child_[part][c];
      }
    }
    return -1;
  }

  // wire to sensor first + index mod count (constant 0 when there is none)
  static Wire sensor(int first, int count, const NeuronInput& input) {
    if (count <= 0) {
      return Wire{};
    }
    return Wire{first + input.index % count, input.weight};
  }

  // wire to neuron first + index mod count (constant 0 when there is none)
  Wire neuron(int first, int count, const NeuronInput& input) const {
    if (count <= 0) {
      return Wire{};
    }
    return Wire{static_cast<int>(plan_.sensors.size()) + first + input.index % count, input.weight};
  }

  const Genome& genome_;
  const BodyPlan& plan_;
  const Ranges& ranges_;
  const std::vector<std::vector<int>>& first_child_;
};

// copies a neuron gene's function and parameter; inputs are wired afterwards
NeuronPlan neuronFrom(const NeuronGene& gene, int part) {
  NeuronPlan neuron;
  neuron.function = gene.function;
  neuron.parameter = gene.parameter;
  neuron.part = part;
  return neuron;
}

// the used inputs of a gene: the first neuronArity() of them, missing ones constant 0
template <typename Resolve>
void wireNeuron(NeuronPlan& neuron, const NeuronGene& gene, Resolve resolve) {
  const int arity = std::min(neuronArity(gene.function), 3);
  for (int i = 0; i < arity; ++i) {
    if (i < static_cast<int>(gene.inputs.size())) {
      neuron.inputs[i] = resolve(gene.inputs[i]);
    }
  }
}

}  // namespace

int dominantAxis(Vec3 p) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::fabs(p[i]) > std::fabs(p[k])) {
      k = i;
    }
  }
  return k;
}

Creature develop(const Genome& genome, const GenomeLimits& limits) {
  checkGenome(genome, limits);
  Creature creature;
  BodyPlan& plan = creature.body;
  auto network = std::make_shared<NeuralNetworkPlan>();
  if (limits.neuron_set == NeuronSet::chaumont)
    network->signal_bound = 1;  // Chaumont et al.: every signal within [-1, 1]
  std::vector<NeuronPlan>& neurons = network->neurons;

  // parts and joints
  Embryo embryo(genome, limits);
  const std::vector<std::vector<int>> first_child = embryo.grow(plan);
  const int part_count = static_cast<int>(plan.parts.size());

  // sensors: per part its joint angles, its contact (or six, one per face) and, with
  // photosensors on every part (or on this photosensitive one), its three photo sensors; then
  // the creature's three photo sensors
  Ranges ranges;
  ranges.sensor_first.resize(part_count);
  ranges.sensor_count.resize(part_count);
  for (int i = 0; i < part_count; ++i) {
    ranges.sensor_first[i] = static_cast<int>(plan.sensors.size());
    for (int d = 0; d < degreesOfFreedom(plan.parts[i].joint); ++d) {
      plan.sensors.push_back(SensorPlan{SensorKind::joint_angle, i, d});
    }
    if (limits.contact_sensors == ContactSensors::per_face) {
      for (int face = 0; face < 6; ++face)
        plan.sensors.push_back(SensorPlan{SensorKind::contact_face, i, face});
    } else {
      plan.sensors.push_back(SensorPlan{SensorKind::contact, i, 0});
    }
    const bool photosensitive = limits.photosensors == Photosensors::every_part ||
                                (limits.photosensors == Photosensors::chosen &&
                                 genome.nodes[plan.parts[i].node].photosensitive);
    if (photosensitive) {
      for (int axis = 0; axis < 3; ++axis)
        plan.sensors.push_back(SensorPlan{SensorKind::photo, i, axis});
    }
    ranges.sensor_count[i] = static_cast<int>(plan.sensors.size()) - ranges.sensor_first[i];
  }
  ranges.photo_first = static_cast<int>(plan.sensors.size());
  for (int axis = 0; axis < 3; ++axis) {
    plan.sensors.push_back(SensorPlan{SensorKind::photo, 0, axis});
  }

  // neurons: each part copies its node's neurons, then the brain's neurons once
  ranges.neuron_first.resize(part_count);
  ranges.neuron_count.resize(part_count);
  for (int i = 0; i < part_count; ++i) {
    const PartGene& node = genome.nodes[plan.parts[i].node];
    ranges.neuron_first[i] = static_cast<int>(neurons.size());
    ranges.neuron_count[i] = static_cast<int>(node.neurons.size());
    for (const NeuronGene& gene : node.neurons) {
      neurons.push_back(neuronFrom(gene, i));
    }
  }
  ranges.brain_first = static_cast<int>(neurons.size());
  ranges.brain_count = static_cast<int>(genome.brain.size());
  for (const NeuronGene& gene : genome.brain) {
    neurons.push_back(neuronFrom(gene, -1));
  }

  // wiring of the neurons
  const Wiring wiring(genome, plan, ranges, first_child);
  for (int i = 0; i < part_count; ++i) {
    const PartGene& node = genome.nodes[plan.parts[i].node];
    for (int n = 0; n < ranges.neuron_count[i]; ++n) {
      wireNeuron(neurons[ranges.neuron_first[i] + n], node.neurons[n],
                 [&](const NeuronInput& input) { return wiring.partInput(input, i); });
    }
  }
  for (int n = 0; n < ranges.brain_count; ++n) {
    wireNeuron(neurons[ranges.brain_first + n], genome.brain[n],
               [&](const NeuronInput& input) { return wiring.brainInput(input); });
  }

  // effectors: one per driven degree of freedom of each non-root joint, each with its wire and
  // the oscillator of the connection that made the part
  std::vector<SineOscillator> oscillators;
  std::vector<ChuaOscillator> chaotic_oscillators;
  bool any_oscillator = false, any_chaotic = false;
  for (int i = 1; i < part_count; ++i) {
    const PartPlan& part = plan.parts[i];
    const PartGene& node = genome.nodes[part.node];
    const int driven =
        std::min(degreesOfFreedom(part.joint), static_cast<int>(node.effectors.size()));
    for (int d = 0; d < driven; ++d) {
      plan.effectors.push_back(EffectorPlan{i, d});
      network->effector_inputs.push_back(wiring.partInput(node.effectors[d].input, i));
      const JointControllerGene& gene = genome.connections[part.connection].controller;
      const bool chaotic = gene.kind == JointControllerKind::chaotic;
      oscillators.push_back(SineOscillator{gene.enabled && !chaotic, gene.amplitude, gene.frequency,
                                           gene.phase, gene.offset});
      chaotic_oscillators.push_back(ChuaOscillator{gene.enabled && chaotic, gene.amplitude,
                                                   gene.offset, gene.chua_start, gene.chua_speed});
      any_oscillator = any_oscillator || (gene.enabled && !chaotic);
      any_chaotic = any_chaotic || (gene.enabled && chaotic);
    }
  }

  // a catapult: the arm (the root) holds the projectile, and Chaumont et al.'s four-unit
  // mechanism (their Figure 4) lets go of it: a constant, a delay, the larger of the delay and
  // the network's trigger, and the release effector. The delay's output reaches the effector
  // two steps after its own, so the projectile goes at the latest on controller step
  // release_delay, earlier when the trigger passes kReleaseCommand.
  if (genome.projectile) {
    plan.held.push_back(heldProjectile(*genome.projectile, plan.parts[0], limits));
    auto signal = [&plan](std::size_t neuron) {
      return static_cast<int>(plan.sensors.size() + neuron);
    };
    NeuronPlan constant{NeuronFunction::constant, 1.0, 0, {}};
    NeuronPlan delay{
        NeuronFunction::delay, static_cast<double>(std::max(1, limits.release_delay - 2)), 0, {}};
    NeuronPlan larger{NeuronFunction::max, 0.0, 0, {}};
    delay.inputs[0] = Wire{signal(neurons.size()), 1.0};
    larger.inputs[0] = Wire{signal(neurons.size() + 1), 1.0};
    larger.inputs[1] = wiring.partInput(genome.projectile->trigger, 0);
    neurons.push_back(constant);
    neurons.push_back(delay);
    neurons.push_back(larger);
    plan.effectors.push_back(EffectorPlan{0, 0, EffectorKind::release});
    network->effector_inputs.push_back(Wire{signal(neurons.size() - 1), 1.0});
    oscillators.push_back(SineOscillator{});
    chaotic_oscillators.push_back(ChuaOscillator{});
  }

  // the network drives the effectors; the sine and the chaotic joint oscillators, those of each
  // kind that has one on, add to it in that order
  network->sensor_count = plan.sensors.size();
  if (!any_oscillator && !any_chaotic) {
    creature.controller = std::move(network);
    return creature;
  }
  auto sum = std::make_shared<ControllerSumPlan>();
  sum->parts = {std::move(network)};
  if (any_oscillator) {
    auto sine = std::make_shared<SineOscillatorsPlan>();
    sine->oscillators = std::move(oscillators);
    sum->parts.push_back(std::move(sine));
  }
  if (any_chaotic) {
    auto chua = std::make_shared<ChuaOscillatorsPlan>();
    chua->oscillators = std::move(chaotic_oscillators);
    chua->circuit = limits.chua;
    sum->parts.push_back(std::move(chua));
  }
  creature.controller = std::move(sum);
  return creature;
}

}  // namespace cambrian::graph
