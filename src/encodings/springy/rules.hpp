// cambrian: the consistency rules of a springy organism (Krčah 2008, §3.2.2): a valid morphology
// (rules 1 and 2) and a valid control system (rules 3 to 7).
#pragma once

#include "encodings/springy/organism.hpp"

namespace cambrian::springy {

/// How far rules 4 and 6 may be missed by rounding, m.
constexpr double kLengthTolerance = 1e-9;

/// Throws GenomeError naming the rule, the node or tube and the numbers when `organism` breaks
/// one (the first found, rules in order), or its structure is not an organism's (a tube joining
/// a node to itself or to a node that does not exist, a size or mass not positive and finite,
/// a repeated or empty name).
void checkOrganism(const Organism& organism, const MuscleLimits& limits);
/// Throws GenomeError when muscle tube `tube` breaks rule 3, 4, 5, 6 or 7.
void checkMuscle(const Organism& organism, const Tube& tube, const MuscleLimits& limits);

/// The distance between segments p0–p1 and q0–q1, m.
double segmentDistance(Vec3 p0, Vec3 p1, Vec3 q0, Vec3 q1);
/// The distance between point `point` and segment p0–p1, m.
double pointSegmentDistance(Vec3 point, Vec3 p0, Vec3 p1);

}  // namespace cambrian::springy
