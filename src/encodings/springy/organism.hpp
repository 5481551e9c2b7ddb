// cambrian: the springy organism (Krčah 2008): spheres (nodes) joined by tubes, each a rod of
// fixed length or a muscle whose length follows a sinusoid. The genotype is the organism itself;
// only the muscles' parameters evolve, the morphology is fixed for a run.
#pragma once

#include "cambrian/math.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cambrian::springy {

/// The thesis' defaults (Table 4.1, Table A.4).
constexpr double kNodeDiameter = 0.2;   ///< m
constexpr double kNodeMass = 1;         ///< kg
constexpr double kTubeDiameter = 0.15;  ///< m, the capsules of rods and muscles

/// Which way a muscle moves first from its initial length (the thesis' δ).
enum class FirstMove : std::uint8_t { shorten = 0, lengthen = 1 };

/// A muscle's control: L(t) = rest_length + amplitude · sin(2π · frequency · t + φ), with the
/// phase φ chosen so that L(0) is the initial length and the first move is `first_move`.
struct Muscle {
  double rest_length = 1;  ///< L_r, m: the middle of the sinusoid
  double amplitude = 0;    ///< A, m (0: the muscle is a rod)
  double frequency = 0;    ///< f, Hz (0: the muscle is a rod)
  FirstMove first_move = FirstMove::lengthen;
  friend bool operator==(const Muscle&, const Muscle&) = default;
};

/// A sphere of the organism.
struct Node {
  std::string name;
  Vec3 position;  ///< its centre at the start, m
  double diameter = kNodeDiameter;
  double mass = kNodeMass;
  friend bool operator==(const Node&, const Node&) = default;
};

enum class TubeKind : std::uint8_t { rod = 0, muscle = 1 };

/// A tube between two nodes: a rod or a muscle.
struct Tube {
  std::string name;
  int a = 0, b = 0;  ///< the nodes it joins (indices)
  TubeKind kind = TubeKind::rod;
  Muscle muscle;  ///< a muscle's control (a rod's is unused and default)
  friend bool operator==(const Tube&, const Tube&) = default;
};

/// A springy organism: an undirected graph of nodes and tubes.
struct Organism {
  std::vector<Node> nodes;
  std::vector<Tube> tubes;
  double tube_diameter = kTubeDiameter;
  friend bool operator==(const Organism&, const Organism&) = default;
};

/// The limits of the muscles' parameters (the thesis' "global rules for all operators").
struct MuscleLimits {
  double max_length = 2;     ///< C_max, m: the longest a muscle may become
  double max_frequency = 2;  ///< f_max, Hz
};

/// L_i: the distance between the centres of the tube's nodes at the start, m.
double initialLength(const Organism& organism, const Tube& tube);
/// C_min = r1 + r2: the length at which the tube's end nodes touch, m.
double touchingLength(const Organism& organism, const Tube& tube);
/// The muscles' indices among the tubes, in order.
std::vector<int> muscleIndices(const Organism& organism);
/// Whether two organisms have the same morphology: the same nodes and the same tubes, muscle
/// parameters aside.
bool sameMorphology(const Organism& a, const Organism& b);

/// φ, radians: sin φ = (L_i − L_r) / A, on the rising branch (−π/2..π/2) for a muscle that
/// lengthens first and on the falling one (π/2..3π/2) for one that shortens first; 0 when A = 0.
double musclePhase(const Muscle& muscle, double initial_length);
/// The muscle's length at time t, m.
double muscleLength(const Muscle& muscle, double initial_length, double t);
/// dL/dt at time t, m/s.
double muscleSpeed(const Muscle& muscle, double initial_length, double t);

}  // namespace cambrian::springy
