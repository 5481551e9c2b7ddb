// cambrian: Minemonics' reaper (evolution.scheme = reaper): each generation culls its worst,
// keeps or varies each survivor by one of seven operators, and sows the culled places again by
// crossover and at random. Breeder::nextGeneration follows it when the scheme is chosen.
#pragma once

#include "cambrian/encoding.hpp"
#include "cambrian/rng.hpp"

#include "evolution/evolution_settings.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace cambrian {

/// How many individuals of a generation the reaper makes of each kind. Sums to the population.
struct ReaperPlan {
  int culled = 0;                              ///< the worst, replaced by the sown
  std::array<int, kReaperShares> survivors{};  ///< per ReaperShare: kept, or varied by it
  int crossovers = 0;                          ///< sown by crossover
  int randoms = 0;                             ///< sown at random
};

/// `total` split in proportion to `weights` by largest remainders (ties to the earlier weight);
/// the counts sum to `total`. Weights must be >= 0 with a positive sum.
std::vector<int> apportion(int total, std::span<const double> weights);

/// The reaper's plan for `settings`: culled = ceil(P * reap_fraction) (at most P - 1, as
/// Minemonics' code rounds up), the survivors apportioned by the shares, the culled places sown
/// round(culled * sow_crossover_fraction) by crossover and the rest at random.
ReaperPlan planReaper(const EvolutionSettings& settings);

/// Throws ConfigError naming the key (evolution.reaper_NAME_share, sow_crossover_fraction) when
/// the reaper's plan for `settings` needs an operator `encoding` lacks.
void requireReaperOperators(const EvolutionSettings& settings, const Encoding& encoding);

/// A partner among `count` ranked survivors (0 the best): with tournament_chance the best of
/// tournament_size contestants, each at index |N(0, count / 3)| (rounded down, at most
/// count - 1: likely near the top, hardly ever the last); otherwise one drawn uniformly.
std::size_t reaperPartner(std::size_t count, const ReaperSettings& settings, Rng& rng);

}  // namespace cambrian
