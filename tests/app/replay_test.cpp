// tests of `cambrian replay` through the executable, on the history of a tiny walk evolution
// run once per test process (in process, one rank)
#include "cambrian/error.hpp"

#include "app/cli.hpp"
#include "store/history.hpp"
#include "store/trajectory.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace cambrian {
namespace {

using test::lineStartingWith;
using test::runCambrian;

int code(ExitCode c) {
  return static_cast<int>(c);
}

// a number as `replay` prints it (17 significant digits)
std::string printed(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// the words of a line
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> items;
  std::istringstream in(line);
  std::string word;
  while (in >> word)
    items.push_back(word);
  return items;
}

class ReplayCommand : public testing::Test {
 protected:
  // the run: walk, 6 individuals, 2 generations, 1 s measured; every 5th creature made to fail
  static void SetUpTestSuite() {
    dir_ = testing::TempDir() + "/cambrian_replay_test_" + std::to_string(::getpid());
    std::filesystem::remove_all(dir_);
    auto run = runCambrian(
        "evolve --task.name walk --evolution.population 6 --evolution.generations 2 "
        "--task.evaluation_time 1 --run.fail_every 5 --seed 4 --quiet --out " +
        dir_);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    history_ = dir_ + "/history.h5";
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }

  // every individual row of the run
  static std::vector<Individual> rows() { return HistoryReader(history_).individuals(); }

  static std::string dir_;
  static std::string history_;
};

std::string ReplayCommand::dir_;
std::string ReplayCommand::history_;

// every creature that was evaluated with status ok replays to its stored fitness, bit for bit
TEST_F(ReplayCommand, EveryOkCreatureReplaysBitForBit) {
  int replayed = 0;
  for (const Individual& row : rows()) {
    if (row.outcome.status != EvalStatus::ok || row.worker_rank < 0)
      continue;
    auto result = runCambrian("replay --history " + history_ + " --id " + std::to_string(row.id));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(lineStartingWith(result.output, "replay"), "replay         bit-identical")
        << result.output;
    auto fitness = words(lineStartingWith(result.output, "fitness"));
    ASSERT_EQ(fitness.size(), 3u) << result.output;
    EXPECT_EQ(fitness[1], printed(row.fitness()));
    EXPECT_EQ(fitness[2], printed(row.fitness()));
    ++replayed;
  }
  EXPECT_GE(replayed, 3);
}

// --best takes the best ok creature of the whole run, or of one generation
TEST_F(ReplayCommand, BestOfRunAndOfGeneration) {
  std::vector<Individual> all = rows();
  for (int generation : {-1, 0, 1}) {
    const Individual* best = nullptr;
    for (const Individual& row : all) {
      if (row.outcome.status != EvalStatus::ok ||
          (generation >= 0 && row.generation != static_cast<std::uint64_t>(generation)))
        continue;
      if (!best || row.fitness() > best->fitness() ||
          (row.fitness() == best->fitness() && row.id < best->id))
        best = &row;
    }
    ASSERT_NE(best, nullptr);
    std::string arguments = "replay --history " + history_ + " --best";
    if (generation >= 0)
      arguments += " --generation " + std::to_string(generation);
    auto result = runCambrian(arguments);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("creature       id " + std::to_string(best->id) + ","),
              std::string::npos)
        << result.output;
    EXPECT_EQ(words(lineStartingWith(result.output, "fitness"))[1], printed(best->fitness()));
  }
}

// the export holds the replayed creature, and exporting does not change the outcome
TEST_F(ReplayCommand, ExportIsTheSameReplay) {
  std::string traj = dir_ + "/best.h5";
  auto plain = runCambrian("replay --history " + history_ + " --best");
  auto exported =
      runCambrian("replay --history " + history_ + " --best --export " + traj + " --frame-rate 20");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_EQ(lineStartingWith(plain.output, "fitness"),
            lineStartingWith(exported.output, "fitness"));
  Trajectory t = readTrajectory(traj);
  auto id_words = words(lineStartingWith(exported.output, "creature"));
  ASSERT_GE(id_words.size(), 3u);
  EXPECT_EQ(std::to_string(t.creature_id) + ",", id_words[2]);
  EXPECT_EQ(printed(t.fitness), words(lineStartingWith(exported.output, "fitness"))[2]);
  EXPECT_EQ(t.task, "walk");
  EXPECT_EQ(t.source, history_);
  EXPECT_EQ(t.frame_stride, 12u);  // 20 Hz at 1/240 s
  EXPECT_GT(t.frameCount(), 10u);
  EXPECT_GT(t.partCount(), 0u);
  EXPECT_NE(t.genome_text.find("cambrian-genome"), std::string::npos);
}

// a stored fitness that is off by one bit is reported with both values and exit code 10
TEST_F(ReplayCommand, MismatchIsReported) {
  // a copy of the history with one ok creature's stored fitness nudged by one ulp
  std::string copy = dir_ + "/tampered.h5";
  std::filesystem::copy_file(history_, copy, std::filesystem::copy_options::overwrite_existing);
  std::vector<Individual> all = rows();
  std::size_t index = 0;
  while (index < all.size() && all[index].outcome.status != EvalStatus::ok)
    ++index;
  ASSERT_LT(index, all.size());
  {
    hid_t file = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    hid_t dataset = H5Dopen2(file, "individuals/fitness", H5P_DEFAULT);
    std::vector<double> fitness(all.size());
    ASSERT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, fitness.data()),
              0);
    fitness[index] = std::nextafter(fitness[index], 1e9);
    ASSERT_GE(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, fitness.data()),
              0);
    H5Dclose(dataset);
    H5Fclose(file);
  }
  auto result = runCambrian("replay --history " + copy + " --id " + std::to_string(all[index].id));
  EXPECT_EQ(result.exit_code, code(ExitCode::replay_mismatch)) << result.output;
  EXPECT_NE(result.output.find("DIFFERENT"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("0x1."), std::string::npos) << result.output;  // hex floats
  EXPECT_NE(result.output.find(copy), std::string::npos) << result.output;
}

// bad input: a clear message naming the file or the id, and the documented exit code
TEST_F(ReplayCommand, BadInput) {
  auto expect = [](const std::string& arguments, ExitCode wanted, const std::string& words) {
    auto result = runCambrian("replay " + arguments);
    EXPECT_EQ(result.exit_code, code(wanted)) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(words), std::string::npos) << arguments << "\n" << result.output;
  };
  std::string missing = dir_ + "/missing.h5";
  expect("--history " + missing + " --best", ExitCode::input_file, missing);
  std::string text = dir_ + "/text.h5";
  std::ofstream(text) << "not a history\n";
  expect("--history " + text + " --best", ExitCode::input_file, "not an HDF5 file");
  std::string traj = dir_ + "/foreign.h5";
  ASSERT_EQ(runCambrian("replay --history " + history_ + " --best --export " + traj).exit_code, 0);
  expect("--history " + traj + " --best", ExitCode::input_file, "not a cambrian history");
  expect("--history " + history_ + " --id 999999", ExitCode::input_file, "999999");
  expect("--history " + history_ + " --best --generation 2", ExitCode::input_file,
         "generation 2 out of range");
  expect("--history " + history_ + " --id 5", ExitCode::input_file, "status failed");
  expect("--best", ExitCode::usage, "--history");
  expect("--history " + history_, ExitCode::usage, "--id I or --best");
  expect("--history " + history_ + " --id 1 --best", ExitCode::usage, "--id I or --best");
  expect("--history " + history_ + " --id 1 --generation 0", ExitCode::usage, "--generation");
  expect("--history " + history_ + " --best --export " + dir_ + "/x.h5 --frame-rate 0",
         ExitCode::config, "frame rate");
  expect("--history " + history_ + " --best --export " + dir_ + "/no/such/dir/x.h5",
         ExitCode::output_file, dir_ + "/no/such/dir/x.h5");
}

// --help describes the command and exits 0
TEST(ReplayHelp, Help) {
  auto result = runCambrian("replay --help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("--history"), std::string::npos);
  EXPECT_NE(result.output.find("--export"), std::string::npos);
  auto usage = runCambrian("--help");
  EXPECT_NE(usage.output.find("replay"), std::string::npos);
}

// simulate --export writes a trajectory of a hand-written creature with the same outcome
TEST(SimulateExport, HandWrittenCreature) {
  std::string genome = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/walker4.genome";
  std::string traj =
      testing::TempDir() + "/cambrian_simulate_export_" + std::to_string(::getpid()) + ".h5";
  auto plain = runCambrian("simulate --genome " + genome + " --task.evaluation_time 1");
  auto exported =
      runCambrian("simulate --genome " + genome + " --task.evaluation_time 1 --export " + traj);
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_EQ(lineStartingWith(plain.output, "fitness"),
            lineStartingWith(exported.output, "fitness"));
  Trajectory t = readTrajectory(traj);
  EXPECT_EQ(t.creature_id, kNoCreatureId);
  EXPECT_EQ(t.source, genome);
  EXPECT_EQ(t.partCount(), 5u);
  EXPECT_EQ(words(lineStartingWith(plain.output, "fitness"))[1], printed(t.fitness));
  std::filesystem::remove(traj);
}

}  // namespace
}  // namespace cambrian
