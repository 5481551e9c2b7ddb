// cambrian: Walking with Dinosaurs' breeding (evolution.scheme = wwd; Rasmussen and Lund, 2.2.3
// and 3.3). After a generation is evaluated and ranked, the best wwd_elite_fraction (the seed's
// 20 %) are the elites, the next wwd_breeder_fraction (30 %) the breeders, the rest (50 %) gene
// pool waste. The elites stay, with their outcomes (they are not simulated again); every other
// place is a child bred from an elite and a breeder, each drawn uniformly from its group: the
// breeder receives a part of the elite (Encoding::combine(crossover, breeder, elite): "we switch
// a part of the breeder creature with a part from the elite"), then the child is always mutated.
//
// The seed's Deviation ("the less the diversity in the results is the more it mutates ... the
// fitness values are normalized" first) gives no formula; cambrian's, with
// evolution.wwd_adaptive_mutation: the generation's fitnesses f_i (failures count as 0, as in
// the statistics) are divided by max_i |f_i| — the best's, since every fitness is >= 0 — so they
// lie in 0..1 whatever the task's scale (all 0: deviation 0); s is their population standard
// deviation; the mutation is scaled by
//   m = clamp(wwd_target_deviation / max(s, 1e-9), wwd_min_multiplier, wwd_max_multiplier)
// (defaults 0.25, 0.5, 4: a generation of equals mutates 4 times as much, one split half best,
// half failed — s = 0.5, the widest normalised fitnesses can spread — half as much). The wwd
// encoding gets m itself as the rate argument of Encoding::mutate (a multiplier of its own
// chance per gene, wwd.mutation_rate or 1/n); any other encoding gets evolution.mutation_rate x m
// (at most 1), its chance per parameter.
#pragma once

#include "cambrian/encoding.hpp"

#include "evolution/evolution_settings.hpp"
#include "evolution/population.hpp"

#include <vector>

namespace cambrian {

/// How the wwd scheme splits a generation. elites + children = the population.
struct WwdPlan {
  int elites = 0;    ///< the best, kept with their outcomes
  int breeders = 0;  ///< the next, each child's receiving parent
  int children = 0;  ///< bred: every place but the elites'
};

/// The plan for `settings`: elites = round(P x wwd_elite_fraction) (at most P - 1), breeders =
/// round(P x wwd_breeder_fraction) (at most P - elites), children = P - elites. Settings that
/// passed validateEvolutionSettings() under the wwd scheme give at least one of each.
WwdPlan planWwd(const EvolutionSettings& settings);

/// The deviation of a generation's fitnesses and the mutation multiplier it gives.
struct MutationScale {
  double deviation = 0;   ///< standard deviation of the fitnesses divided by max |fitness|
  double multiplier = 1;  ///< what the mutation of the bred is scaled by
};

/// The standard deviation (over n) of `fitness` divided by its largest absolute value; 0 for an
/// empty list or all zeros. Summed in sorted order, so any order of the same values gives the
/// same bits.
double normalisedDeviation(std::vector<double> fitness);

/// The deviation of `fitness` and, with settings.adaptive_mutation, the multiplier
/// clamp(target_deviation / max(deviation, 1e-9), min_multiplier, max_multiplier) (else 1).
MutationScale mutationScale(const WwdSettings& settings, const std::vector<double>& fitness);

/// The scale the wwd scheme breeds the generation after `evaluated` with (Individual::fitness()
/// of each individual). Under another scheme the deviation still, and multiplier 1.
MutationScale mutationScale(const EvolutionSettings& settings, const Population& evaluated);

/// The rate the wwd scheme passes to `encoding`.mutate for multiplier `multiplier`:
/// scaledMutationRate of evolution.mutation_rate (the multiplier itself for the wwd encoding).
double wwdMutationRate(const Encoding& encoding, const EvolutionSettings& settings,
                       double multiplier);

/// Throws ConfigError naming evolution.scheme when `encoding` lacks mutation or crossover.
void requireWwdOperators(const Encoding& encoding);

}  // namespace cambrian
