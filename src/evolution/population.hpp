// cambrian: individuals and the population rank 0 holds. An Individual is the one record of
// a creature: the run, the history, the checkpoint and the tables all keep it as it is.
#pragma once

#include "cambrian/encoding.hpp"
#include "cambrian/outcome.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

/// What made an individual.
enum class Origin : std::uint8_t {
  random,
  seed,
  elite,
  mutation,
  crossover,
  graft,
  // Minemonics' reaper (evolution.scheme = reaper)
  gene_specification,
  gene_split,
  gene_purge,
  branch_specification,
  grow_stub,
  graft_feature,
  segment_crossover,  ///< Minemonics' crossover (evolution.reaper_crossover)
  migrant,            ///< arrived from another island (islands.count), with its outcome
};
/// Number of Origin values.
constexpr int kOriginKinds = 14;

/// Lower-case origin name ("crossover").
const char* originName(Origin origin);

/// An id no individual has (the value of Individual::id before one is given).
constexpr std::uint64_t kNoId = UINT64_MAX;

/// One creature of one generation.
struct Individual {
  std::uint64_t id = kNoId;            ///< unique across the run, increasing with creation
  std::uint64_t generation = 0;        ///< generation it belongs to
  std::vector<std::uint64_t> parents;  ///< 0 (random, seed), 1 (elite, mutation) or 2 ids
  Origin origin = Origin::random;
  Genotype genome;
  Outcome outcome;          ///< filled by evaluation (or copied, for elites)
  bool evaluated = false;   ///< true once outcome holds a result for this genome
  double eval_seconds = 0;  ///< wall time of its evaluation; 0 when copied
  int worker_rank = -1;     ///< rank that evaluated it; -1 when copied or not yet evaluated
  /// steady-state evolution: the results taken in before it was bred (its parents were drawn
  /// from the members then); with the order of the history's rows, what a replay repeats.
  /// 0 in generational runs.
  std::uint64_t bred_after = 0;

  /// The fitness used for selection: the outcome's, or kWorstFitness before evaluation and for
  /// a non-finite value (so ranking is a total order).
  double fitness() const;
  /// The genome's byte form, made once and kept by the genotype: rank 0 needs the bytes for the
  /// request, the digest, the history and the checkpoint.
  const std::vector<std::uint8_t>& genomeBytes() const { return genome.bytes(); }
};

/// A generation of individuals in creation order (ids increasing).
struct Population {
  std::uint64_t generation = 0;
  std::vector<Individual> individuals;

  /// Indices of the individuals, best first: fitness descending, ties broken by id ascending.
  std::vector<std::size_t> ranking() const;
  /// Index of the individual with this id; throws std::out_of_range when absent.
  std::size_t indexOf(std::uint64_t id) const;
  /// True when every individual holds an outcome.
  bool allEvaluated() const;
};

/// The best of `individuals` with status ok — of generation `generation` only, when given: the
/// highest fitness, ties to the lowest id (replay --best, evolution.seed_history); null when
/// none is ok.
const Individual* bestOk(const std::vector<Individual>& individuals,
                         std::optional<std::uint64_t> generation = std::nullopt);

}  // namespace cambrian
