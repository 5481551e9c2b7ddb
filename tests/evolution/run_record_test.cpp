#include "evolution/run_record.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cambrian {
namespace {

Individual someone(std::uint64_t id, double fitness) {
  Individual individual;
  individual.id = id;
  individual.genome.nodes.resize(1);
  individual.outcome.fitness = fitness;
  individual.evaluated = true;
  return individual;
}

TEST(RunDigest, DependsOnIdsGenomesAndFitnessButNotTimings) {
  RunDigest a, b, c, d;
  Individual x = someone(1, 0.5);
  a.add(x);
  x.eval_seconds = 3;
  x.worker_rank = 4;
  b.add(x);
  EXPECT_EQ(a.value(), b.value());
  c.add(someone(1, 0.5000000001));
  EXPECT_NE(a.value(), c.value());
  Individual y = someone(1, 0.5);
  y.genome.nodes[0].density = 900;
  d.add(y);
  EXPECT_NE(a.value(), d.value());
  EXPECT_EQ(a.hex().size(), 16u);
}

TEST(RunRecord, TsvRowHoldsEveryColumn) {
  Individual x = someone(7, 0.25);
  x.generation = 2;
  x.parents = {3, 5};
  x.origin = Origin::crossover;
  x.outcome.parts = 4;
  x.worker_rank = 2;
  std::string row = individualsTsvRow(makeIndividualRecord(x));
  EXPECT_EQ(row, "2\t7\t3,5\tcrossover\t0.25\tok\t4\t0.000000\t2\n");
  std::string header = individualsTsvHeader();
  EXPECT_EQ(std::count(header.begin(), header.end(), '\t'), 8);
}

TEST(RunRecord, GenerationUtilisation) {
  GenerationRecord r;
  r.workers = 2;
  r.evaluations = 10;
  r.evaluation_span_seconds = 1;
  r.worker_busy_seconds = 1.5;
  EXPECT_DOUBLE_EQ(r.utilisation(), 0.75);
  EXPECT_DOUBLE_EQ(r.evaluationsPerSecond(), 10);
  EXPECT_NE(generationsTsvRow(r).find("\t2\t"), std::string::npos);
}

TEST(RunRecord, AtomicWriteReplacesTheFile) {
  std::string path = testing::TempDir() + "/cambrian_run_record_test.tsv";
  writeTextFileAtomically(path, "one\n");
  writeTextFileAtomically(path, "two\n");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "two\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  EXPECT_THROW(writeTextFileAtomically("/nonexistent-dir/x.tsv", "x"), Error);
}

}  // namespace
}  // namespace cambrian
