// Tests of the run driver: records and tables, digests, stop and resume, the times of each
// generation, the checkpoint cadence, extending a finished run, refusing changed settings.
#include "run/evolution_run.hpp"

#include "cambrian/error.hpp"

#include "run/small_synthetic_run.hpp"
#include "run/tables.hpp"
#include "store/checkpoint.hpp"
#include "store/history.hpp"
#include "tasks/task.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace cambrian {
namespace {

// a small synthetic run (population 10, seed 4); `fresh` ignores a checkpoint left in `dir`
RunResult runOnce(const std::string& dir, std::ostream& out, bool fresh = true, int generations = 3,
                  RunSettings run = {}) {
  return smallSyntheticRun(EvolutionMode::generational, dir, out, fresh, 10, generations,
                           std::move(run), 4);
}

// the same as a steady state (seed `seed`)
RunResult runSteady(const std::string& dir, std::ostream& out, bool fresh = true,
                    int generations = 3, RunSettings run = {}, std::uint64_t seed = 4) {
  return smallSyntheticRun(EvolutionMode::steady_state, dir, out, fresh, 10, generations,
                           std::move(run), seed);
}

// a stop request that turns true on its second poll (after one generation)
int stop_polls = 0;
bool stopOnSecondPoll() {
  return ++stop_polls >= 2;
}
const char* stopName() {
  return "a test";
}

// the deterministic columns of the individual records
std::vector<std::string> recordKeys(const RunResult& result) {
  std::vector<std::string> keys;
  const std::vector<MeasureInfo> measures = {{"cost_us", "us"}, {"nodes", "1"}};
  for (const Individual& r : result.individuals) {
    Individual copy = r;
    copy.eval_seconds = 0;
    copy.worker_rank = 0;
    keys.push_back(individualsTsvRow(copy, measures));
  }
  return keys;
}

TEST(EvolutionRun, RecordsEveryIndividualAndGenerationAndWritesTables) {
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test";
  std::filesystem::remove_all(dir);
  std::ostringstream out;
  RunResult result = runOnce(dir, out);
  EXPECT_EQ(result.individuals.size(), 30u);
  ASSERT_EQ(result.generations.size(), 3u);
  EXPECT_EQ(result.generations[0].evaluations, 10u);
  EXPECT_EQ(result.generations[1].evaluations, 8u);  // two elites are not re-evaluated
  EXPECT_GE(result.generations[2].stats.best, result.generations[0].stats.best);
  EXPECT_TRUE(std::filesystem::exists(dir + "/individuals.tsv"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/generations.tsv"));
  EXPECT_NE(out.str().find("gen 3/3"), std::string::npos);
  EXPECT_NE(out.str().find("eta"), std::string::npos);
  // the records keep no genomes (the history does), the history stores the task's measures
  for (const Individual& individual : result.individuals)
    EXPECT_FALSE(individual.genome);
  HistoryReader reader(dir + "/history.h5");
  EXPECT_EQ(reader.measures(), (std::vector<MeasureInfo>{{"cost_us", "us"}, {"nodes", "1"}}));
  EXPECT_EQ(reader.individuals()[4].outcome.measure("nodes"),
            result.individuals[4].outcome.measure("nodes"));
  EXPECT_EQ(reader.attributes().run_only_settings,
            (std::vector<std::string>{"evolution.generations", "run.out"}));
}

// a synthetic run from ten copies of one seed genome (population 10, 3 generations)
RunResult runFromCopies(const std::string& dir, bool repeatable, bool reuse) {
  EvolutionSettings settings;
  settings.population = 10;
  settings.generations = 3;
  settings.seed = 4;
  WorkerSettings worker;
  worker.creature.set("task.name", "synthetic");
  worker.creature.set("task.synthetic_cost_us", "20");
  const Encoding& encoding = worker.creature.encoding();
  std::vector<Genotype> seeds(10, encoding.random(9, 0, 0));
  InProcessEvaluator evaluator(worker);
  RunSettings run;
  run.out_dir = dir;
  run.fresh = true;
  run.quiet = true;
  run.measures = worker.creature.task().measures();
  run.repeatable = repeatable;
  run.reuse_outcomes = reuse;
  run.config_text = "[evolution]\ngenerations = 3\npopulation = 10\n";
  std::ostringstream out;
  return runEvolution(settings, encoding, seeds, evaluator, run, out);
}

std::size_t totalEvaluations(const RunResult& result) {
  std::size_t total = 0;
  for (const GenerationRecord& record : result.generations)
    total += record.evaluations;
  return total;
}

TEST(EvolutionRun, CopiesOfAnEvaluatedGenomeTakeItsOutcomeWithTheSameResults) {
  // without noise the synthetic task's outcome is a function of the genome, as a body task's
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_reuse";
  RunResult reused = runFromCopies(dir + "/reused", true, true);
  RunResult evaluated = runFromCopies(dir + "/evaluated", true, false);
  EXPECT_EQ(reused.digest, evaluated.digest);
  EXPECT_EQ(recordKeys(reused), recordKeys(evaluated));
  // ten equal seeds: one simulated, nine copies that took its outcome, on no rank
  EXPECT_EQ(evaluated.generations[0].evaluations, 10u);
  EXPECT_EQ(reused.generations[0].evaluations, 1u);
  int copies = 0;
  for (const Individual& individual : reused.individuals)
    if (individual.generation == 0 && individual.worker_rank == -1)
      ++copies;
  EXPECT_EQ(copies, 9);
  EXPECT_LT(totalEvaluations(reused), totalEvaluations(evaluated));
  // a task that is not repeatable (a noisy one) evaluates every copy
  RunResult noisy = runFromCopies(dir + "/noisy", false, true);
  EXPECT_EQ(totalEvaluations(noisy), totalEvaluations(evaluated));
  std::filesystem::remove_all(dir);
}

TEST(EvolutionRun, SameSettingsSameDigest) {
  std::ostringstream out;
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test2";
  EXPECT_EQ(runOnce(dir, out).digest, runOnce(dir, out).digest);
}

TEST(EvolutionRun, StoppedAndResumedRunEqualsTheStraightRun) {
  std::ostringstream out;
  std::string base = testing::TempDir() + "/cambrian_evolution_run_test_";
  RunResult straight = runOnce(base + "straight", out);
  EXPECT_TRUE(std::filesystem::exists(base + "straight/checkpoint.h5"));

  // stopped after one generation: checkpointed, not finished
  std::string dir = base + "stopped";
  RunSettings stopping;
  stop_polls = 0;
  stopping.stop_requested = stopOnSecondPoll;
  stopping.stop_reason = stopName;
  std::ostringstream first;
  RunResult stopped = runOnce(dir, first, true, 3, stopping);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(stopped.next_generation, 1u);
  EXPECT_EQ(stopped.generations.size(), 1u);
  EXPECT_NE(first.str().find("stopped by a test after 1 generation(s)"), std::string::npos)
      << first.str();

  // the same run again continues and ends as the straight run
  std::ostringstream second;
  RunResult resumed = runOnce(dir, second, false);
  EXPECT_TRUE(resumed.resumed);
  EXPECT_FALSE(resumed.stopped);
  EXPECT_NE(second.str().find("resuming from " + dir + "/checkpoint.h5 at generation 1"),
            std::string::npos)
      << second.str();
  EXPECT_EQ(resumed.digest, straight.digest);
  EXPECT_EQ(recordKeys(resumed), recordKeys(straight));
  ASSERT_EQ(resumed.generations.size(), 3u);
  EXPECT_EQ(resumed.generations[2].stats.best, straight.generations[2].stats.best);
}

// checks that each history row's times hold its history append and its checkpoint, and that the
// history and the tables agree
void expectCompleteTimes(const std::string& dir, const RunResult& result) {
  HistoryReader reader(dir + "/history.h5");
  const std::vector<GenerationRecord>& rows = reader.generations();
  ASSERT_EQ(rows.size(), result.generations.size());
  double walls = 0;
  for (std::size_t g = 0; g < rows.size(); ++g) {
    // a generation's checkpoint is written while the next one starts (in process: before its
    // evaluations, so in its serial time), the last one's at the end of its own time
    bool last = g + 1 == rows.size();
    EXPECT_GE(rows[g].wall_seconds,
              rows[g].evaluation_span_seconds + (last ? rows[g].checkpoint_seconds : 0))
        << g;
    EXPECT_GE(last ? rows[g].rank0_serial_seconds : rows[g + 1].rank0_serial_seconds,
              rows[g].checkpoint_seconds)
        << g;
    EXPECT_EQ(rows[g].wall_seconds, result.generations[g].wall_seconds) << g;
    EXPECT_EQ(rows[g].rank0_serial_seconds, result.generations[g].rank0_serial_seconds) << g;
    EXPECT_EQ(rows[g].rank0_cpu_seconds, result.generations[g].rank0_cpu_seconds) << g;
    walls += rows[g].wall_seconds;
  }
  // the generations follow each other without overlap
  EXPECT_LE(walls, result.wall_seconds);
}

// which generation rows of DIR/history.h5 record a checkpoint
std::vector<bool> checkpointed(const std::string& dir) {
  std::vector<bool> rows;
  for (const GenerationRecord& row : HistoryReader(dir + "/history.h5").generations())
    rows.push_back(row.checkpoint_seconds > 0);
  return rows;
}

TEST(EvolutionRun, GenerationTimesTileTheRunAndHoldEveryCheckpoint) {
  // a checkpoint after every generation
  std::ostringstream out;
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_times";
  RunSettings every;
  every.checkpoint_every = 1;
  expectCompleteTimes(dir, runOnce(dir, out, true, 3, every));
  EXPECT_EQ(checkpointed(dir), (std::vector<bool>{true, true, true}));

  // no cadence: only the stop's checkpoint, which goes into the last row
  dir += "_stopped";
  RunSettings stopping;
  stop_polls = 0;
  stopping.stop_requested = stopOnSecondPoll;
  stopping.stop_reason = stopName;
  stopping.checkpoint_every = 0;
  RunResult stopped = runOnce(dir, out, true, 3, stopping);
  ASSERT_TRUE(stopped.stopped);
  expectCompleteTimes(dir, stopped);
  EXPECT_EQ(checkpointed(dir), (std::vector<bool>{true}));
}

TEST(EvolutionRun, TheDefaultCadenceIsTheFirstGenerationAMinuteAndTheLast) {
  // generations far shorter than a minute: only the first and the last have a checkpoint
  RunSettings defaults;
  EXPECT_EQ(defaults.checkpoint_every, 0);
  EXPECT_EQ(defaults.checkpoint_minutes, 1.0);
  std::ostringstream out;
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_cadence";
  RunResult result = runOnce(dir, out, true, 4);
  expectCompleteTimes(dir, result);
  EXPECT_EQ(checkpointed(dir), (std::vector<bool>{true, false, false, true}));

  // a cadence by the clock that has already passed: every generation
  RunSettings clock;
  clock.checkpoint_minutes = 1e-9;
  runOnce(dir, out, true, 3, clock);
  EXPECT_EQ(checkpointed(dir), (std::vector<bool>{true, true, true}));
}

TEST(EvolutionRun, MoreGenerationsExtendAFinishedRun) {
  std::ostringstream out;
  std::string base = testing::TempDir() + "/cambrian_evolution_run_test_";
  RunResult straight = runOnce(base + "long", out, true, 4);
  runOnce(base + "extended", out, true, 2);
  RunResult extended = runOnce(base + "extended", out, false, 4);
  EXPECT_TRUE(extended.resumed);
  EXPECT_EQ(extended.digest, straight.digest);
  EXPECT_EQ(recordKeys(extended), recordKeys(straight));
}

TEST(EvolutionRun, AChangedResultSettingIsRefused) {
  std::ostringstream out;
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_changed";
  runOnce(dir, out, true, 2);
  RunSettings changed;
  changed.config_text =
      "[evolution]\ngenerations = 2\npopulation = 10\n\n[run]\nout = " + dir + "\nseed = 5\n";
  try {
    runOnce(dir, out, false, 2, changed);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::checkpoint);
    EXPECT_NE(std::string(e.what()).find("run.seed was '4'"), std::string::npos) << e.what();
  }
}

TEST(EvolutionRun, ASteadyStateTakesInGenerationsOfPopulationResults) {
  std::ostringstream out;
  const std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_steady";
  RunResult result = runSteady(dir, out);
  ASSERT_EQ(result.generations.size(), 3u);
  ASSERT_EQ(result.individuals.size(), 30u);
  for (const GenerationRecord& record : result.generations) {
    EXPECT_EQ(record.evaluations, 10u);
    EXPECT_EQ(record.stats.count, 10u);  // the members' statistics
  }
  // a result replaces a member only when at least as fit: the best never falls
  EXPECT_LE(result.generations[0].stats.best, result.generations[1].stats.best);
  EXPECT_LE(result.generations[1].stats.best, result.generations[2].stats.best);
  // in process one creature is out at a time: the first generation, then each child bred
  // after the result before it, taken in in id order
  const std::vector<Individual> rows = HistoryReader(dir + "/history.h5").individuals();
  ASSERT_EQ(rows.size(), 30u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].id, i);
    EXPECT_EQ(rows[i].generation, i / 10);
    EXPECT_EQ(rows[i].bred_after, i < 10 ? 0u : i) << "row " << i;
    EXPECT_EQ(rows[i].origin == Origin::random, i < 10) << "row " << i;
  }
  // the same settings give the same run; the generational mode another
  EXPECT_EQ(runSteady(dir, out).digest, result.digest);
  EXPECT_NE(runOnce(dir, out).digest, result.digest);
}

TEST(EvolutionRun, AStoppedSteadyStateResumesToTheStraightRun) {
  std::ostringstream out;
  const std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_steady_resume";
  RunResult straight = runSteady(dir, out);
  stop_polls = 0;
  RunSettings stopping;
  stopping.stop_requested = stopOnSecondPoll;
  stopping.stop_reason = stopName;
  RunResult stopped = runSteady(dir, out, true, 3, stopping);
  ASSERT_TRUE(stopped.stopped);
  EXPECT_EQ(stopped.next_generation, 1u);
  // the checkpoint holds the members (in process nothing is in flight at a generation's end:
  // the next child is bred after it)
  CheckpointState checkpoint = readCheckpoint(dir + "/checkpoint.h5");
  EXPECT_TRUE(checkpoint.steady_state);
  EXPECT_EQ(checkpoint.population.individuals.size(), 10u);
  EXPECT_TRUE(checkpoint.population.allEvaluated());
  std::ostringstream second;
  RunResult resumed = runSteady(dir, second, false);
  EXPECT_TRUE(resumed.resumed);
  EXPECT_EQ(resumed.digest, straight.digest);
  EXPECT_EQ(recordKeys(resumed), recordKeys(straight));
}

TEST(EvolutionRun, ASteadyStateFollowsARecordedOrderOfItsOwnSettingsOnly) {
  std::ostringstream out;
  const std::string recorded = testing::TempDir() + "/cambrian_evolution_run_test_recorded";
  const std::string dir = testing::TempDir() + "/cambrian_evolution_run_test_following";
  RunResult original = runSteady(recorded, out);
  RunSettings following;
  following.arrival_order = recorded + "/history.h5";
  EXPECT_EQ(runSteady(dir, out, true, 3, following).digest, original.digest);
  // a longer run goes on past the record as results arrive
  EXPECT_EQ(runSteady(dir, out, true, 4, following).generations.size(), 4u);
  // another seed's record is refused, naming the key and the file
  try {
    runSteady(dir, out, true, 3, following, 5);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::config);
    EXPECT_NE(std::string(e.what()).find("run.arrival_order = " + following.arrival_order),
              std::string::npos)
        << e.what();
  }
}

TEST(EvolutionRun, ProgressLineNamesTheFigures) {
  GenerationRecord r;
  r.generation = 1;
  r.stats.best = 2.5;
  r.workers = 2;
  r.evaluations = 10;
  r.evaluation_span_seconds = 2;
  r.worker_busy_seconds = 3;
  std::string line = progressLine(r, 30, 3725);
  EXPECT_NE(line.find("gen 2/30"), std::string::npos);
  EXPECT_NE(line.find("best 2.5"), std::string::npos);
  EXPECT_NE(line.find("evals/s 5.0"), std::string::npos);
  EXPECT_NE(line.find("util 75%"), std::string::npos);
  EXPECT_NE(line.find("eta 1:02:05"), std::string::npos);
}

}  // namespace
}  // namespace cambrian
