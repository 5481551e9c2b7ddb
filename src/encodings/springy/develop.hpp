// cambrian: a springy organism as a body (Krčah 2008, Algorithms B.1 and B.2): a sphere per node,
// a fixed joint per rod, a slider per muscle, proxy bodies on universal joints where a node has
// more than one joint, capsules along the tubes; and the sinusoids that drive its muscles.
#pragma once

#include "cambrian/encoding.hpp"

#include "encodings/springy/organism.hpp"

namespace cambrian::springy {

/// What the body is made of beyond the organism file.
struct BodySettings {
  double muscle_force = 200;  ///< N, the thesis' "slider max force"
  double friction = 1000;     ///< the nodes' and tubes' Coulomb coefficient (the thesis' "mu 1000")
};

/// How many bodies and joints of each kind Algorithm B.1 makes of an organism.
struct BodyCounts {
  int main_bodies = 0, proxies = 0, universal_joints = 0, sliders = 0, fixed_joints = 0;
};

/// The organism as a body plan with one position effector per muscle (tube order) and the
/// controller that moves each muscle along its sinusoid. Part 0 is node 0's main body; the
/// organism must be valid (rules 1-7). Needs physics.world = rigid_bodies (closed loops,
/// colliders carried by parts).
Creature developOrganism(const Organism& organism, const BodySettings& settings);
/// The body counts of Algorithm B.1 for `organism` (for tests and `inspect`).
BodyCounts countBodies(const Organism& organism);

}  // namespace cambrian::springy
