// cambrian: parent selection operators, usable by every breeding scheme.
#pragma once

#include "cambrian/rng.hpp"

#include "evolution/evolution_settings.hpp"

#include <cstddef>
#include <vector>

namespace cambrian {

/// Picks `count` parents from a ranked population. `ranked_fitness` holds the fitness of each
/// individual best first (ties already broken by id), every value >= 0 and finite. Returns
/// positions into `ranked_fitness`. All draws come from `rng`, so the picks are a pure function
/// of (fitness, count, settings, rng stream). Throws std::invalid_argument on an empty ranking.
std::vector<std::size_t> selectParents(const std::vector<double>& ranked_fitness, std::size_t count,
                                       const SelectionSettings& settings, Rng& rng);

/// Expected share of the picks each ranked position receives under `settings` (the exact
/// selection probabilities; tournament and truncation included). Sums to 1.
std::vector<double> selectionProbabilities(const std::vector<double>& ranked_fitness,
                                           const SelectionSettings& settings);

}  // namespace cambrian
