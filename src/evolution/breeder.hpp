// cambrian: breeding generations over genomes of any encoding (through the Encoding interface):
// the generational Sims / Chaumont scheme — elitism plus mutation, crossover, grafting —,
// Minemonics' reaper (reaper.hpp) or Walking with Dinosaurs' scheme (wwd_breeding.hpp), as
// evolution.scheme says.
#pragma once

#include "cambrian/encoding.hpp"

#include "evolution/evolution_settings.hpp"
#include "evolution/population.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace cambrian {

class Rng;
class SteadyMembers;

/// How many individuals of a generation each operator makes. Sums to the population size.
struct BreedingPlan {
  int elites = 0;
  int mutations = 0;
  int crossovers = 0;
  int grafts = 0;
  /// elites + mutations + crossovers + grafts.
  int total() const { return elites + mutations + crossovers + grafts; }
};

/// The plan for `settings`: elites = round(P * elite_fraction), the rest split by the offspring
/// fractions (rounded; grafts take the remainder).
BreedingPlan planBreeding(const EvolutionSettings& settings);

/// The rate a breeding scheme passes to `encoding`.mutate for the per-parameter `rate` scaled by
/// `multiplier` (1 but under the wwd scheme): `multiplier` itself for an encoding that scales its
/// own chance per gene (Encoding::scalesOwnMutation), else min(1, rate x multiplier).
double scaledMutationRate(const Encoding& encoding, double rate, double multiplier);

/// The selection method a mutation_selection other than `same` names (`same`: rank, unused).
SelectionMethod selectionMethodFor(MutationSelection choice);

/// Whether a new genome makes a body that may be born (Chaumont et al. 5.5).
using ViabilityCheck = std::function<bool(const Genotype&)>;

/// Makes generations. Every random decision is keyed by (run seed, purpose) and counted by
/// (generation, offspring slot), so a generation is a pure function of the previous one's genomes
/// and fitnesses — never of rank count or arrival order. Ids are handed out in slot order.
class Breeder {
 public:
  /// `settings` must have passed validateEvolutionSettings(); `encoding` (configured) makes and
  /// varies the genomes and must outlive the breeder. Throws ConfigError when the plan needs an
  /// operator the encoding lacks.
  Breeder(const EvolutionSettings& settings, const Encoding& encoding);

  /// Generation 0: random genomes, or the seeds followed by mutated copies of them (round robin;
  /// under the wwd scheme mutated as a bred child of multiplier 1 is: the wwd encoding at its own
  /// chance per gene — "the rest of the population is filled with slightly mutated versions").
  Population initialPopulation(const std::vector<Genotype>& seeds = {});

  /// The next generation from an evaluated one. Generational: the best `elites` copied with
  /// their outcomes (not re-evaluated), then mutation, crossover and graft offspring of selected
  /// parents. Reaper: the kept survivors with their outcomes, the varied survivors, the sown.
  /// Wwd: the elites with their outcomes, then children of an elite and a breeder (planWwd).
  /// Where a short batch ends (evolution.batch_generations), any scheme: the best ok individual
  /// with its outcome, then mutated copies of it as initialPopulation makes them from a seed.
  /// Throws std::invalid_argument when `evaluated` is not fully evaluated.
  Population nextGeneration(const Population& evaluated);

  /// Steady-state evolution (evolution.mode = steady_state): one child of the evaluated
  /// `members` as they are now, with the next id. Its operator (by the offspring shares) and
  /// parents (by evolution.selection, or mutation_selection) come from the stream (seed,
  /// selection, id, kSteadyStream), its genome (made when first read) from (seed, variation, id,
  /// kSteadyStream); `bred_after` is recorded on it, its generation is the members'. A pure
  /// function of the members' genomes and fitnesses and the id. Throws std::invalid_argument
  /// when there are no members. Implemented in steady_state.cpp.
  Individual steadyChild(const SteadyMembers& members, std::uint64_t bred_after);

  /// New individuals that fail `check` are redrawn — same parents, the next draws of the same
  /// random stream — up to `max_attempts` times in all (Chaumont et al. 5.5). Elites and seed
  /// genomes are never redrawn. No check (the default) accepts everything.
  void setViabilityCheck(ViabilityCheck check, int max_attempts = 50) {
    viable_ = std::move(check);
    max_attempts_ = max_attempts;
  }

  /// The id the next new individual gets.
  std::uint64_t nextId() const { return next_id_; }
  /// Sets the id counter (resuming a run).
  void setNextId(std::uint64_t id) { next_id_ = id; }
  /// The plan every generation after the first follows (the generational scheme).
  const BreedingPlan& plan() const { return plan_; }

 private:
  // the reaper's next generation (reaper.cpp)
  Population reap(const Population& evaluated);
  // the first generation of a new short batch: the best of `evaluated` and its mutants
  Population restartFromBest(const Population& evaluated);
  // the wwd scheme's next generation (wwd_breeding.cpp)
  Population breedWwd(const Population& evaluated);
  // how the generational scheme and the steady state make a child of `origin` (mutation,
  // crossover, graft) from its parents' genomes (`second` unused for mutation)
  std::function<Genotype(Rng&, int)> varyParents(Origin origin, Genotype first,
                                                 Genotype second) const;
  // a copy of `parent` in `generation`, with its outcome (its genome did not change)
  Individual eliteCopy(const Individual& parent, std::uint64_t generation);
  // a new individual of generation `g` in offspring slot `slot`, its genome deferred: when first
  // read, `make` (holding copies of what it reads) draws it from the slot's stream (seed,
  // variation, g, slot), tidied and drawn again while the viability check refuses it (same
  // parents, the next draws of the same stream)
  Individual offspring(std::uint64_t g, std::uint64_t slot, Origin origin,
                       std::vector<std::uint64_t> parents,
                       std::function<Genotype(Rng&, int attempt)> make);
  // whether `genome`, drawn at `attempt`, is kept: it passes `viable`, or it is the last attempt
  static bool acceptable(const ViabilityCheck& viable, int max_attempts, const Genotype& genome,
                         int attempt) {
    return !viable || attempt + 1 >= max_attempts || viable(genome);
  }
  bool acceptable(const Genotype& genome, int attempt) const {
    return acceptable(viable_, max_attempts_, genome, attempt);
  }
  EvolutionSettings settings_;
  const Encoding& encoding_;
  BreedingPlan plan_;
  std::uint64_t next_id_ = 0;
  ViabilityCheck viable_;
  int max_attempts_ = 1;
};

}  // namespace cambrian
