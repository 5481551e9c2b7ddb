#include "parallel/evolution_run.hpp"

#include "cambrian/error.hpp"

#include "evolution/breeder.hpp"
#include "evolution/statistics.hpp"
#include "parallel/mpi_context.hpp"
#include "store/history.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
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

// DIR/history.h5 with the run's provenance, or none when the run keeps no history
std::unique_ptr<HistoryWriter> openHistory(const EvolutionSettings& settings,
                                           const RunSettings& run) {
  if (!run.history)
    return nullptr;
  makeOutputDirectory(run.out_dir);
  HistoryAttributes attributes;
  attributes.config_text = run.config_text;
  attributes.seed = settings.seed;
  attributes.rank_count = run.rank_count;
  return std::make_unique<HistoryWriter>(run.out_dir + "/history.h5", attributes);
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
  RunDigest digest;
  double cpu_start = processCpuSeconds();
  auto run_start = Clock::now();

  // generation 0
  Breeder breeder(settings, limits);
  if (run.viable)
    breeder.setViabilityCheck(run.viable);
  Population population = breeder.initialPopulation(seeds);
  std::unique_ptr<HistoryWriter> history = openHistory(settings, run);

  for (int g = 0; g < settings.generations; ++g) {
    auto generation_start = Clock::now();

    // evaluate what is new, then summarise in id order
    EvaluationSpan span = evaluator.evaluate(population, settings.seed);
    GenerationRecord record;
    record.generation = population.generation;
    record.stats = computeStats(population);
    record.evaluations = span.evaluations;
    record.workers = span.workers;
    record.evaluation_span_seconds = span.span_seconds;
    record.worker_busy_seconds = span.busy_seconds;
    record.worker_idle_seconds =
        std::max(0.0, span.workers * span.span_seconds - span.busy_seconds);
    digest.add(population);
    appendRecords(population, result.individuals);

    // the history rows of the evaluated generation (appended once its timings are known)
    std::vector<HistoryIndividual> history_rows;
    HistoryGeneration history_generation;
    if (history) {
      for (const Individual& individual : population.individuals)
        history_rows.push_back(makeHistoryIndividual(individual));
      history_generation = makeHistoryGeneration(record, population);
    }

    // breed the next generation (rank 0's serial part)
    if (g + 1 < settings.generations)
      population = breeder.nextGeneration(population);
    record.wall_seconds = std::chrono::duration<double>(Clock::now() - generation_start).count();
    record.rank0_serial_seconds = std::max(0.0, record.wall_seconds - span.span_seconds);
    result.generations.push_back(record);

    // append and flush the generation to the history
    if (history) {
      history_generation.rank0_serial_seconds = record.rank0_serial_seconds;
      history_generation.wall_seconds = record.wall_seconds;
      history->appendGeneration(history_rows, history_generation);
    }

    // progress
    double elapsed = std::chrono::duration<double>(Clock::now() - run_start).count();
    double eta = elapsed / (g + 1) * (settings.generations - g - 1);
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

  // digest, timings and the tables
  result.digest = digest.hex();
  result.rank0_cpu_seconds = processCpuSeconds() - cpu_start;
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - run_start).count();
  if (history)
    history->close();
  writeTables(run.out_dir, result);
  return result;
}

}  // namespace cambrian
