// cambrian: the one record of a generation (fitness statistics, diversity and the timings an
// Amdahl study needs) and the run digest. The run, the history, the checkpoint and the tables all
// keep these as they are; Individual (population.hpp) is the one record of a creature.
#pragma once

#include "core/hash.hpp"
#include "evolution/population.hpp"
#include "evolution/statistics.hpp"

#include <cstdint>
#include <string>

namespace cambrian {

/// One generation.
struct GenerationRecord {
  std::uint64_t generation = 0;
  FitnessStats stats;
  std::uint64_t evaluations = 0;       ///< individuals evaluated (elites are not)
  int workers = 0;                     ///< evaluating ranks
  std::uint64_t distinct_genomes = 0;  ///< distinct genome byte strings (diversity)
  double rank0_serial_seconds = 0;     ///< rank 0 busy outside the evaluation span (breeding...)
  double rank0_cpu_seconds = 0;        ///< CPU time rank 0 used in the whole generation
  double rank0_dispatch_seconds = 0;   ///< rank 0 handing out creatures and taking in results
  double evaluation_span_seconds = 0;  ///< first request sent to last result received
  double worker_busy_seconds = 0;      ///< sum of evaluation wall times
  double worker_idle_seconds = 0;      ///< workers * span - busy
  double checkpoint_seconds = 0;       ///< writing the checkpoint after it (0: none written)
  double wall_seconds = 0;             ///< whole generation on rank 0
  double unix_time = 0;     ///< seconds since 1970-01-01 UTC when it went into the history (0: not)
  std::uint64_t epoch = 0;  ///< the epoch it was rated in (evolution.epochs, from 0; 0 without)
  /// its fitnesses' standard deviation after division by the largest |fitness| (0..0.5;
  /// mutationScale() in wwd_breeding.hpp): the seed's Deviation, a diversity measure
  double fitness_deviation = 0;
  /// what the mutation of the children bred from it is scaled by: the wwd scheme's adaptive
  /// mutation (evolution.wwd_adaptive_mutation); 1 under every other scheme
  double mutation_multiplier = 1;
  /// Evaluations per second of the evaluation span (0 when the span is 0).
  double evaluationsPerSecond() const;
  /// Share of worker time spent evaluating during the span, 0..1.
  double utilisation() const;
};

/// Number of distinct genome byte strings in `population`.
std::uint64_t distinctGenomes(const Population& population);

/// FNV-1a 64-bit digest over every individual's id, genome bytes and fitness bits, fed in id
/// order. Equal digests mean the same run, whatever the rank count.
class RunDigest {
 public:
  /// A digest over nothing yet.
  RunDigest() = default;
  /// A digest that continues from `value` (a value() saved in a checkpoint).
  explicit RunDigest(std::uint64_t value) : hash_(value) {}
  /// Adds the individuals of a generation (in their id order; ids must increase across calls).
  void add(const Population& population);
  /// Adds one individual.
  void add(const Individual& individual);
  /// The digest so far.
  std::uint64_t value() const { return hash_.value(); }
  /// The digest as 16 lower-case hex digits.
  std::string hex() const;

 private:
  Fnv1a hash_;
};

}  // namespace cambrian
