// cambrian: fitness statistics of a generation.
#pragma once

#include "evolution/population.hpp"

#include <cstddef>
#include <vector>

namespace cambrian {

/// Summary of the fitness of one generation (failed individuals count with kWorstFitness).
struct FitnessStats {
  std::size_t count = 0;   ///< individuals
  std::size_t failed = 0;  ///< individuals whose status is not ok
  double best = 0, worst = 0, mean = 0, stddev = 0;
  double q25 = 0, median = 0, q75 = 0;
  std::uint64_t best_id = kNoId;  ///< the best individual (ties: lowest id)
};

/// The q-quantile (0..1) of ascending `sorted` values, linearly interpolated; 0 when empty.
double quantile(const std::vector<double>& sorted, double q);

/// Statistics of an evaluated population; deterministic (summed in id order).
FitnessStats computeStats(const Population& population);

}  // namespace cambrian
