// cambrian: the settings of the genetic algorithm (the [evolution] section of an experiment).
#pragma once

#include "cambrian/encoding.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

class SettingsSchema;

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

/// Parameters of the parent selection operators.
struct SelectionSettings {
  SelectionMethod method = SelectionMethod::truncation;
  double truncation_fraction = 0.2;  ///< share of the ranked population eligible (truncation)
  int tournament_size = 3;           ///< contestants per tournament (tournament)
  double rank_pressure = 1.7;        ///< expected offspring of the best under linear ranking
};

/// How the generational scheme draws the parents it mutates (evolution.mutation_selection): with
/// the crossover and graft parents by evolution.selection (`same`), or by a method of their own
/// (the springy organisms' Algorithm 3.1 has S_mut beside S_cross).
enum class MutationSelection : std::uint8_t { same, truncation, tournament, roulette, sus, rank };

/// How each generation is bred from the last (evolution.scheme).
enum class BreedingScheme : std::uint8_t {
  generational,  ///< Sims / Chaumont: elites, then mutation, crossover and graft offspring
  reaper,        ///< Minemonics' reaper: cull, vary the survivors, sow by crossover and at random
  wwd,           ///< Walking with Dinosaurs: elites kept, the rest bred from an elite and a breeder
};

/// Whether the run waits for whole generations (evolution.mode).
enum class EvolutionMode : std::uint8_t {
  generational,  ///< breed a generation, evaluate all of it, breed the next (every scheme)
  steady_state,  ///< no generations: each result is taken in at once and a child sent out
                 ///< (steady_state.hpp); a "generation" is `population` results taken in
};

/// The kinds of survivor the reaper makes, in slot order: kept (elites), then one per operator.
enum class ReaperShare : std::uint8_t {
  elite,
  gene_specification,
  gene_split,
  gene_purge,
  branch_specification,
  grow_stub,
  graft_feature,
};
/// Number of ReaperShare values.
constexpr int kReaperShares = 7;
/// Lower-case name ("gene_split"), as in the keys evolution.reaper_NAME_share.
const char* reaperShareName(ReaperShare share);

/// Minemonics' reaper (evolution.scheme = reaper), with the thesis' numbers.
struct ReaperSettings {
  double reap_fraction = 0.3;  ///< the worst share culled, and sown again
  /// relative weights of the survivors' kinds (ReaperShare order): 14.28 % each
  std::array<double, kReaperShares> shares{1, 1, 1, 1, 1, 1, 1};
  double sow_crossover_fraction = 0.5;  ///< of the sown, the share made by crossover (the rest
                                        ///< random)
  /// the crossover that sows them: cambrian's (Sims') or Minemonics' segment crossover
  Variation crossover = Variation::crossover;
  int tournament_size = 10;        ///< contestants when a partner is chosen by tournament
  double tournament_chance = 0.5;  ///< chance a partner comes from a tournament, not at random
};

/// Walking with Dinosaurs' scheme (evolution.scheme = wwd, wwd_breeding.hpp), with the seed's
/// numbers: elites 20 %, breeders 30 %, the rest gene pool waste; the mutation of the bred scaled
/// by the spread of the generation's normalised fitnesses.
struct WwdSettings {
  double elite_fraction = 0.2;     ///< the best share, kept with their outcomes
  double breeder_fraction = 0.3;   ///< the next share, each bred child's receiving parent
  bool adaptive_mutation = true;   ///< scale the mutation by the fitness deviation ("Deviation")
  double target_deviation = 0.25;  ///< the normalised deviation the mutation is not scaled at
  double min_multiplier = 0.5;     ///< the least the mutation is scaled by (a wide spread)
  double max_multiplier = 4;       ///< the most the mutation is scaled by (no spread)
};

/// Everything the generational Sims / Chaumont scheme, the reaper and the wwd scheme need. The
/// encoding's own operator settings (structural mutation rates) are the encoding's.
struct EvolutionSettings {
  EvolutionMode mode = EvolutionMode::generational;
  /// steady_state: contestants of the reverse tournament that picks the member a new result
  /// may replace (it does when it is at least as fit)
  int replacement_tournament = 2;
  BreedingScheme scheme = BreedingScheme::generational;
  ReaperSettings reaper;            ///< evolution.scheme = reaper
  WwdSettings wwd;                  ///< evolution.scheme = wwd
  int population = 100;             ///< individuals per generation (P)
  int generations = 30;             ///< generations to run, the initial one included (G)
  double elite_fraction = 0.2;      ///< best share copied unchanged and not re-evaluated
  double mutation_fraction = 0.4;   ///< share of the non-elite offspring made by mutation
  double crossover_fraction = 0.3;  ///< share made by crossover
  double graft_fraction = 0.3;      ///< share made by grafting
  double mutation_rate = 0.10;      ///< chance each parameter of a mutated offspring is perturbed
  double post_crossover_mutation_chance =
      0.1;                                     ///< chance an offspring of crossover / graft mutates
  double post_crossover_mutation_rate = 0.05;  ///< per-parameter rate of that mutation
  SelectionSettings selection;
  /// the mutation parents' method; its parameters are evolution.selection's
  MutationSelection mutation_selection = MutationSelection::same;
  std::vector<std::string> seed_genomes;  ///< genome files the first generation starts from
  /// a previous run's history.h5: the best individual of its last generation seeds the first
  /// generation too (after the seed_genomes; empty: none)
  std::string seed_history;
  /// Walking with Dinosaurs' short batches: after every this many generations the population
  /// starts again from its best creature alone (the best and mutated copies of it); 0: never
  int batch_generations = 0;
  /// Minemonics' competitive ranking: measures as NAME[:WEIGHT[:higher|lower]]; when given, a
  /// generation's fitness is each individual's weighted rank points (competitive_ranking.hpp)
  std::vector<std::string> ranking;
  /// Minemonics' epochs: each RANKING[@CONDITION] (epochs.hpp); when given, each generation is
  /// rated by its epoch's ranking (instead of `ranking`)
  std::vector<std::string> epochs;
  std::uint64_t seed = 1;  ///< run seed: keys every random stream of the run

  /// Declares the [evolution] keys (and run.seed), bound to this object, with their ranges;
  /// evolution.generations is run-only (a resumed run may extend a finished one).
  void declareSettings(SettingsSchema& schema);
};

/// Checks every range; throws ConfigError naming the key (evolution.<name>) and the value. The
/// same rules declareSettings() attaches to the keys.
void validateEvolutionSettings(const EvolutionSettings& settings);

}  // namespace cambrian
