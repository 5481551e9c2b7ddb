#include "parallel/evolution_run.hpp"

#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "evolution/breeder.hpp"
#include "evolution/statistics.hpp"
#include "parallel/mpi_context.hpp"
#include "parallel/test_kill.hpp"
#include "physics/simulation.hpp"
#include "store/checkpoint.hpp"
#include "store/history.hpp"
#include "store/run_lock.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// h:mm:ss
std::string clockText(double seconds) {
  auto total = static_cast<long long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, (total / 60) % 60,
                total % 60);
  return text;
}

// the records of a population, in id order
void appendRecords(const Population& population, std::vector<IndividualRecord>& records) {
  for (const Individual& individual : population.individuals) {
    records.push_back(makeIndividualRecord(individual));
  }
}

// the output directory
void makeOutputDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw Error(ExitCode::output_file, dir + ": cannot create directory: " + error.message());
}

// the provenance of the run's history (the config hash leaves out run-only settings)
HistoryAttributes historyAttributes(const EvolutionSettings& settings, const RunSettings& run) {
  HistoryAttributes attributes;
  attributes.config_text = run.config_text;
  attributes.config_hash = resultConfigHash(run.config_text);
  attributes.seed = settings.seed;
  attributes.rank_count = run.rank_count;
  attributes.bullet_precision = bulletPrecision();
  return attributes;
}

// the table record of a history row (what a resumed run keeps)
IndividualRecord individualRecordOf(const HistoryIndividual& row) {
  IndividualRecord record;
  record.generation = row.generation;
  record.id = row.id;
  for (std::uint64_t parent : {row.parent_a, row.parent_b}) {
    if (parent != kNoId)
      record.parents.push_back(parent);
  }
  record.origin = row.origin;
  record.fitness = row.fitness;
  record.status = row.status;
  record.parts = row.parts;
  record.eval_seconds = row.eval_seconds;
  record.worker_rank = row.worker_rank;
  return record;
}

GenerationRecord generationRecordOf(const HistoryGeneration& row) {
  GenerationRecord record;
  record.generation = row.generation;
  FitnessStats& s = record.stats;
  s.count = row.count;
  s.failed = row.failed;
  s.best = row.best;
  s.worst = row.worst;
  s.mean = row.mean;
  s.stddev = row.stddev;
  s.q25 = row.q25;
  s.median = row.median;
  s.q75 = row.q75;
  s.best_id = row.best_id;
  record.evaluations = row.evaluations;
  record.workers = row.workers;
  record.rank0_serial_seconds = row.rank0_serial_seconds;
  record.rank0_cpu_seconds = row.rank0_cpu_seconds;
  record.rank0_dispatch_seconds = row.rank0_dispatch_seconds;
  record.evaluation_span_seconds = row.evaluation_span_seconds;
  record.worker_busy_seconds = row.worker_busy_seconds;
  record.worker_idle_seconds = row.worker_idle_seconds;
  record.wall_seconds = row.wall_seconds;
  return record;
}

// individuals.tsv and generations.tsv, atomically
void writeTables(const std::string& dir, const RunResult& result) {
  makeOutputDirectory(dir);
  std::string individuals = individualsTsvHeader();
  for (const IndividualRecord& r : result.individuals)
    individuals += individualsTsvRow(r);
  writeTextFileAtomically(dir + "/individuals.tsv", individuals);
  std::string generations = generationsTsvHeader();
  for (const GenerationRecord& r : result.generations)
    generations += generationsTsvRow(r);
  writeTextFileAtomically(dir + "/generations.tsv", generations);
}

}  // namespace

std::string progressLine(const GenerationRecord& r, int generations, double eta_seconds) {
  char line[256];
  std::snprintf(line, sizeof line,
                "gen %llu/%d  best %.6g  mean %.6g  median %.6g  evals/s %.1f  util %.0f%%  "
                "eta %s",
                static_cast<unsigned long long>(r.generation + 1), generations, r.stats.best,
                r.stats.mean, r.stats.median, r.evaluationsPerSecond(), 100 * r.utilisation(),
                clockText(eta_seconds).c_str());
  return line;
}

RunResult runEvolution(const EvolutionSettings& settings, const GenomeLimits& limits,
                       const std::vector<Genome>& seeds, PopulationEvaluator& evaluator,
                       const RunSettings& run, std::ostream& out) {
  RunResult result;
  double cpu_start = processCpuSeconds();
  auto run_start = Clock::now();
  auto secondsSince = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  setTestKillPoint(run.test_kill_at);
  Breeder breeder(settings, limits);
  if (run.viable)
    breeder.setViabilityCheck(run.viable);

  // a checkpoint to continue from (checked before anything is overwritten), or a fresh start
  // (the directory locked first: one run at a time writes it)
  std::optional<CheckpointState> checkpoint;
  std::optional<RunLock> lock;
  if (run.history) {
    makeOutputDirectory(run.out_dir);
    std::string warning;
    lock.emplace(run.out_dir, &warning);
    if (!warning.empty())
      out << "cambrian evolve: warning: " << warning << std::endl;
    if (!run.fresh)
      checkpoint = findCheckpoint(run.out_dir);
    if (checkpoint)
      checkResumeSettings(checkpointPath(run.out_dir), checkpoint->config_text, run.config_text,
                          run.default_config_text);
    // another build may evaluate creatures differently: allowed, but said
    if (checkpoint &&
        (checkpoint->cambrian_version != kVersion || checkpoint->git_hash != kGitHash))
      out << "cambrian evolve: warning: " << checkpointPath(run.out_dir)
          << " was written by cambrian " << checkpoint->cambrian_version << " (git "
          << checkpoint->git_hash << "), this is " << kVersion << " (git " << kGitHash
          << "): the run continues exactly only if both evaluate and breed alike" << std::endl;
  }
  RunDigest digest;
  std::optional<Population> last;  // the last evaluated generation
  std::unique_ptr<HistoryWriter> history;
  std::vector<double> walls;  // generation wall times, for the max-hours prediction
  std::uint64_t start = 0;
  if (checkpoint) {
    // the history cut back to the checkpoint, the records kept, the breeder and digest state
    start = checkpoint->next_generation;
    out << "cambrian evolve: resuming from " << checkpointPath(run.out_dir) << " at generation "
        << start << " (" << start << " generation(s) done, written by a run of "
        << checkpoint->rank_count << " rank(s))" << std::endl;
    HistoryRows kept;
    try {
      history =
          resumeHistory(run.out_dir + "/history.h5", start, historyAttributes(settings, run), kept,
                        historyChunkRows(static_cast<std::uint64_t>(settings.population)));
    } catch (const InputError& e) {
      throw Error(ExitCode::checkpoint, std::string(e.what()) +
                                            " (needed to resume from checkpoint.h5); "
                                            "`cambrian evolve --fresh` starts over");
    }
    for (const HistoryIndividual& row : kept.individuals)
      result.individuals.push_back(individualRecordOf(row));
    for (const HistoryGeneration& row : kept.generations) {
      result.generations.push_back(generationRecordOf(row));
      walls.push_back(row.wall_seconds - row.checkpoint_seconds);
    }
    breeder.setNextId(checkpoint->next_id);
    digest = RunDigest(checkpoint->digest);
    last = std::move(checkpoint->population);
    result.resumed = true;
  } else if (run.history) {
    // nothing to continue from: stale checkpoint files go, the history starts empty
    std::error_code error;
    if (!run.fresh && std::filesystem::exists(run.out_dir + "/history.h5", error))
      out << "cambrian evolve: no checkpoint in " << run.out_dir << ", starting fresh" << std::endl;
    removeCheckpoints(run.out_dir);
    history = std::make_unique<HistoryWriter>(
        run.out_dir + "/history.h5", historyAttributes(settings, run),
        historyChunkRows(static_cast<std::uint64_t>(settings.population)));
  }

  // the last evaluated generation's checkpoint (`next_id` as it was when that generation ended,
  // `digest` over every generation up to it); its time goes into that generation's row
  std::uint64_t checkpointed = start;
  auto checkpoint_time = Clock::now();
  double checkpoint_seconds_max = 0;
  auto writeRunCheckpoint = [&](std::uint64_t next_generation, std::uint64_t next_id,
                                std::uint64_t digest_value) -> double {
    auto begin = Clock::now();
    CheckpointState state;
    state.config_text = run.config_text;
    state.seed = settings.seed;
    state.next_generation = next_generation;
    state.next_id = next_id;
    state.digest = digest_value;
    state.rank_count = run.rank_count;
    state.population = *last;
    writeCheckpoint(run.out_dir, state, [&](const std::string& stage) {
      testKillPoint("checkpoint_" + stage, next_generation - 1);
    });
    testKillPoint("checkpoint_done", next_generation - 1);
    double seconds = std::max(secondsSince(begin), 1e-9);
    checkpoint_seconds_max = std::max(checkpoint_seconds_max, seconds);
    checkpointed = next_generation;
    checkpoint_time = Clock::now();
    return seconds;
  };

  // a generation's times run from the start of its breeding to the start of the next one's (the
  // last one's: to the end of its history append and checkpoint), so consecutive rows tile the
  // run; its serial time is what of that lies outside its evaluation span
  auto generation_start = Clock::now();
  double generation_cpu_start = 0;
  auto closeTimes = [&](GenerationRecord& record) {
    record.wall_seconds = secondsSince(generation_start);
    record.rank0_cpu_seconds = processCpuSeconds() - generation_cpu_start;
    record.rank0_serial_seconds =
        std::max(0.0, record.wall_seconds - record.evaluation_span_seconds);
  };

  // the last evaluated generation until it is in the history: written, with its checkpoint when
  // one is due, while the next generation evaluates (the workers never wait for the file
  // system), or at the end or a clean stop, when nothing is left to overlap
  struct Pending {
    std::size_t record = 0;  // index into result.generations
    std::uint64_t next_id = 0;
  };
  std::optional<Pending> pending;
  std::optional<Population> retired;  // the generation before `last`, freed in the same slot
  const auto total = static_cast<std::uint64_t>(std::max(settings.generations, 0));
  auto finishPending = [&](bool final_write) {
    if (!pending)
      return;
    // the run digest over it and the freeing of the generation before: a millisecond or two of
    // hashing and freeing that the workers need not wait for either
    digest.add(*last);
    retired.reset();
    if (!history) {
      pending.reset();
      return;
    }
    GenerationRecord& record = result.generations[pending->record];
    if (final_write)
      closeTimes(record);
    std::uint64_t g = record.generation;
    std::vector<HistoryIndividual> history_rows;
    for (const Individual& individual : last->individuals)
      history_rows.push_back(makeHistoryIndividual(individual));
    history->appendGeneration(history_rows, makeHistoryGeneration(record, *last));
    testKillPoint("history", g);

    // a checkpoint every checkpoint_every generations or checkpoint_minutes, after the first
    // (a history never holds generations without one for long) and at the end
    bool due = final_write || g == 0 || g + 1 == total ||
               (run.checkpoint_every > 0 &&
                g + 1 - checkpointed >= static_cast<std::uint64_t>(run.checkpoint_every)) ||
               (run.checkpoint_minutes > 0 &&
                secondsSince(checkpoint_time) >= run.checkpoint_minutes * 60);
    double checkpoint_seconds =
        due ? writeRunCheckpoint(g + 1, pending->next_id, digest.value()) : 0;
    // the last generation's times include its append and checkpoint
    if (final_write)
      closeTimes(record);
    GenerationTimes times;
    times.rank0_serial_seconds = record.rank0_serial_seconds;
    times.rank0_cpu_seconds = record.rank0_cpu_seconds;
    times.checkpoint_seconds = checkpoint_seconds;
    times.wall_seconds = record.wall_seconds;
    history->completeLastGeneration(times);
    pending.reset();
  };

  // why the run should stop before generation g ("" to go on)
  auto stopReason = [&](std::uint64_t g) -> std::string {
    if (run.stop_requested && run.stop_requested())
      return std::string("stopped by ") + (run.stop_reason ? run.stop_reason() : "a signal");
    if (run.max_hours > 0 && !walls.empty()) {
      // the slowest of the last five generations plus the slowest checkpoint must still fit
      double predicted =
          *std::max_element(walls.end() - std::min<std::size_t>(walls.size(), 5), walls.end()) +
          checkpoint_seconds_max;
      double limit = run.max_hours * 3600;
      if (secondsSince(run_start) + predicted > limit) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "stopped before the --max-hours %g limit (generation %llu would need about "
                      "%.1f s, %.1f s are left)",
                      run.max_hours, static_cast<unsigned long long>(g), predicted,
                      std::max(0.0, limit - secondsSince(run_start)));
        return text;
      }
    }
    return "";
  };

  std::string stop_reason;
  std::uint64_t g = start;
  for (; g < total; ++g) {
    // a clean stop: the last generation written and checkpointed, then out
    stop_reason = stopReason(g);
    if (!stop_reason.empty())
      break;

    // the previous generation ends here: its times are complete
    if (pending) {
      GenerationRecord& previous = result.generations[pending->record];
      closeTimes(previous);
      walls.back() = previous.wall_seconds;
    }
    generation_start = Clock::now();
    generation_cpu_start = processCpuSeconds();

    // breed (generation 0: the initial population), then evaluate what is new while the
    // previous generation goes to the history
    Population population = last ? breeder.nextGeneration(*last) : breeder.initialPopulation(seeds);
    EvaluationSpan span =
        evaluator.evaluate(population, settings.seed, [&] { finishPending(false); });

    // summarise in id order (the times so far; closed when the next generation starts)
    GenerationRecord record;
    record.generation = population.generation;
    record.stats = computeStats(population);
    record.evaluations = span.evaluations;
    record.workers = span.workers;
    record.evaluation_span_seconds = span.span_seconds;
    record.rank0_dispatch_seconds = span.dispatch_seconds;
    record.worker_busy_seconds = span.busy_seconds;
    record.worker_idle_seconds =
        std::max(0.0, span.workers * span.span_seconds - span.busy_seconds);
    appendRecords(population, result.individuals);
    closeTimes(record);
    retired = std::move(last);
    last = std::move(population);
    result.generations.push_back(record);
    walls.push_back(record.wall_seconds);
    pending = Pending{result.generations.size() - 1, breeder.nextId()};

    // progress
    double elapsed = secondsSince(run_start);
    double eta = elapsed / static_cast<double>(g + 1 - start) * static_cast<double>(total - g - 1);
    if (!run.quiet)
      out << progressLine(record, settings.generations, eta) << std::endl;
    if (run.verbose) {
      char detail[256];
      std::snprintf(
          detail, sizeof detail,
          "    evaluated %zu  span %.3f s  busy %.3f s  idle %.3f s  rank0 serial %.4f s  "
          "failed %zu  best id %llu",
          record.evaluations, record.evaluation_span_seconds, record.worker_busy_seconds,
          record.worker_idle_seconds, record.rank0_serial_seconds, record.stats.failed,
          static_cast<unsigned long long>(record.stats.best_id));
      out << detail << std::endl;
    }
  }

  // the last generation into the history, checkpointed (a resume that stops at once has none)
  finishPending(true);

  // digest, timings and the tables
  result.stopped = !stop_reason.empty();
  result.next_generation = std::max(g, start);
  if (result.stopped)
    out << "cambrian evolve: " << stop_reason << " after " << result.next_generation
        << " generation(s); run the same command again to continue from "
        << checkpointPath(run.out_dir) << std::endl;
  result.digest = digest.hex();
  result.rank0_cpu_seconds = processCpuSeconds() - cpu_start;
  result.wall_seconds = secondsSince(run_start);
  if (history)
    history->close();
  writeTables(run.out_dir, result);
  return result;
}

}  // namespace cambrian
