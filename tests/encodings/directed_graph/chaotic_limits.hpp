// Test helper: the limits of a run with chaotic joint controllers (genome.joint_controller).
#pragma once

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::test {

/// Default limits with chaotic joint controllers on every joint (`chance` of them on).
inline graph::GenomeLimits chaoticLimits(double chance = 1.0) {
  graph::GenomeLimits limits;
  limits.joint_controller = graph::JointControllerKind::chaotic;
  limits.joint_controller_chance = chance;
  return limits;
}

}  // namespace cambrian::test
