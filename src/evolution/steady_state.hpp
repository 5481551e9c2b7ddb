// cambrian: steady-state evolution's members and their rule of replacement — where a result
// taken in goes among them. Its children come from Breeder::steadyChild (steady_state.cpp); the run
// driver (run/evolution_run.cpp) takes results in as they arrive.
#pragma once

#include "evolution/evolution_settings.hpp"
#include "evolution/population.hpp"

#include <cstdint>
#include <vector>

namespace cambrian {

/// The counter of the random streams steady-state evolution draws for an individual: (seed,
/// selection, id, kSteadyStream) picks the operator and parents of the child `id`, (seed,
/// variation, id, kSteadyStream) varies it, (seed, selection, id, kSteadyStream + 1) draws the
/// reverse tournament it meets when taken in. No generational stream has this counter (theirs
/// are offspring slots, below a population's size).
constexpr std::uint64_t kSteadyStream = ~std::uint64_t{0} - 1;

/// A steady state's members — at most evolution.population, in id order — and their ranking
/// (fitness descending, ties: the lowest id), kept up to date as results are taken in, so that
/// breeding a child ranks nothing (Breeder::steadyChild).
class SteadyMembers {
 public:
  /// `settings` (population, replacement_tournament, seed) must outlive the members.
  explicit SteadyMembers(const EvolutionSettings& settings) : settings_(settings) {}

  /// Takes an evaluated individual in: while there are fewer than evolution.population members
  /// it joins them; else `replacement_tournament` members are drawn (with replacement, by their
  /// place in id order) from its stream, and it replaces the worst of them (the lowest fitness,
  /// ties: the lowest id, the oldest) when it is at least as fit. A pure function of the members,
  /// the individual and the settings. Returns whether it entered.
  bool takeIn(Individual individual);

  /// The members, in id order; their generation is the one the next result is taken in during.
  const Population& population() const { return members_; }
  /// Sets the generation the population() reports.
  void setGeneration(std::uint64_t generation) { members_.generation = generation; }
  /// How many there are.
  std::size_t size() const { return members_.individuals.size(); }
  /// Their fitnesses, best first (as selectParents takes them), and the ids in that order.
  const std::vector<double>& rankedFitness() const { return ranked_fitness_; }
  const std::vector<std::uint64_t>& rankedIds() const { return ranked_ids_; }
  /// The member of this id (which must be one).
  const Individual& member(std::uint64_t id) const {
    return members_.individuals[members_.indexOf(id)];
  }

 private:
  // where (fitness, id) stands in the ranking
  std::size_t rankOf(double fitness, std::uint64_t id) const;
  void addToRanking(const Individual& individual);
  void removeFromRanking(const Individual& individual);

  const EvolutionSettings& settings_;
  Population members_;
  std::vector<double> ranked_fitness_;
  std::vector<std::uint64_t> ranked_ids_;
};

}  // namespace cambrian
