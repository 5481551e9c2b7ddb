// cambrian: rank 0's side of a whole run — generations of breeding and evaluation, progress
// lines, the history, checkpoints and resume, the run digest and the tables.
#pragma once

#include "cambrian/encoding.hpp"

#include "evolution/evolution_settings.hpp"
#include "evolution/generation_record.hpp"
#include "evolution/population.hpp"
#include "parallel/scheduler.hpp"
#include "run/run_settings.hpp"

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace cambrian {

/// What a run produced.
struct RunResult {
  std::string digest;                   ///< RunDigest::hex() over every individual
  std::vector<Individual> individuals;  ///< every individual, in id order, its genome dropped
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

/// Runs `settings.generations` generations from `seeds` (random genomes of `encoding` when
/// empty) on `evaluator`, prints progress to `out`, appends each generation to DIR/history.h5
/// (flushed, readable while the run goes on; see docs/hdf5-schema.md) when `run.history`, writes
/// DIR/individuals.tsv and DIR/generations.tsv at the end (Error(output_file) naming the path
/// when it cannot) and returns the records.
///
/// With `run.history`, checkpoints (docs/checkpoints.md): DIR/checkpoint.h5 is written after a
/// generation every `checkpoint_every` generations or `checkpoint_minutes` minutes, after the
/// first and the last generation and before a clean stop; a run whose DIR holds a checkpoint
/// continues from it (one line on `out` says so) unless `run.fresh`, with the history cut back
/// to it, and gives the records, tables and digest of a straight run. Settings that change
/// results must match the checkpoint's (Error(checkpoint) naming the key and both values); an
/// unreadable or missing but expected checkpoint is Error(checkpoint) naming the file. The run
/// stops cleanly (checkpoint, RunResult::stopped) when `run.stop_requested()` turns true or the
/// next generation would not end before `max_hours`.
RunResult runEvolution(const EvolutionSettings& settings, const Encoding& encoding,
                       const std::vector<Genotype>& seeds, PopulationEvaluator& evaluator,
                       const RunSettings& run, std::ostream& out);

}  // namespace cambrian
