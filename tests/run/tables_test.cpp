// Tests of the run's tables: the individuals table's fixed columns and one column per measure,
// the generations table, atomic writing.
#include "run/tables.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cambrian {
namespace {

TEST(Tables, IndividualRowHoldsEveryColumnAndTheMeasuresByName) {
  Individual x;
  x.id = 7;
  x.generation = 2;
  x.parents = {3, 5};
  x.origin = Origin::crossover;
  x.evaluated = true;
  x.outcome.fitness = 0.25;
  x.outcome.parts = 4;
  x.outcome.measures = {{"height", 0.5}, {"distance", 1.0 / 3.0}};
  x.worker_rank = 2;
  const std::vector<MeasureInfo> measures = {{"distance", "m"}, {"speed", "m/s"}, {"height", "m"}};
  EXPECT_EQ(individualsTsvRow(x, measures),
            "2\t7\t3,5\tcrossover\t0.25\tok\t4\t0.000000\t2\t0.33333333333333331\tnan\t0.5\n");
  std::string header = individualsTsvHeader(measures);
  EXPECT_EQ(std::count(header.begin(), header.end(), '\t'), 8 + 3);
  EXPECT_EQ(header.substr(header.rfind("worker_rank")), "worker_rank\tdistance\tspeed\theight\n");
  // without parents
  x.parents.clear();
  EXPECT_NE(individualsTsvRow(x, {}).find("\t-\t"), std::string::npos);
}

TEST(Tables, GenerationRow) {
  GenerationRecord r;
  r.generation = 3;
  r.workers = 2;
  r.evaluations = 10;
  r.fitness_deviation = 0.125;
  r.mutation_multiplier = 2;
  std::string row = generationsTsvRow(r);
  EXPECT_EQ(row.rfind("3\t", 0), 0u);
  EXPECT_NE(row.find("\t10\t2\t"), std::string::npos);
  // the wwd scheme's diversity and mutation multiplier, last
  EXPECT_EQ(row.substr(row.size() - 9), "\t0.125\t2\n");
  std::string header = generationsTsvHeader();
  EXPECT_EQ(header.substr(header.rfind("\tfitness_deviation")),
            "\tfitness_deviation\tmutation_multiplier\n");
  EXPECT_EQ(std::count(header.begin(), header.end(), '\t'),
            std::count(row.begin(), row.end(), '\t'));
}

TEST(Tables, AtomicWriteReplacesTheFile) {
  std::string path = testing::TempDir() + "/cambrian_tables_test.tsv";
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
