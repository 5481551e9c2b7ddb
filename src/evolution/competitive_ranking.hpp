// cambrian: Minemonics' competitive ranking — several measures combined into one fitness by the
// ranks each individual reaches on them within its generation, weighted.
#pragma once

#include "evolution/population.hpp"

#include <string>
#include <vector>

namespace cambrian {

/// One measure of a competitive ranking: its weight and which way is better.
struct RankedMeasure {
  std::string measure;  ///< a measure of the task ("average_velocity")
  double weight = 1;
  bool higher_is_better = true;
};

/// Parses "NAME[:WEIGHT[:higher|lower]]" (weight 1 and higher by default); ConfigError naming
/// `key` and the text when it does not parse or the weight is not finite and >= 0.
RankedMeasure parseRankedMeasure(const std::string& text, const std::string& key);

/// Minemonics' competitive ranking (its thesis, "Culling"): for each measure every individual of
/// status ok scores "the number of individuals that performed worse" (ok ones with a strictly
/// worse value), times the measure's weight; its fitness becomes the sum of its scores. An
/// individual without the measure scores 0 on it and counts as worse than every value; one not
/// ok keeps the worst fitness. Depends only on the measures, never on the individuals' order.
void rankCompetitively(std::vector<Individual>& individuals,
                       const std::vector<RankedMeasure>& measures);

}  // namespace cambrian
