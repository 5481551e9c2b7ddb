#include "parallel/evolution_run.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace cambrian {
namespace {

RunResult runOnce(const std::string& dir, std::ostream& out) {
  EvolutionSettings settings;
  settings.population = 10;
  settings.generations = 3;
  settings.seed = 4;
  WorkerSettings worker;
  worker.task.kind = TaskKind::synthetic;
  worker.task.synthetic_cost_us = 20;
  InProcessEvaluator evaluator(worker);
  RunSettings run;
  run.out_dir = dir;
  return runEvolution(settings, worker.limits, {}, evaluator, run, out);
}

TEST(EvolutionRun, RecordsEveryIndividualAndGenerationAndWritesTables) {
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test";
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
}

TEST(EvolutionRun, SameSettingsSameDigest) {
  std::ostringstream out;
  std::string dir = testing::TempDir() + "/cambrian_evolution_run_test2";
  EXPECT_EQ(runOnce(dir, out).digest, runOnce(dir, out).digest);
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
