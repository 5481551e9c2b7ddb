// cambrian: rank 0's side of a whole run — generations of evaluation and breeding, progress
// lines, records, the run digest and the output files.
#pragma once

#include "cambrian/genome.hpp"

#include "evolution/breeder.hpp"
#include "evolution/evolution_settings.hpp"
#include "evolution/run_record.hpp"
#include "parallel/scheduler.hpp"

#include <cstdint>
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
  std::string default_config_text;  ///< every setting at its default, same form (resume check)
  int rank_count = 1;               ///< MPI ranks of the run, stored in the history
  int checkpoint_every = 0;         ///< checkpoint every this many generations (0: no cadence)
  double checkpoint_minutes = 1;  ///< ... or when this many minutes passed since the last (0: off)
  double max_hours = 0;           ///< stop cleanly before this wall time (0: no limit)
  bool fresh = false;             ///< ignore and remove an existing checkpoint, start over
  std::string test_kill_at;       ///< testing: "POINT:GENERATION" where rank 0 SIGKILLs itself
  bool (*stop_requested)() = nullptr;      ///< polled at generation ends: true stops cleanly
  const char* (*stop_reason)() = nullptr;  ///< what asked for the stop (for the message)
};

/// What a run produced.
struct RunResult {
  std::string digest;  ///< RunDigest::hex() over every individual
  std::vector<IndividualRecord> individuals;
  std::vector<GenerationRecord> generations;
  double rank0_cpu_seconds = 0;  ///< CPU time rank 0 used during the run (getrusage)
  double wall_seconds = 0;
  bool resumed = false;               ///< continued from DIR/checkpoint.h5
  bool stopped = false;               ///< stopped early (signal or max-hours), checkpointed
  std::uint64_t next_generation = 0;  ///< the generation a further run continues with
};

/// One progress line (no newline): generation, best / mean / median fitness, evaluations per
/// second, worker utilisation and the estimated time left.
std::string progressLine(const GenerationRecord& record, int generations, double eta_seconds);

/// Runs `settings.generations` generations from `seeds` (random genomes when empty) on
/// `evaluator`, prints progress to `out`, appends each generation to DIR/history.h5 (flushed,
/// readable while the run goes on; see docs/hdf5-schema.md) when `run.history`, writes
/// DIR/individuals.tsv and DIR/generations.tsv at the end (Error(output_file) naming the path
/// when it cannot) and returns the records.
///
/// With `run.history`, checkpoints (docs/checkpoints.md): DIR/checkpoint.h5 is written after a
/// generation every `checkpoint_every` generations or `checkpoint_minutes` minutes, after the
/// last generation and before a clean stop; a run whose DIR holds a checkpoint continues from it
/// (one line on `out` says so) unless `run.fresh`, with the history cut back to it, and gives the
/// records, tables and digest of a straight run. Settings that change results must match the
/// checkpoint's (Error(checkpoint) naming the key and both values); an unreadable or missing but
/// expected checkpoint is Error(checkpoint) naming the file. The run stops cleanly (checkpoint,
/// RunResult::stopped) when `run.stop_requested()` turns true or the next generation would not end
/// before `max_hours`.
RunResult runEvolution(const EvolutionSettings& settings, const GenomeLimits& limits,
                       const std::vector<Genome>& seeds, PopulationEvaluator& evaluator,
                       const RunSettings& run, std::ostream& out);

}  // namespace cambrian
