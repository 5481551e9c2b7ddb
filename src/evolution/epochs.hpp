// cambrian: Minemonics' epochs — a run as a sequence of epochs, each rating its generations by
// its own competitive ranking of the task's measures (its juries) until its transition
// condition holds: after a number of generations, or when the best of a generation reaches a
// value of a measure.
#pragma once

#include "evolution/competitive_ranking.hpp"
#include "evolution/population.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

/// One epoch: its ranking and when it ends.
struct Epoch {
  /// How an epoch ends.
  enum class Until : std::uint8_t {
    end,          ///< never: the last epoch
    generations,  ///< after `generations` generations
    reached,      ///< after the first generation whose best `measure` reaches `threshold`
  };
  std::vector<RankedMeasure> ranking;  ///< the juries, combined by competitive ranking
  Until until = Until::end;
  std::uint64_t generations = 0;  ///< Until::generations
  std::string measure;            ///< Until::reached: the measure watched
  double threshold = 0;           ///< Until::reached: the value to reach
  bool at_least = true;           ///< Until::reached: >= (true) or <= (false) the threshold
};

/// Parses "RANKING[@CONDITION]": RANKING is ranked measures NAME[:WEIGHT[:higher|lower]] joined
/// by + (a list setting splits at commas); CONDITION is N (generations) or NAME>=X / NAME<=X (a
/// measure's value reached by the best of a generation). ConfigError naming `key` and the text when
/// it does not parse.
Epoch parseEpoch(const std::string& text, const std::string& key);

/// Parses every epoch of `texts`; every epoch but the last needs a condition, the last has none.
std::vector<Epoch> parseEpochs(const std::vector<std::string>& texts, const std::string& key);

/// Where a run stands in its epochs: the epoch of the generation rated next and the first
/// generation of that epoch.
struct EpochPlace {
  std::size_t epoch = 0;
  std::uint64_t first_generation = 0;
  friend bool operator==(const EpochPlace&, const EpochPlace&) = default;
};

/// The place after `population` (generation g, rated in `place`) is done: the next epoch from
/// g + 1 when `place`'s condition holds (generations: g + 1 - first_generation >= N; reached: an
/// individual of status ok has the measure at or beyond the threshold), else `place` unchanged.
EpochPlace nextEpochPlace(const std::vector<Epoch>& epochs, EpochPlace place,
                          const Population& population);

}  // namespace cambrian
