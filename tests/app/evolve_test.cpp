// cambrian evolve through the executable, in one process (no mpirun): what the command line
// and the experiment file give, where a bad value is reported, the stored settings, and the
// output directory's protection (a changed seed, a foreign history, a second run).
#include "app/cli.hpp"
#include "physics/physics_settings.hpp"
#include "store/history.hpp"
#include "store/run_lock.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sys/file.h>
#include <unistd.h>

namespace cambrian {
namespace {

using test::runCambrian;

// a fresh, empty directory under the test temp directory
std::string freshDir(const std::string& name) {
  std::string dir = testing::TempDir() + "/cambrian_evolve_test_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// a file's bytes
std::string contents(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// a tiny synthetic evolution's arguments, writing into `dir`
std::string tinyRun(const std::string& dir, int generations = 2) {
  return "evolve --task.name synthetic --task.synthetic_cost_us 10 --evolution.population 6 "
         "--evolution.generations " +
         std::to_string(generations) + " --quiet --out " + dir;
}

// the value of `key = ` in an INI-like text, or ""
std::string iniValue(const std::string& text, const std::string& key) {
  std::size_t at = text.find("\n" + key + " = ");
  if (at == std::string::npos)
    return "";
  at += key.size() + 4;
  return text.substr(at, text.find('\n', at) - at);
}

TEST(EvolveCommand, ShortSeedIsTheStoredSeedAndAChangedSeedIsRefused) {
  std::string dir = freshDir("seed");
  auto first = runCambrian(tinyRun(dir) + " --seed 3");
  ASSERT_EQ(first.exit_code, 0) << first.output;

  // the stored settings carry the seed the run used, not the file's or the default
  HistoryReader reader(dir + "/history.h5");
  EXPECT_EQ(reader.attributes().seed, 3u);
  EXPECT_EQ(iniValue(reader.attributes().config_text, "seed"), "3")
      << reader.attributes().config_text;

  // continuing with another seed would mix two runs: refused, nothing changed
  std::string history = contents(dir + "/history.h5");
  std::string checkpoint = contents(dir + "/checkpoint.h5");
  auto second = runCambrian(tinyRun(dir, 3) + " --seed 4");
  EXPECT_EQ(second.exit_code, 6) << second.output;
  EXPECT_NE(second.output.find("run.seed was '3'"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("is '4'"), std::string::npos) << second.output;
  EXPECT_EQ(contents(dir + "/history.h5"), history);
  EXPECT_EQ(contents(dir + "/checkpoint.h5"), checkpoint);

  // the same seed continues
  auto third = runCambrian(tinyRun(dir, 3) + " --seed 3");
  EXPECT_EQ(third.exit_code, 0) << third.output;
  EXPECT_NE(third.output.find("resuming"), std::string::npos) << third.output;
}

TEST(EvolveCommand, ANegativeOrMalformedSeedIsRefused) {
  std::string dir = freshDir("negative_seed");
  for (const char* seed : {"-3", "1e3", "x", "18446744073709551616"}) {
    auto result = runCambrian(tinyRun(dir) + " --seed " + seed);
    EXPECT_EQ(result.exit_code, 2) << seed << ": " << result.output;
    EXPECT_NE(result.output.find(seed), std::string::npos) << result.output;
  }
  std::ofstream(dir + "/bad_seed.ini") << "[run]\nseed = -3\n";
  auto from_file = runCambrian(tinyRun(dir) + " --config " + dir + "/bad_seed.ini");
  EXPECT_EQ(from_file.exit_code, 3) << from_file.output;
  EXPECT_NE(from_file.output.find("bad_seed.ini"), std::string::npos) << from_file.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/history.h5"));
}

TEST(EvolveCommand, ABadValueNamesWhereItCameFrom) {
  std::string dir = freshDir("origin");
  std::string ini = dir + "/experiment.ini";
  std::ofstream(ini) << "[physics]\ntime_step = -1\n[evolution]\npopulation = 8\n";

  // from the file: the file, the key and the value
  auto from_file = runCambrian(tinyRun(dir + "/out") + " --config " + ini);
  EXPECT_EQ(from_file.exit_code, 3) << from_file.output;
  EXPECT_NE(from_file.output.find(ini + ": physics.time_step = -1"), std::string::npos)
      << from_file.output;

  // from the command line: not blamed on the file
  std::ofstream(ini) << "[evolution]\npopulation = 8\n";
  auto from_line =
      runCambrian(tinyRun(dir + "/out") + " --config " + ini + " --physics.max_speed inf");
  EXPECT_EQ(from_line.exit_code, 3) << from_line.output;
  EXPECT_NE(from_line.output.find("command line: --physics.max_speed = inf"), std::string::npos)
      << from_line.output;
  EXPECT_EQ(from_line.output.find(ini + ":"), std::string::npos) << from_line.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/history.h5"));
}

TEST(EvolveCommand, AHistoryWithoutACheckpointIsNeverOverwritten) {
  // not an HDF5 file
  std::string dir = freshDir("junk_history");
  std::ofstream(dir + "/history.h5") << "someone's notes";
  auto junk = runCambrian(tinyRun(dir));
  EXPECT_EQ(junk.exit_code, 6) << junk.output;
  EXPECT_NE(junk.output.find(dir + "/history.h5"), std::string::npos) << junk.output;
  EXPECT_EQ(contents(dir + "/history.h5"), "someone's notes");

  // a run's history whose checkpoints are gone: refused too; --fresh starts over
  std::string run = freshDir("no_checkpoint");
  auto first = runCambrian(tinyRun(run));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  std::filesystem::remove(run + "/checkpoint.h5");
  std::filesystem::remove(run + "/checkpoint.prev.h5");
  std::string history = contents(run + "/history.h5");
  auto again = runCambrian(tinyRun(run));
  EXPECT_EQ(again.exit_code, 6) << again.output;
  EXPECT_EQ(contents(run + "/history.h5"), history);
  auto fresh = runCambrian(tinyRun(run) + " --fresh");
  EXPECT_EQ(fresh.exit_code, 0) << fresh.output;
}

TEST(EvolveCommand, AJobKilledInItsFirstMinuteContinuesFromGeneration0) {
  // default cadence (a minute): killed during generation 1, a few milliseconds in
  std::string dir = freshDir("killed_early");
  auto killed = runCambrian(tinyRun(dir, 3) + " --run.test_kill_at evaluation:1");
  EXPECT_NE(killed.exit_code, 0) << killed.output;
  ASSERT_TRUE(std::filesystem::exists(dir + "/checkpoint.h5"));

  // the same command continues after generation 0 and ends as a straight run does
  auto resumed = runCambrian(tinyRun(dir, 3));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("at generation 1"), std::string::npos) << resumed.output;
  std::string straight_dir = freshDir("killed_early_straight");
  auto straight = runCambrian(tinyRun(straight_dir, 3));
  std::string digest = test::lineStartingWith(straight.output, "digest ");
  ASSERT_FALSE(digest.empty()) << straight.output;
  EXPECT_EQ(test::lineStartingWith(resumed.output, "digest "), digest);
}

TEST(EvolveCommand, AJobKilledBeforeItsFirstCheckpointStartsAgainOnTheSameCommand) {
  // generation 0's rows in the history, its checkpoint not yet written
  std::string dir = freshDir("killed_before_first_checkpoint");
  auto killed = runCambrian(tinyRun(dir, 3) + " --run.test_kill_at history:0");
  EXPECT_NE(killed.exit_code, 0) << killed.output;
  ASSERT_FALSE(std::filesystem::exists(dir + "/checkpoint.h5"));

  // the same command writes generation 0 again and ends as a straight run does
  auto again = runCambrian(tinyRun(dir, 3));
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("starting fresh"), std::string::npos) << again.output;
  auto straight = runCambrian(tinyRun(freshDir("killed_before_first_checkpoint_straight"), 3));
  std::string digest = test::lineStartingWith(straight.output, "digest ");
  ASSERT_FALSE(digest.empty()) << straight.output;
  EXPECT_EQ(test::lineStartingWith(again.output, "digest "), digest);

  // another seed's run on that directory is still refused
  std::filesystem::remove(dir + "/checkpoint.h5");
  std::filesystem::remove(dir + "/checkpoint.prev.h5");
  auto other = runCambrian(tinyRun(dir, 3) + " --seed 99");
  EXPECT_EQ(other.exit_code, 6) << other.output;
}

TEST(EvolveCommand, AHistoryLeftUnreadableByAKillAtItsStartIsStartedAgain) {
  // killed inside HDF5's first writes: history.h5 unreadable, the run's marker beside it
  std::string dir = freshDir("killed_in_first_writes");
  auto killed = runCambrian(tinyRun(dir, 3) + " --run.test_kill_at history:0");
  EXPECT_NE(killed.exit_code, 0) << killed.output;
  ASSERT_TRUE(std::filesystem::exists(dir + "/history.h5.starting"));
  std::filesystem::resize_file(dir + "/history.h5", 100);  // the HDF5 signature, cut short

  // the same command starts it again and ends as a straight run does; the marker goes
  auto again = runCambrian(tinyRun(dir, 3));
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("starting fresh"), std::string::npos) << again.output;
  auto straight = runCambrian(tinyRun(freshDir("killed_in_first_writes_straight"), 3));
  std::string digest = test::lineStartingWith(straight.output, "digest ");
  ASSERT_FALSE(digest.empty()) << straight.output;
  EXPECT_EQ(test::lineStartingWith(again.output, "digest "), digest);
  EXPECT_FALSE(std::filesystem::exists(dir + "/history.h5.starting"));

  // another seed's run, or the same run without its marker, leaves such a file alone
  auto killed_again = runCambrian(tinyRun(dir, 3) + " --fresh --run.test_kill_at history:0");
  EXPECT_NE(killed_again.exit_code, 0) << killed_again.output;
  std::filesystem::resize_file(dir + "/history.h5", 100);
  auto other = runCambrian(tinyRun(dir, 3) + " --seed 99");
  EXPECT_EQ(other.exit_code, 6) << other.output;
  std::filesystem::remove(dir + "/history.h5.starting");
  auto unmarked = runCambrian(tinyRun(dir, 3));
  EXPECT_EQ(unmarked.exit_code, 6) << unmarked.output;
  EXPECT_EQ(std::filesystem::file_size(dir + "/history.h5"), 100u);
}

TEST(EvolveCommand, ASecondRunOnTheSameDirectoryIsRefused) {
  std::string dir = freshDir("locked");
  // another process (this test) holds the directory's lock
  int fd = ::open(RunLock::pathIn(dir).c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  std::string holder = "host " + std::string(host) + " pid " + std::to_string(::getpid()) + "\n";
  ASSERT_EQ(::pwrite(fd, holder.data(), holder.size(), 0), static_cast<ssize_t>(holder.size()));
  auto busy = runCambrian(tinyRun(dir) + " --run.lock_wait 0.5");
  EXPECT_EQ(busy.exit_code, 5) << busy.output;
  EXPECT_NE(busy.output.find("another cambrian evolve is writing"), std::string::npos)
      << busy.output;
  EXPECT_NE(busy.output.find("pid " + std::to_string(::getpid()) + ", alive on this host"),
            std::string::npos)
      << busy.output;
  EXPECT_NE(busy.output.find("waiting up to 0.5 s"), std::string::npos) << busy.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/history.h5"));

  // released: the run goes ahead
  ::close(fd);
  auto free = runCambrian(tinyRun(dir));
  EXPECT_EQ(free.exit_code, 0) << free.output;
}

TEST(EvolveCommand, ResumingACheckpointOfAnotherVersionWarns) {
  std::string dir = freshDir("other_version");
  auto first = runCambrian(tinyRun(dir));
  ASSERT_EQ(first.exit_code, 0) << first.output;

  // the checkpoint says an older cambrian wrote it
  hid_t file = H5Fopen((dir + "/checkpoint.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Adelete(file, "cambrian_version"), 0);
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attribute = H5Acreate2(file, "cambrian_version", type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* old_version = "0.0.1";
  ASSERT_GE(H5Awrite(attribute, type, &old_version), 0);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);

  // it continues, and says so
  auto resumed = runCambrian(tinyRun(dir, 3));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("warning: " + dir + "/checkpoint.h5 was written by cambrian 0.0.1"),
            std::string::npos)
      << resumed.output;
  // the history names this build's Bullet precision
  EXPECT_EQ(HistoryReader(dir + "/history.h5").attributes().bullet_precision,
            std::string(bulletPrecision()));
}

// the live line within a generation: written in place ("\r", erase line) when asked for or on
// a terminal, wiped before each generation's line; none in a log (a pipe, as here) or when quiet
TEST(EvolveCommand, TheLiveLineIsShownWhenAskedForAndNeverInALog) {
  const std::string erase = "\r\033[K";
  std::string arguments = tinyRun(freshDir("live"));
  arguments.replace(arguments.find(" --quiet"), 8, "");
  auto live = runCambrian(arguments + " --run.progress live");
  ASSERT_EQ(live.exit_code, 0) << live.output;
  EXPECT_NE(live.output.find(erase + "  gen 1/2  evaluated 1/6 (population 6)  eta "),
            std::string::npos)
      << live.output;
  EXPECT_NE(live.output.find(erase + "  gen 1/2  evaluated 6/6 (population 6)  eta "),
            std::string::npos)
      << live.output;
  // each generation's line starts after the live line was wiped
  EXPECT_NE(live.output.find(erase + "gen 1/2  best "), std::string::npos) << live.output;
  EXPECT_NE(live.output.find(erase + "gen 2/2  best "), std::string::npos) << live.output;

  arguments = tinyRun(freshDir("plain"));
  arguments.replace(arguments.find(" --quiet"), 8, "");
  auto log = runCambrian(arguments);  // auto, and the output is a pipe
  ASSERT_EQ(log.exit_code, 0) << log.output;
  EXPECT_NE(log.output.find("gen 2/2  best "), std::string::npos) << log.output;
  EXPECT_EQ(log.output.find('\r'), std::string::npos) << log.output;

  auto quiet = runCambrian(tinyRun(freshDir("quiet")) + " --run.progress live");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find('\r'), std::string::npos) << quiet.output;

  auto bad = runCambrian(tinyRun(freshDir("bad_progress")) + " --run.progress sometimes");
  EXPECT_EQ(bad.exit_code, test::code(ExitCode::config)) << bad.output;
  EXPECT_NE(bad.output.find("run.progress"), std::string::npos) << bad.output;
}

// evolution.ranking: every stored fitness is its individual's rank points among its generation
// on the juries named (recounted here from the stored measures, elites included), and the
// replay of a ranked creature compares its measures, not its fitness
TEST(EvolveCommand, ARankedRunStoresEachIndividualsRankPoints) {
  std::string dir = freshDir("ranked");
  auto run = runCambrian(
      "evolve --task.name juries --task.evaluation_time 1 --evolution.population 8 "
      "--evolution.generations 3 --evolution.ranking average_velocity:2:higher "
      "--evolution.ranking ground_contact_ratio:0.5:lower --seed 5 --quiet --out " +
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  HistoryReader reader(dir + "/history.h5");
  const std::vector<Individual> rows = reader.individuals();
  ASSERT_EQ(rows.size(), 24u);
  bool some_points = false;
  for (const Individual& row : rows) {
    if (row.outcome.status != EvalStatus::ok) {
      EXPECT_EQ(row.fitness(), kWorstFitness);
      continue;
    }
    double points = 0;
    for (const Individual& other : rows) {
      if (other.generation != row.generation || other.outcome.status != EvalStatus::ok)
        continue;
      points +=
          2 * (other.outcome.measure("average_velocity") < row.outcome.measure("average_velocity"));
      points += 0.5 * (other.outcome.measure("ground_contact_ratio") >
                       row.outcome.measure("ground_contact_ratio"));
    }
    EXPECT_EQ(row.fitness(), points) << "individual " << row.id;
    some_points = some_points || points > 0;
  }
  EXPECT_TRUE(some_points);
  auto replay = runCambrian("replay --history " + dir + "/history.h5 --best");
  EXPECT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_NE(replay.output.find("evolution.ranking; not compared"), std::string::npos)
      << replay.output;
  // a measure the task does not report is refused, naming the key and the task's measures
  auto bad = runCambrian("evolve --task.name walk --evolution.ranking speed --quiet --out " +
                         freshDir("ranked_bad"));
  EXPECT_EQ(bad.exit_code, 3) << bad.output;
  EXPECT_NE(bad.output.find("evolution.ranking = speed: task walk has no measure 'speed'"),
            std::string::npos)
      << bad.output;
}

// Minemonics' epochs: two generations ranked by average velocity, then by maximum height; the
// history says each generation's epoch; a run killed in the first generation of the second
// epoch (its checkpoint the last of the first) resumes into the second epoch and ends as the
// straight run does
TEST(EvolveCommand, EpochsRateEachGenerationByTheirJuriesAcrossKillAndResume) {
  const std::string command =
      "evolve --task.name juries --task.evaluation_time 1 --evolution.population 8 "
      "--evolution.generations 4 --evolution.epochs average_velocity@2 "
      "--evolution.epochs maximum_height --run.checkpoint_every 1 --seed 6 --out ";
  const std::string dir = freshDir("epochs");
  auto straight = runCambrian(command + dir);
  ASSERT_EQ(straight.exit_code, 0) << straight.output;
  EXPECT_NE(straight.output.find("epoch 1/2 (average_velocity@2) from generation 1"),
            std::string::npos)
      << straight.output;
  EXPECT_NE(straight.output.find("epoch 2/2 (maximum_height) from generation 3"), std::string::npos)
      << straight.output;
  HistoryReader reader(dir + "/history.h5");
  std::vector<std::uint64_t> epochs;
  for (const GenerationRecord& row : reader.generations())
    epochs.push_back(row.epoch);
  EXPECT_EQ(epochs, (std::vector<std::uint64_t>{0, 0, 1, 1}));
  // each generation's fitness is its epoch's rank points
  const std::vector<Individual> rows = reader.individuals();
  for (const Individual& row : rows) {
    if (row.outcome.status != EvalStatus::ok)
      continue;
    const char* measure = row.generation < 2 ? "average_velocity" : "maximum_height";
    double points = 0;
    for (const Individual& other : rows) {
      if (other.generation == row.generation && other.outcome.status == EvalStatus::ok)
        points += other.outcome.measure(measure) < row.outcome.measure(measure);
    }
    EXPECT_EQ(row.fitness(), points) << "individual " << row.id;
  }

  const std::string killed_dir = freshDir("epochs_killed");
  auto killed = runCambrian(command + killed_dir + " --run.test_kill_at evaluation:2");
  EXPECT_NE(killed.exit_code, 0) << killed.output;
  auto resumed = runCambrian(command + killed_dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("at generation 2"), std::string::npos) << resumed.output;
  EXPECT_NE(resumed.output.find("epoch 2/2 (maximum_height) from generation 3"), std::string::npos)
      << resumed.output;
  const std::string digest = test::lineStartingWith(straight.output, "digest ");
  ASSERT_FALSE(digest.empty());
  EXPECT_EQ(test::lineStartingWith(resumed.output, "digest "), digest);
  std::vector<std::uint64_t> resumed_epochs;
  for (const GenerationRecord& row : HistoryReader(killed_dir + "/history.h5").generations())
    resumed_epochs.push_back(row.epoch);
  EXPECT_EQ(resumed_epochs, epochs);

  // an epoch naming a measure the task lacks, and epochs beside evolution.ranking, are refused
  auto bad = runCambrian(
      "evolve --task.name juries --evolution.epochs speed@2 "
      "--evolution.epochs maximum_height --quiet --out " +
      freshDir("epochs_bad"));
  EXPECT_EQ(bad.exit_code, 3) << bad.output;
  EXPECT_NE(bad.output.find("evolution.epochs = speed@2: task juries has no measure 'speed'"),
            std::string::npos)
      << bad.output;
  auto both = runCambrian(
      "evolve --task.name juries --evolution.epochs maximum_height "
      "--evolution.ranking average_velocity --quiet --out " +
      freshDir("epochs_both"));
  EXPECT_EQ(both.exit_code, 3) << both.output;
  EXPECT_NE(both.output.find("evolution.epochs and evolution.ranking are both set"),
            std::string::npos)
      << both.output;
}

// Minemonics' reaper: every generation after the first has the reaper's kinds in their counts
// (population 14: 5 culled, sown 3 by crossover and 2 at random; the 9 survivors in sevenths,
// the 2 left over to the first two kinds), named in the history;
// a run killed in the third generation's evaluation resumes and ends as the straight run does
TEST(EvolveCommand, TheReaperBreedsItsSharesAndResumesExactly) {
  const std::string command =
      "evolve --task.name juries --task.evaluation_time 1 --evolution.population 14 "
      "--evolution.generations 3 --evolution.scheme reaper --run.checkpoint_every 1 --seed 7 "
      "--out ";
  const std::string dir = freshDir("reaper");
  auto straight = runCambrian(command + dir);
  ASSERT_EQ(straight.exit_code, 0) << straight.output;
  HistoryReader reader(dir + "/history.h5");
  std::map<std::uint64_t, std::map<std::string, int>> kinds;
  for (const Individual& row : reader.individuals())
    ++kinds[row.generation][originName(row.origin)];
  for (std::uint64_t g : {1u, 2u}) {
    std::map<std::string, int> expected{{"elite", 2},
                                        {"gene_specification", 2},
                                        {"gene_split", 1},
                                        {"gene_purge", 1},
                                        {"branch_specification", 1},
                                        {"grow_stub", 1},
                                        {"graft_feature", 1},
                                        {"crossover", 3},
                                        {"random", 2}};
    EXPECT_EQ(kinds[g], expected) << "generation " << g;
  }

  const std::string killed_dir = freshDir("reaper_killed");
  auto killed = runCambrian(command + killed_dir + " --run.test_kill_at evaluation:2");
  EXPECT_NE(killed.exit_code, 0) << killed.output;
  auto resumed = runCambrian(command + killed_dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("at generation 2"), std::string::npos) << resumed.output;
  const std::string digest = test::lineStartingWith(straight.output, "digest ");
  ASSERT_FALSE(digest.empty());
  EXPECT_EQ(test::lineStartingWith(resumed.output, "digest "), digest);
}

// a sequence of fitness tests (Walking with Dinosaurs): a run seeded by a previous run's history
// starts from the best individual (status ok; ties: lowest id) of its last generation, the rest
// of its first generation mutated copies of it, and breeds by the wwd scheme (population 6: one
// elite kept, five bred); a history that is not there is refused naming the key and the path
TEST(EvolveCommand, ASeedHistoryStartsFromTheBestOfItsLastGeneration) {
  const std::string first = freshDir("seed_history_first");
  auto earlier = runCambrian(tinyRun(first, 3) + " --seed 4");
  ASSERT_EQ(earlier.exit_code, 0) << earlier.output;
  std::optional<Individual> best;
  for (const Individual& row : HistoryReader(first + "/history.h5").individuals()) {
    if (row.generation == 2 && row.outcome.status == EvalStatus::ok &&
        (!best || row.fitness() > best->fitness()))
      best = row;
  }
  ASSERT_TRUE(best);

  const std::string second = freshDir("seed_history_second");
  auto next = runCambrian(tinyRun(second) + " --seed 5 --evolution.scheme wwd " +
                          "--evolution.seed_history " + first + "/history.h5");
  ASSERT_EQ(next.exit_code, 0) << next.output;
  std::map<std::uint64_t, std::map<std::string, int>> kinds;
  for (const Individual& row : HistoryReader(second + "/history.h5").individuals()) {
    ++kinds[row.generation][originName(row.origin)];
    if (row.generation != 0)
      continue;
    if (row.id == 0) {
      EXPECT_EQ(row.origin, Origin::seed);
      EXPECT_EQ(row.genome.bytes(), best->genome.bytes());
    } else {
      EXPECT_EQ(row.origin, Origin::mutation);
      EXPECT_EQ(row.parents, std::vector<std::uint64_t>{0});
    }
  }
  EXPECT_EQ(kinds[0], (std::map<std::string, int>{{"seed", 1}, {"mutation", 5}}));
  EXPECT_EQ(kinds[1], (std::map<std::string, int>{{"elite", 1}, {"crossover", 5}}));

  const std::string third = freshDir("seed_history_missing");
  const std::string nowhere = third + "/nowhere/history.h5";
  auto missing = runCambrian(tinyRun(third) + " --evolution.seed_history " + nowhere);
  EXPECT_EQ(missing.exit_code, test::code(ExitCode::input_file)) << missing.output;
  EXPECT_NE(missing.output.find("evolution.seed_history = " + nowhere + ": "), std::string::npos)
      << missing.output;
  EXPECT_FALSE(std::filesystem::exists(third + "/history.h5"));
}

TEST(EvolveCommand, HelpShowsDefaultsAsWritten) {
  auto help = runCambrian("evolve --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--evolution.elite_fraction arg (=0.2)"), std::string::npos)
      << help.output;
  EXPECT_NE(help.output.find("--run.quiet arg (=false)"), std::string::npos);
  EXPECT_EQ(help.output.find("0000000000"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace cambrian
