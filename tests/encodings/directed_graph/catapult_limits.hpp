// Test helper: the limits of a catapult genome (genome.catapult = true).
#pragma once

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::test {

/// Default limits with catapults on, the projectile's block mutable or not.
inline graph::GenomeLimits catapultLimits(bool projectile_mutation = false) {
  graph::GenomeLimits limits;
  limits.catapult = true;
  limits.projectile_mutation = projectile_mutation;
  return limits;
}

}  // namespace cambrian::test
