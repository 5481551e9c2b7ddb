// cambrian: BodyPlan, the immutable developed creature — the one meeting point between genome
// encodings and physics. No Bullet here.
#pragma once

#include "cambrian/genome.hpp"
#include "cambrian/math.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cambrian {

/// One weighted wire into a neuron or effector: value = weight * signal[signal], or the weight
/// itself when signal < 0 (a constant).
struct Wire {
  int signal = -1;
  double weight = 0;
  friend bool operator==(const Wire&, const Wire&) = default;
};

/// One part instance and the joint that ties it to its parent.
struct PartPlan {
  int node = 0;                        ///< genome node it is an instance of
  int parent = -1;                     ///< index of the parent part, -1 for the root
  int connection = -1;                 ///< genome connection that made it, -1 for the root
  int depth = 0;                       ///< root = 0
  Vec3 size;                           ///< full box size, metres
  double mass = 0;                     ///< kg
  Transform pose;                      ///< pose at birth in the creature frame (root at the origin)
  JointType joint = JointType::rigid;  ///< to the parent
  Vec3 pivot_in_parent;                ///< joint point in the parent's frame
  Vec3 pivot_in_child;                 ///< joint point in this part's frame
  Quat parent_to_child;                ///< this part's frame relative to the parent's frame
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  ///< in this part's frame
  Vec3 joint_limit;          ///< symmetric limit per degree of freedom, radians
  double cross_section = 0;  ///< m^2, smaller of the two faces meeting at the joint; physics
                             ///< turns it into the joint's maximum torque
  bool reflected = false;    ///< made through a reflected connection
};

/// What a sensor reads. Values are written by physics into the signal array each step.
enum class SensorKind : std::uint8_t {
  joint_angle,  ///< angle of degree of freedom `axis` of the joint to the parent, radians / limit
  contact,      ///< 1 if the part touches anything, else 0
  photo,        ///< component `axis` of the unit direction to the target in the part's frame
};

struct SensorPlan {
  SensorKind kind = SensorKind::contact;
  int part = 0;
  int axis = 0;
};

/// A neuron instance: function, parameter and up to three input wires.
struct NeuronPlan {
  NeuronFunction function = NeuronFunction::sum;
  double parameter = 0;
  int part = -1;  ///< owning part, -1 for a brain neuron
  std::array<Wire, 3> inputs{};
};

/// Drives one degree of freedom: torque = strength * clamp(input + oscillator, -1, 1).
struct EffectorPlan {
  int part = 0;
  int dof = 0;
  Wire input;
  JointControllerGene oscillator;  ///< Minemonics per-joint controller (disabled = none)
};

/// The developed creature. Signal array layout: sensors first, then neurons.
struct BodyPlan {
  std::vector<PartPlan> parts;  ///< parents always precede children
  std::vector<SensorPlan> sensors;
  std::vector<NeuronPlan> neurons;
  std::vector<EffectorPlan> effectors;
  bool truncated = false;  ///< development stopped at GenomeLimits::max_parts

  int signalCount() const { return static_cast<int>(sensors.size() + neurons.size()); }
  int neuronSignal(int neuron) const { return static_cast<int>(sensors.size()) + neuron; }
  int jointCount() const { return parts.empty() ? 0 : static_cast<int>(parts.size()) - 1; }
  int degreesOfFreedom() const;
  double totalMass() const;
  double totalVolume() const;
};

/// Develops a genome (embryogenesis): walks the graph from node 0 with recursive limits,
/// reflections and scaling; instantiates sensors, neurons and effectors and wires them as
/// Sims describes. Deterministic. Sizes are clamped to limits; development stops at
/// limits.max_parts parts (breadth-first), setting `truncated`.
BodyPlan develop(const Genome& genome, const GenomeLimits& limits);

}  // namespace cambrian
