// cambrian: rank 0's side of a whole run — generations of evaluation and breeding, progress
// lines, records, the run digest and the output files.
#pragma once

#include "cambrian/genome.hpp"

#include "evolution/breeder.hpp"
#include "evolution/evolution_settings.hpp"
#include "evolution/run_record.hpp"
#include "parallel/scheduler.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace cambrian {

/// Where a run writes and how much it says.
struct RunSettings {
  std::string out_dir = "cambrian-run";  ///< history.h5, individuals.tsv, generations.tsv go here
  bool quiet = false;                    ///< no progress lines, only the digest
  bool verbose = false;                  ///< timing details after each progress line
  ViabilityCheck viable;    ///< birth test for new individuals (none: accept all), rank 0 only
  bool history = true;      ///< write DIR/history.h5 generation by generation (SWMR)
  std::string config_text;  ///< the effective settings as INI text, stored in the history
  int rank_count = 1;       ///< MPI ranks of the run, stored in the history
};

/// What a run produced.
struct RunResult {
  std::string digest;  ///< RunDigest::hex() over every individual
  std::vector<IndividualRecord> individuals;
  std::vector<GenerationRecord> generations;
  double rank0_cpu_seconds = 0;  ///< CPU time rank 0 used during the run (getrusage)
  double wall_seconds = 0;
};

/// One progress line (no newline): generation, best / mean / median fitness, evaluations per
/// second, worker utilisation and the estimated time left.
std::string progressLine(const GenerationRecord& record, int generations, double eta_seconds);

/// Runs `settings.generations` generations from `seeds` (random genomes when empty) on
/// `evaluator`, prints progress to `out`, appends each generation to DIR/history.h5 (flushed,
/// readable while the run goes on; see docs/hdf5-schema.md) when `run.history`, writes
/// DIR/individuals.tsv and DIR/generations.tsv at the end (Error(output_file) naming the path
/// when it cannot) and returns the records.
RunResult runEvolution(const EvolutionSettings& settings, const GenomeLimits& limits,
                       const std::vector<Genome>& seeds, PopulationEvaluator& evaluator,
                       const RunSettings& run, std::ostream& out);

}  // namespace cambrian
