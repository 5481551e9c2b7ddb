// tests of `cambrian replay` through the executable, on the history of a tiny walk evolution
// run once per test process (in process, one rank)
#include "cambrian/error.hpp"

#include "app/cli.hpp"
#include "core/settings.hpp"
#include "store/history.hpp"
#include "store/trajectory.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace cambrian {
namespace {

using test::code;
using test::lineStartingWith;
using test::runCambrian;

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
  // a negative id or generation does not wrap around; a bad frame rate is refused unused
  expect("--history " + history_ + " --id -1", ExitCode::usage, "--id -1: expected a whole number");
  expect("--history " + history_ + " --best --generation -2", ExitCode::usage,
         "--generation -2: expected a whole number");
  for (const char* rate : {"0", "nan", "-5"})
    expect("--history " + history_ + " --best --frame-rate " + rate, ExitCode::config,
           "frame rate");
  expect("--history " + history_ + " --best --export " + dir_ + "/no/such/dir/x.h5",
         ExitCode::output_file, dir_ + "/no/such/dir/x.h5");
}

// the text of a file
std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// the stored text form of individual `id`'s genome
std::string storedGenomeText(const std::vector<Individual>& all, std::uint64_t id) {
  for (const Individual& row : all) {
    if (row.id == id)
      return row.genome.encoding().toText(row.genome);
  }
  return "";
}

// the id replay printed on its creature line ("creature       id 7, generation ...")
std::uint64_t replayedId(const std::string& output) {
  auto items = words(lineStartingWith(output, "creature"));
  return items.size() >= 3 ? std::stoull(items[2]) : kNoId;
}

// a changed evaluation time (command line) and time step (config file) are listed with stored
// and new values before the table; both outcomes are shown, nothing is compared, exit 0
// a damaged history fails at once (exit 4, naming the file): a finished file is opened plainly,
// not as SWMR, whose reader retries a bad metadata checksum for minutes
TEST_F(ReplayCommand, ADamagedHistoryFailsAtOnce) {
  std::ifstream in(history_, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::size_t> headers;  // object headers ("OHDR", checksummed)
  for (std::size_t at = bytes.find("OHDR"); at != std::string::npos;
       at = bytes.find("OHDR", at + 1))
    headers.push_back(at);
  ASSERT_GT(headers.size(), 9u);
  for (std::size_t which : {3u, 6u, 9u}) {
    std::string damaged = bytes;
    damaged[headers[which] + 8] ^= 0x40;
    std::string path = dir_ + "/damaged" + std::to_string(which) + ".h5";
    std::ofstream(path, std::ios::binary) << damaged;
    auto result = runCambrian("replay --history " + path + " --best");
    EXPECT_EQ(result.exit_code, code(ExitCode::input_file)) << which << result.output;
    EXPECT_NE(result.output.find(path), std::string::npos) << result.output;
  }
}

TEST_F(ReplayCommand, AHistoryThatSendsHdf5IntoAnEndlessLoopEndsWithinTheBound) {
  // a damaged history found by fuzzing: HDF5 1.10 loops in H5HG_read on one of its attributes
  std::string path =
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/store/data/history_hdf5_endless_loop.h5";
  ::setenv("CAMBRIAN_READ_SECONDS", "2", 1);
  auto result = runCambrian("replay --history " + path + " --best");
  ::unsetenv("CAMBRIAN_READ_SECONDS");
  EXPECT_EQ(result.exit_code, code(ExitCode::input_file)) << result.output;
  EXPECT_NE(result.output.find(path + ": reading the file did not end within 2 s"),
            std::string::npos)
      << result.output;
}

TEST_F(ReplayCommand, AHistoryThatCrashesHdf5IsRefusedNotCrashedOn) {
  // a damaged history found by fuzzing: HDF5 1.10 copies from a wild address in H5HG_read
  std::string path = std::string(CAMBRIAN_SOURCE_DIR) + "/tests/store/data/history_hdf5_crash.h5";
  auto result = runCambrian("replay --history " + path + " --best");
  EXPECT_EQ(result.exit_code, code(ExitCode::input_file)) << result.output;
  EXPECT_NE(result.output.find(path + ": reading the file crashed the HDF5 library"),
            std::string::npos)
      << result.output;
}

TEST_F(ReplayCommand, ChangedSettingsAreShownNotCompared) {
  std::string stored_step =
      iniValues(HistoryReader(history_).attributes().config_text)["physics.time_step"];
  ASSERT_FALSE(stored_step.empty());
  ASSERT_NE(stored_step, "0.0035");
  std::string config = dir_ + "/changed.ini";
  std::ofstream(config) << "[physics]\ntime_step = 0.0035\n";
  auto result = runCambrian("replay --history " + history_ +
                            " --best --task.evaluation_time 2 --config " + config);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("changed        physics.time_step: stored " + stored_step +
                               ", replayed with 0.0035\n"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("changed        task.evaluation_time: stored 1, replayed with 2\n"),
            std::string::npos)
      << result.output;
  std::size_t note = result.output.find("made under other settings");
  ASSERT_NE(note, std::string::npos) << result.output;
  EXPECT_LT(note, result.output.find("\nstatus")) << result.output;
  EXPECT_NE(lineStartingWith(result.output, "task").find("2 s measured, step 0.0035 s"),
            std::string::npos)
      << result.output;
  auto steps = words(lineStartingWith(result.output, "steps"));
  ASSERT_EQ(steps.size(), 3u) << result.output;
  EXPECT_NE(steps[1], steps[2]);
  EXPECT_EQ(result.output.find("DIFFERENT"), std::string::npos) << result.output;
  EXPECT_EQ(lineStartingWith(result.output, "replay"),
            "replay         under changed settings (not compared)");
}

// a creature that fails under the changed settings: the monitor's message says why
TEST_F(ReplayCommand, AFailureUnderChangedSettingsSaysWhy) {
  auto result = runCambrian("replay --history " + history_ + " --best --physics.max_speed 1e-6");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(words(lineStartingWith(result.output, "status")).back(), "exploded") << result.output;
  EXPECT_NE(lineStartingWith(result.output, "why").find("(physics.max_speed 1e-06)"),
            std::string::npos)
      << result.output;
  // a replay that passes has no such line
  auto same = runCambrian("replay --history " + history_ + " --best");
  EXPECT_EQ(lineStartingWith(same.output, "why"), "") << same.output;
}

// a setting given equal to the stored value changes nothing: the replay is still compared bit
// for bit (command line and config file)
TEST_F(ReplayCommand, SettingEqualToStoredIsStillCompared) {
  std::string config = dir_ + "/same.ini";
  std::ofstream(config) << "[task]\nname = walk\n";
  auto result = runCambrian("replay --history " + history_ +
                            " --best --task.evaluation_time 1.0 --config " + config);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(lineStartingWith(result.output, "replay"), "replay         bit-identical")
      << result.output;
  EXPECT_NE(result.output.find("setting        task.evaluation_time = 1 as stored (unchanged)"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("setting        task.name = walk as stored (unchanged)"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("changed "), std::string::npos) << result.output;
}

// an export under changed settings records them in the trajectory's source
TEST_F(ReplayCommand, ExportUnderChangedSettingsSaysSo) {
  std::string traj = dir_ + "/changed_traj.h5";
  auto result = runCambrian("replay --history " + history_ +
                            " --best --task.evaluation_time 2 --export " + traj);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  Trajectory t = readTrajectory(traj);
  EXPECT_EQ(t.source,
            history_ + " (replayed under changed settings: task.evaluation_time = 2 (stored 1))");
  EXPECT_EQ(printed(t.fitness), words(lineStartingWith(result.output, "fitness"))[2]);
  EXPECT_EQ(t.creature_id, replayedId(result.output));
  EXPECT_GT(t.time.back(), 2.0);  // the longer evaluation was recorded
}

// settings that are bad, unknown or that replay cannot change: the documented exit codes,
// naming the key (and the file)
TEST_F(ReplayCommand, BadSettings) {
  auto expect = [](const std::string& arguments, ExitCode wanted,
                   const std::vector<std::string>& phrases) {
    auto result = runCambrian("replay --history " + history_ + " --best " + arguments);
    EXPECT_EQ(result.exit_code, code(wanted)) << arguments << "\n" << result.output;
    for (const std::string& phrase : phrases)
      EXPECT_NE(result.output.find(phrase), std::string::npos) << arguments << "\n"
                                                               << result.output;
  };
  expect("--task.evaluation_time -1", ExitCode::config,
         {"command line: --task.evaluation_time = -1"});
  expect("--physics.world nosuch", ExitCode::config, {"physics.world = nosuch"});
  expect("--task.evaluation_time many", ExitCode::usage, {"task.evaluation_time", "many"});
  expect("--task.no_such_key 1", ExitCode::usage, {"task.no_such_key"});
  expect("--genome.max_parts 5", ExitCode::usage,
         {"--genome.max_parts", "cannot change [genome] settings", "--save-genome"});
  expect("--evolution.add_node_rate 0.5", ExitCode::usage,
         {"--evolution.add_node_rate", "only [environment], [physics] and [task]"});
  std::string genome_ini = dir_ + "/genome.ini";
  std::ofstream(genome_ini) << "[genome]\nmax_parts = 5\n";
  expect("--config " + genome_ini, ExitCode::config,
         {genome_ini, "genome.max_parts", "cannot change [genome] settings"});
  std::string unknown_ini = dir_ + "/unknown.ini";
  std::ofstream(unknown_ini) << "[physics]\nno_such_key = 1\n";
  expect("--config " + unknown_ini, ExitCode::config, {unknown_ini, "no_such_key"});
  std::string bad_ini = dir_ + "/bad.ini";
  std::ofstream(bad_ini) << "[physics]\ntime_step = 0\n";
  expect("--config " + bad_ini, ExitCode::config, {bad_ini, "physics.time_step = 0"});
  expect("--config " + dir_ + "/missing.ini", ExitCode::config, {dir_ + "/missing.ini"});
}

// --save-genome writes the stored genome's text form; simulate evaluates that file with the
// replay's evaluation seed and the run's settings to the replayed fitness, bit for bit
TEST_F(ReplayCommand, SavedGenomeIsTheStoredOne) {
  std::string path = dir_ + "/best.genome";
  auto result = runCambrian("replay --history " + history_ + " --best --save-genome " + path);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(lineStartingWith(result.output, "replay"), "replay         bit-identical");
  EXPECT_EQ(lineStartingWith(result.output, "genome"),
            "genome         saved to " + path + " (text form)");
  std::string text = fileText(path);
  EXPECT_EQ(text, storedGenomeText(rows(), replayedId(result.output)));
  EXPECT_EQ(text.rfind("cambrian-genome", 0), 0u) << text;
  auto seed = words(lineStartingWith(result.output, "eval seed"));
  ASSERT_EQ(seed.size(), 3u) << result.output;
  auto simulated =
      runCambrian("simulate --genome " + path + " --task.evaluation_time 1 --seed " + seed[2]);
  ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
  EXPECT_EQ(lineStartingWith(simulated.output, "status"), "status     ok");
  EXPECT_EQ(words(lineStartingWith(simulated.output, "fitness"))[1],
            words(lineStartingWith(result.output, "fitness"))[2]);
}

// --save-genome replaces a file that is there (and says so); a path that cannot be written is
// exit 5 naming it; the history itself is refused
TEST_F(ReplayCommand, SaveGenomeOutputs) {
  std::string path = dir_ + "/replaced.genome";
  std::ofstream(path) << "old contents\n";
  auto result = runCambrian("replay --history " + history_ + " --id 1 --save-genome " + path);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(lineStartingWith(result.output, "genome").find("replacing the file that was there"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(fileText(path), storedGenomeText(rows(), 1));
  std::string unwritable = dir_ + "/no/such/dir/g.genome";
  result = runCambrian("replay --history " + history_ + " --id 1 --save-genome " + unwritable);
  EXPECT_EQ(result.exit_code, code(ExitCode::output_file)) << result.output;
  EXPECT_NE(result.output.find(unwritable), std::string::npos) << result.output;
  result = runCambrian("replay --history " + history_ + " --id 1 --save-genome " + history_);
  EXPECT_EQ(result.exit_code, code(ExitCode::usage)) << result.output;
  EXPECT_NE(result.output.find("the history being replayed"), std::string::npos) << result.output;
  EXPECT_NO_THROW(HistoryReader{history_});
}

// a genome saved by replay seeds a tiny evolution: it is generation 0's seed individual,
// evaluated with status ok
TEST_F(ReplayCommand, SavedGenomeSeedsAnEvolution) {
  std::string path = dir_ + "/seed.genome";
  ASSERT_EQ(runCambrian("replay --history " + history_ + " --best --save-genome " + path).exit_code,
            0);
  std::string out = dir_ + "/seeded";
  auto run = runCambrian(
      "evolve --evolution.population 4 --evolution.generations 1 --task.evaluation_time 1 "
      "--evolution.seed_genomes " +
      path + " --seed 11 --quiet --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  int seeds = 0;
  for (const Individual& row : HistoryReader(out + "/history.h5").individuals()) {
    if (row.origin != Origin::seed)
      continue;
    ++seeds;
    EXPECT_EQ(row.genome.encoding().toText(row.genome), fileText(path));
    EXPECT_EQ(row.outcome.status, EvalStatus::ok);
  }
  EXPECT_EQ(seeds, 1);
}

// --help describes the command and exits 0
TEST(ReplayHelp, Help) {
  auto result = runCambrian("replay --help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("--history"), std::string::npos);
  EXPECT_NE(result.output.find("--export"), std::string::npos);
  EXPECT_NE(result.output.find("--save-genome"), std::string::npos);
  EXPECT_NE(result.output.find("text form"), std::string::npos);
  EXPECT_NE(result.output.find("--task.evaluation_time"), std::string::npos);
  EXPECT_NE(result.output.find("--physics.time_step"), std::string::npos);
  EXPECT_EQ(result.output.find("--genome.max_parts"), std::string::npos);
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
