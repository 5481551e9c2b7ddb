// cambrian: a Walking with Dinosaurs creature as a body and its layered network: boxes joined
// face to face by three-axis joints, a pressure sensor where a box asks for one, three angle
// sensors and three muscles per joint.
#pragma once

#include "cambrian/encoding.hpp"

#include "encodings/wwd/grammar.hpp"

namespace cambrian::wwd {

/// What the body is made of beyond the DNA (the wwd.* settings).
struct BodySettings {
  double density = 1000;  ///< kg / m^3: "each box is designated a weight proportional
                          ///< to its volume"
  double friction =
      0.5;  ///< the boxes' Coulomb coefficient (Bullet's default, as the seed's BasicDemo)
  double strength_per_area = 2000;  ///< N m of muscle torque per m^2 of the joint's cross-section
};

/// The creature the grammar read. Box i is part i; joint j (box j + 1's joint to its parent) is a
/// spherical joint whose axes are the child face's two in-plane axes and its normal axis, each
/// held to its DOF limit. Sensors, per box in order: its pressure sensor (if any), then its
/// joint's three angles. Effectors: three per joint, in joint order.
Creature developCreature(const CreatureGenes& genes, const BodySettings& settings);

/// Where face point `point` of a box of full size `size` lies, and the face's outward normal.
struct FaceFrame {
  Vec3 point, normal;
  int axis = 0;  ///< the face's axis (0 x, 1 y, 2 z)
};
FaceFrame faceFrame(Vec3 size, const FacePoint& point);

}  // namespace cambrian::wwd
