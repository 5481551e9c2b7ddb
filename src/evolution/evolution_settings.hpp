// cambrian: the settings of the genetic algorithm (the [evolution] section of an experiment).
#pragma once

#include "cambrian/operators.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

/// How parents are chosen from the ranked survivors of a generation.
enum class SelectionMethod : std::uint8_t {
  truncation,  ///< uniform among the best `truncation_fraction` (Sims / Chaumont survivors)
  tournament,  ///< best of `tournament_size` drawn uniformly with replacement
  roulette,    ///< fitness-proportionate
  sus,         ///< stochastic universal sampling (fitness-proportionate, one spin)
  rank,        ///< linear ranking with selection pressure `rank_pressure` in [1, 2]
};

/// Lower-case name of a selection method ("tournament").
const char* selectionMethodName(SelectionMethod method);
/// Parses a selection method name; throws ConfigError naming evolution.selection and the value.
SelectionMethod selectionMethodFromName(const std::string& name);

/// Parameters of the parent selection operators.
struct SelectionSettings {
  SelectionMethod method = SelectionMethod::truncation;
  double truncation_fraction = 0.2;  ///< share of the ranked population eligible (truncation)
  int tournament_size = 3;           ///< contestants per tournament (tournament)
  double rank_pressure = 1.7;        ///< expected offspring of the best under linear ranking
};

/// Everything the generational Sims / Chaumont scheme needs.
struct EvolutionSettings {
  int population = 100;             ///< individuals per generation (P)
  int generations = 30;             ///< generations to run, the initial one included (G)
  double elite_fraction = 0.2;      ///< best share copied unchanged and not re-evaluated
  double mutation_fraction = 0.4;   ///< share of the non-elite offspring made by mutation
  double crossover_fraction = 0.3;  ///< share made by crossover
  double graft_fraction = 0.3;      ///< share made by grafting
  double post_crossover_mutation_chance =
      0.1;                                     ///< chance an offspring of crossover / graft mutates
  double post_crossover_mutation_rate = 0.05;  ///< per-site rate of that mutation
  MutationSettings mutation;  ///< asexual mutation (parameter_rate 0.10 by default)
  SelectionSettings selection;
  std::vector<std::string> seed_genomes;  ///< genome files the first generation starts from
  std::uint64_t seed = 1;                 ///< run seed: keys every random stream of the run
};

/// Checks every range; throws ConfigError naming the key (evolution.<name>) and the value.
void validateEvolutionSettings(const EvolutionSettings& settings);

}  // namespace cambrian
