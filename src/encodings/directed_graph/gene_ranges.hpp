// cambrian: the fixed ranges of genome fields (those not set by GenomeLimits), shared by
// generation, validation, repair and mutation so that they always agree.
#pragma once

#include "cambrian/math.hpp"

#include "encodings/directed_graph/genome.hpp"

#include <cstdint>

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
/// ConnectionGene.reflection may only use these bits (mirror x, y, z).
constexpr std::uint8_t kReflectionMask = 0x7;

/// Number of values of each enumeration.
constexpr int kPartShapeCount = 1;
/// Number of JointType values.
constexpr int kJointTypeCount = 4;
/// Number of NeuronFunction values.
constexpr int kNeuronFunctionCount = static_cast<int>(NeuronFunction::count_);
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
