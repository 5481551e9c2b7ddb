// cambrian: the fixed ranges of genome fields (those not set by GenomeLimits), shared by
// generation, validation, repair and mutation so that they always agree.
#pragma once

#include "cambrian/math.hpp"

#include "encodings/directed_graph/genome.hpp"

#include <cstdint>
#include <span>

namespace cambrian::graph {

/// Connection.position components lie in [-kPositionBound, kPositionBound].
constexpr double kPositionBound = 1.0;
/// Connection.orientation components lie in [-kOrientationBound, kOrientationBound] radians.
constexpr double kOrientationBound = kPi;
/// PartGene.joint_limit components lie in [0, kJointLimitMax] radians.
constexpr double kJointLimitMax = kPi;
/// NeuronGene.parameter lies in [-kNeuronParameterBound, kNeuronParameterBound].
constexpr double kNeuronParameterBound = 10.0;
/// At most this many effectors per node (one per degree of freedom of a spherical joint).
constexpr int kMaxEffectors = 3;
/// JointControllerGene.amplitude lies in [0, kControllerAmplitudeMax].
constexpr double kControllerAmplitudeMax = 1.0;
/// JointControllerGene.offset lies in [-kControllerOffsetBound, kControllerOffsetBound].
constexpr double kControllerOffsetBound = 1.0;
/// JointControllerGene.phase lies in [-kControllerPhaseBound, kControllerPhaseBound] radians.
constexpr double kControllerPhaseBound = kPi;
/// JointControllerGene.chua_start components lie in [-kChuaStartBound, kChuaStartBound]
/// (Minemonics' initial conditions).
constexpr double kChuaStartBound = 0.5;
/// JointControllerGene.chua_speed lies in [kChuaSpeedMin, kChuaSpeedMax] (Minemonics' range).
constexpr double kChuaSpeedMin = 0.001;
/// The highest chua_speed.
constexpr double kChuaSpeedMax = 10.0;
/// PartGene.restitution's value for "the world's restitution" (physics.restitution).
constexpr double kWorldRestitution = -1;
/// PartGene.joint_damping's value for "the world's damping" (physics.joint_damping).
constexpr double kWorldDamping = -1;
/// ConnectionGene.reflection may only use these bits (mirror x, y, z).
constexpr std::uint8_t kReflectionMask = 0x7;

/// Number of values of each enumeration.
constexpr int kPartShapeCount = 2;  // box, capsule
/// Number of JointType values.
constexpr int kJointTypeCount = 4;
/// The joint types' names in the text form and in genome.joint_types, by JointType value.
inline constexpr const char* kJointNames[] = {"rigid", "revolute", "universal", "spherical"};
/// Every joint type allowed (GenomeLimits::joint_types).
constexpr std::uint8_t kAllJointTypes = (1u << kJointTypeCount) - 1;

/// Whether `type` is among the joint types `limits` allows.
inline bool jointTypeAllowed(const GenomeLimits& limits, JointType type) {
  const auto value = static_cast<unsigned>(type);
  return value < kJointTypeCount && (limits.joint_types >> value & 1u) != 0;
}
/// How many joint types `limits` allows (at least one).
inline int allowedJointTypeCount(const GenomeLimits& limits) {
  int count = 0;
  for (int t = 0; t < kJointTypeCount; ++t)
    count += limits.joint_types >> t & 1;
  return count;
}
/// The `index`-th allowed joint type (index < allowedJointTypeCount), in JointType order: with
/// every type allowed, JointType(index), so draws over all types are unchanged.
inline JointType allowedJointType(const GenomeLimits& limits, std::uint64_t index) {
  for (int t = 0; t < kJointTypeCount; ++t) {
    if ((limits.joint_types >> t & 1) && index-- == 0)
      return static_cast<JointType>(t);
  }
  return JointType::fixed;
}

/// Number of NeuronFunction values.
constexpr int kNeuronFunctionCount = static_cast<int>(NeuronFunction::count_);
/// The functions of `limits`' neuron set, in the order draws index them (the sims set: every
/// function cambrian had before the chaumont set, in enumeration order, so its draws are those of
/// before the set existed).
std::span<const NeuronFunction> neuronSet(const GenomeLimits& limits);
/// Whether `function` is in `limits`' neuron set.
bool neuronFunctionAllowed(const GenomeLimits& limits, NeuronFunction function);
/// The name of a neuron set ("sims", "chaumont").
const char* neuronSetName(NeuronSet set);

/// Number of SignalSource values.
constexpr int kSignalSourceCount = 7;

/// v clamped into [lo, hi]; NaN becomes lo, so the result is always in range.
inline double clampToRange(double v, double lo, double hi) {
  if (!(v >= lo))
    return lo;
  if (!(v <= hi))
    return hi;
  return v;
}

}  // namespace cambrian::graph
