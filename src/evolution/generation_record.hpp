// cambrian: the plain records of a run (per individual, per generation) and the run digest.
// A store module writes these to HDF5; until then individuals.tsv and generations.tsv hold them.
#pragma once

#include "cambrian/outcome.hpp"

#include "evolution/population.hpp"
#include "evolution/statistics.hpp"

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace cambrian {

/// One evaluated (or copied) individual, as the history keeps it.
struct IndividualRecord {
  std::uint64_t generation = 0;
  std::uint64_t id = kNoId;
  std::vector<std::uint64_t> parents;
  Origin origin = Origin::random;
  double fitness = kWorstFitness;
  EvalStatus status = EvalStatus::ok;
  int parts = 0;
  double eval_seconds = 0;  ///< wall time (timing: varies run to run)
  int worker_rank = -1;     ///< who evaluated it (varies with the rank count); -1 for copies
};

/// The record of an individual of an evaluated population.
IndividualRecord makeIndividualRecord(const Individual& individual);

/// One generation: fitness statistics and the timings an Amdahl study needs.
struct GenerationRecord {
  std::uint64_t generation = 0;
  FitnessStats stats;
  std::size_t evaluations = 0;         ///< individuals evaluated (elites are not)
  int workers = 0;                     ///< evaluating ranks
  double rank0_serial_seconds = 0;     ///< rank 0 busy outside the evaluation span (breeding...)
  double rank0_cpu_seconds = 0;        ///< CPU time rank 0 used in the whole generation
  double rank0_dispatch_seconds = 0;   ///< rank 0 handing out creatures and taking in results
  double evaluation_span_seconds = 0;  ///< first request sent to last result received
  double worker_busy_seconds = 0;      ///< sum of evaluation wall times
  double worker_idle_seconds = 0;      ///< workers * span - busy
  double wall_seconds = 0;             ///< whole generation on rank 0
  /// Evaluations per second of the evaluation span (0 when the span is 0).
  double evaluationsPerSecond() const;
  /// Share of worker time spent evaluating during the span, 0..1.
  double utilisation() const;
};

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
  std::uint64_t value() const { return hash_; }
  /// The digest as 16 lower-case hex digits.
  std::string hex() const;

 private:
  void bytes(const void* data, std::size_t size);
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// Header line of individuals.tsv (tab separated, ends with a newline).
std::string individualsTsvHeader();
/// One line of individuals.tsv; parents are joined with ',' ('-' when none); fitness in %.17g.
std::string individualsTsvRow(const IndividualRecord& record);
/// Header line of generations.tsv.
std::string generationsTsvHeader();
/// One line of generations.tsv.
std::string generationsTsvRow(const GenerationRecord& record);

/// Writes `text` to `path` atomically (temporary file, rename); throws Error(output_file)
/// naming the path.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace cambrian
