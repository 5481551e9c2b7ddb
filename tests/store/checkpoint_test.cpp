// Tests of the checkpoint file: round trips, rotation, a writer killed mid-write, bad files, a
// version-1 checkpoint of an earlier cambrian still read.
#include "store/checkpoint.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "store/history.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cambrian {
namespace {

// a fresh, empty directory in the test temp directory
std::string tempDir(const std::string& name) {
  std::string dir = testing::TempDir() + "/cambrian_checkpoint_test_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const std::vector<MeasureInfo> kMeasures = {{"distance", "m"}};

const std::string kConfig =
    "[evolution]\ngenerations = 5\npopulation = 4\n\n[physics]\ntime_step = 0.004\n\n[run]\n"
    "out = a\nquiet = true\nseed = 9\n";

// a state with every kind of field filled: parents, measures, messages, a NaN fitness
CheckpointState makeState(std::uint64_t generation, std::uint64_t salt = 0) {
  CheckpointState state;
  state.config_text = kConfig;
  state.config_hash = "0123456789abcdef";
  state.seed = 9;
  state.next_generation = generation + 1;
  state.next_id = 100 + salt;
  state.digest = 0x0123456789abcdefULL ^ salt;
  state.rank_count = 3;
  state.population.generation = generation;
  for (std::uint64_t i = 0; i < 4; ++i) {
    Individual individual;
    individual.id = 10 * generation + i;
    individual.generation = generation;
    individual.origin = i == 0 ? Origin::elite : (i == 1 ? Origin::crossover : Origin::mutation);
    individual.parents = i == 1 ? std::vector<std::uint64_t>{3, 5} : std::vector<std::uint64_t>{2};
    individual.genome =
        graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 7 + salt, 0, i));
    individual.evaluated = true;
    individual.outcome.fitness = i == 3 ? std::nan("") : 1.25 + static_cast<double>(i);
    individual.outcome.status = i == 2 ? EvalStatus::failed : EvalStatus::ok;
    individual.outcome.measures = {{"distance", 0.5 * i}, {"body_length", 2.0}};
    individual.outcome.steps = 2400 + i;
    individual.outcome.wall_seconds = 0.01 * i;
    individual.outcome.parts = 2 + static_cast<int>(i);
    individual.outcome.joints = 1;
    individual.outcome.neurons = 5;
    individual.outcome.message = i == 2 ? "evaluator threw: bad bytes" : "";
    individual.eval_seconds = 0.02 * i;
    individual.worker_rank = static_cast<int>(i) - 1;
    state.population.individuals.push_back(individual);
  }
  return state;
}

// the message and code of readCheckpoint / findCheckpoint failures
template <class F>
std::pair<ExitCode, std::string> failure(F call) {
  try {
    call();
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  return {ExitCode::ok, ""};
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// runs `body` in a child process and expects it to die by SIGKILL
void expectKilled(const std::function<void()>& body) {
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      body();
    } catch (...) {
      _exit(3);
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(Checkpoint, RoundTripsEveryField) {
  std::string dir = tempDir("round_trip");
  CheckpointState state = makeState(3);
  writeCheckpoint(dir, state);
  EXPECT_FALSE(std::filesystem::exists(checkpointPath(dir) + ".tmp"));
  CheckpointState back = readCheckpoint(checkpointPath(dir));

  // scalars
  EXPECT_EQ(back.config_text, state.config_text);
  EXPECT_EQ(back.config_hash, state.config_hash);
  EXPECT_EQ(back.seed, 9u);
  EXPECT_EQ(back.next_generation, 4u);
  EXPECT_EQ(back.next_id, 100u);
  EXPECT_EQ(back.digest, state.digest);
  EXPECT_EQ(back.rank_count, 3);
  EXPECT_EQ(back.population.generation, 3u);

  // every individual, bit for bit
  ASSERT_EQ(back.population.individuals.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const Individual& a = state.population.individuals[i];
    const Individual& b = back.population.individuals[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.generation, b.generation);
    EXPECT_EQ(a.parents, b.parents);
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.genomeBytes(), b.genomeBytes());
    EXPECT_EQ(a.outcome.wall_seconds, b.outcome.wall_seconds);
    EXPECT_EQ(a.outcome.joints, b.outcome.joints);
    EXPECT_EQ(a.outcome.neurons, b.outcome.neurons);
    EXPECT_EQ(std::memcmp(&a.outcome.fitness, &b.outcome.fitness, sizeof(double)), 0);
    EXPECT_EQ(a.outcome.status, b.outcome.status);
    EXPECT_EQ(a.outcome.measures, b.outcome.measures);
    EXPECT_EQ(a.outcome.steps, b.outcome.steps);
    EXPECT_EQ(a.outcome.parts, b.outcome.parts);
    EXPECT_EQ(a.outcome.message, b.outcome.message);
    EXPECT_EQ(a.eval_seconds, b.eval_seconds);
    EXPECT_EQ(a.worker_rank, b.worker_rank);
    EXPECT_TRUE(b.evaluated);
  }
}

TEST(Checkpoint, KeepsThePreviousOne) {
  std::string dir = tempDir("rotation");
  writeCheckpoint(dir, makeState(1));
  EXPECT_FALSE(std::filesystem::exists(previousCheckpointPath(dir)));
  writeCheckpoint(dir, makeState(2));
  EXPECT_EQ(readCheckpoint(checkpointPath(dir)).next_generation, 3u);
  EXPECT_EQ(readCheckpoint(previousCheckpointPath(dir)).next_generation, 2u);
  writeCheckpoint(dir, makeState(3));
  EXPECT_EQ(readCheckpoint(checkpointPath(dir)).next_generation, 4u);
  EXPECT_EQ(readCheckpoint(previousCheckpointPath(dir)).next_generation, 3u);
  EXPECT_EQ(findCheckpoint(dir)->next_generation, 4u);
}

TEST(Checkpoint, WriterKilledAtEveryStageLeavesAUsableCheckpoint) {
  for (const char* stage : {"write", "rename"}) {
    std::string dir = tempDir(std::string("killed_") + stage);
    writeCheckpoint(dir, makeState(1));
    writeCheckpoint(dir, makeState(2));
    std::string before = fileBytes(checkpointPath(dir));
    expectKilled([&] {
      writeCheckpoint(dir, makeState(3), [&](const std::string& s) {
        if (s == stage)
          std::raise(SIGKILL);
      });
    });
    // the last complete checkpoint is still in place, untouched
    EXPECT_TRUE(std::filesystem::exists(checkpointPath(dir) + ".tmp")) << stage;
    EXPECT_EQ(fileBytes(checkpointPath(dir)), before) << stage;
    EXPECT_EQ(findCheckpoint(dir)->next_generation, 3u) << stage;
    // and the next write goes through
    writeCheckpoint(dir, makeState(3));
    EXPECT_EQ(findCheckpoint(dir)->next_generation, 4u) << stage;
  }
}

TEST(Checkpoint, EmptyDirectoryMeansAFreshRun) {
  std::string dir = tempDir("empty");
  EXPECT_FALSE(findCheckpoint(dir).has_value());
  auto [code, message] = failure([&] { readCheckpoint(checkpointPath(dir)); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find(checkpointPath(dir)), std::string::npos) << message;
  EXPECT_NE(message.find("no such"), std::string::npos) << message;
}

TEST(Checkpoint, TruncatedFileIsRefusedAndThePreviousOneIsOffered) {
  std::string dir = tempDir("truncated");
  writeCheckpoint(dir, makeState(1));
  writeCheckpoint(dir, makeState(2));
  std::string path = checkpointPath(dir);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  std::string truncated = fileBytes(path);
  auto [code, message] = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("checkpoint.prev.h5 is good (continues from generation 2)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("--fresh"), std::string::npos) << message;
  // nothing overwritten
  EXPECT_EQ(fileBytes(path), truncated);
}

TEST(Checkpoint, NonHdf5AndForeignFilesAreRefused) {
  std::string dir = tempDir("foreign");
  std::string path = checkpointPath(dir);
  std::ofstream(path) << "just some text\n";
  auto [code, message] = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;

  // a history file is HDF5 but not a checkpoint
  std::filesystem::remove(path);
  {
    HistoryAttributes attributes;
    HistoryWriter writer(path, attributes, kMeasures);
  }
  std::tie(code, message) = failure([&] { readCheckpoint(path); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("not a cambrian checkpoint"), std::string::npos) << message;
  EXPECT_NE(message.find("cambrian-history"), std::string::npos) << message;
}

// rewrites a uint attribute / one byte of a dataset of a checkpoint through HDF5
void patchFile(const std::string& path, const std::function<void(hid_t)>& patch) {
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  patch(file);
  H5Fclose(file);
}

TEST(Checkpoint, NewerFormatVersionIsRefused) {
  std::string dir = tempDir("newer");
  writeCheckpoint(dir, makeState(1));
  patchFile(checkpointPath(dir), [](hid_t file) {
    hid_t attribute = H5Aopen(file, "format_version", H5P_DEFAULT);
    std::int32_t version = kCheckpointFormatVersion + 1;
    H5Awrite(attribute, H5T_NATIVE_INT32, &version);
    H5Aclose(attribute);
  });
  auto [code, message] = failure([&] { readCheckpoint(checkpointPath(dir)); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("format_version " + std::to_string(kCheckpointFormatVersion + 1) +
                         " is not supported"),
            std::string::npos)
      << message;
}

TEST(Checkpoint, ChangedContentsFailTheStateHash) {
  std::string dir = tempDir("corrupt");
  writeCheckpoint(dir, makeState(1));
  patchFile(checkpointPath(dir), [](hid_t file) {
    // the digest attribute no longer matches the hash of the state
    hid_t attribute = H5Aopen(file, "next_id", H5P_DEFAULT);
    std::uint64_t id = 7;
    H5Awrite(attribute, H5T_NATIVE_UINT64, &id);
    H5Aclose(attribute);
  });
  auto [code, message] = failure([&] { readCheckpoint(checkpointPath(dir)); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("state_hash"), std::string::npos) << message;
}

TEST(Checkpoint, KeepsAnIslandsMigrationStateUnderTheStateHash) {
  std::string dir = tempDir("migrations");
  CheckpointState state = makeState(2);
  state.migrations = {1, 0, 0, 0, 0, 0, 0, 0, 42, 7};
  writeCheckpoint(dir, state);
  EXPECT_EQ(readCheckpoint(checkpointPath(dir)).migrations, state.migrations);
  // without islands, no dataset and nothing read back
  std::string plain = tempDir("no_migrations");
  writeCheckpoint(plain, makeState(2));
  EXPECT_TRUE(readCheckpoint(checkpointPath(plain)).migrations.empty());
  // a changed byte fails the state hash
  patchFile(checkpointPath(dir), [](hid_t file) {
    hid_t dataset = H5Dopen2(file, "migrations", H5P_DEFAULT);
    std::uint8_t bytes[10] = {1, 0, 0, 0, 0, 0, 0, 0, 43, 7};
    H5Dwrite(dataset, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes);
    H5Dclose(dataset);
  });
  auto [code, message] = failure([&] { readCheckpoint(checkpointPath(dir)); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("state_hash"), std::string::npos) << message;
}

TEST(Checkpoint, KeepsASteadyStatesCreaturesInFlightAndWhenEachWasBred) {
  std::string dir = tempDir("steady_state");
  CheckpointState state = makeState(3);
  state.steady_state = true;
  // the last two are in flight: bred, not evaluated
  auto& individuals = state.population.individuals;
  for (std::size_t k = 0; k < individuals.size(); ++k)
    individuals[k].bred_after = 10 + k;
  for (std::size_t k = individuals.size() - 2; k < individuals.size(); ++k) {
    individuals[k].evaluated = false;
    individuals[k].outcome = Outcome{};
  }
  writeCheckpoint(dir, state);
  CheckpointState read = readCheckpoint(checkpointPath(dir));
  EXPECT_TRUE(read.steady_state);
  ASSERT_EQ(read.population.individuals.size(), individuals.size());
  for (std::size_t k = 0; k < individuals.size(); ++k) {
    EXPECT_EQ(read.population.individuals[k].bred_after, 10 + k);
    EXPECT_EQ(read.population.individuals[k].evaluated, individuals[k].evaluated);
  }
  // a generational checkpoint keeps no bred_after and must be fully evaluated
  std::string plain = tempDir("not_steady");
  writeCheckpoint(plain, makeState(3));
  EXPECT_FALSE(readCheckpoint(checkpointPath(plain)).steady_state);
  EXPECT_EQ(readCheckpoint(checkpointPath(plain)).population.individuals[1].bred_after, 0u);
  CheckpointState unevaluated = state;
  unevaluated.steady_state = false;
  writeCheckpoint(plain, unevaluated);
  auto [plain_code, plain_message] = failure([&] { readCheckpoint(checkpointPath(plain)); });
  EXPECT_EQ(plain_code, ExitCode::checkpoint);
  EXPECT_NE(plain_message.find("not fully evaluated"), std::string::npos) << plain_message;
  // a changed bred_after fails the state hash
  const std::size_t rows = individuals.size();
  patchFile(checkpointPath(dir), [rows](hid_t file) {
    hid_t dataset = H5Dopen2(file, "population/bred_after", H5P_DEFAULT);
    std::vector<std::uint64_t> values(rows);
    H5Dread(dataset, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    values.back() = 99;
    H5Dwrite(dataset, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
  });
  auto [code, message] = failure([&] { readCheckpoint(checkpointPath(dir)); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("state_hash"), std::string::npos) << message;
}

TEST(Checkpoint, MissingButExpectedIsAnError) {
  // a previous checkpoint without a current one
  std::string dir = tempDir("missing_current");
  writeCheckpoint(dir, makeState(1));
  writeCheckpoint(dir, makeState(2));
  std::filesystem::remove(checkpointPath(dir));
  auto [code, message] = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find(checkpointPath(dir) + ": missing"), std::string::npos) << message;
  EXPECT_NE(message.find("is good"), std::string::npos) << message;

  // a history that records a checkpoint
  dir = tempDir("missing_recorded");
  {
    HistoryWriter writer(dir + "/history.h5", HistoryAttributes{}, kMeasures);
    GenerationRecord row;
    writer.appendGeneration({}, row);
    row.checkpoint_seconds = 0.25;
    writer.completeLastGeneration(row);
  }
  std::tie(code, message) = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("records that checkpoints were written"), std::string::npos) << message;

  // a history with generations but no checkpoint: refused, the history kept
  dir = tempDir("missing_unrecorded");
  {
    HistoryWriter writer(dir + "/history.h5", HistoryAttributes{}, kMeasures);
    writer.appendGeneration({}, GenerationRecord{});
  }
  auto size_before = std::filesystem::file_size(dir + "/history.h5");
  std::tie(code, message) = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("holds 1 generation(s)"), std::string::npos) << message;
  EXPECT_NE(message.find("nothing was changed"), std::string::npos) << message;
  EXPECT_NE(message.find("--fresh"), std::string::npos) << message;
  EXPECT_EQ(std::filesystem::file_size(dir + "/history.h5"), size_before);

  // ... unless it is generation 0 of this very run (killed before its first checkpoint)
  dir = tempDir("missing_first_of_this_run");
  HistoryAttributes this_run;
  this_run.config_hash = "0123456789abcdef";
  this_run.seed = 7;
  {
    HistoryWriter writer(dir + "/history.h5", this_run, kMeasures);
    writer.appendGeneration({}, GenerationRecord{});
  }
  EXPECT_FALSE(findCheckpoint(dir, &this_run).has_value());
  for (auto other : {std::pair<std::string, std::uint64_t>{"0123456789abcdef", 8},
                     std::pair<std::string, std::uint64_t>{"fedcba9876543210", 7}}) {
    HistoryAttributes another = this_run;
    std::tie(another.config_hash, another.seed) = other;
    std::tie(code, message) = failure([&] { findCheckpoint(dir, &another); });
    EXPECT_EQ(code, ExitCode::checkpoint);
    EXPECT_NE(message.find("holds 1 generation(s)"), std::string::npos) << message;
  }
  {
    HistoryWriter writer(dir + "/history.h5", this_run, kMeasures);
    writer.appendGeneration({}, GenerationRecord{});
    GenerationRecord second;
    second.generation = 1;
    writer.appendGeneration({}, second);
  }
  std::tie(code, message) = failure([&] { findCheckpoint(dir, &this_run); });
  EXPECT_NE(message.find("holds 2 generation(s)"), std::string::npos) << message;

  // a history that is not one (junk, or another kind of HDF5 file): refused, kept
  dir = tempDir("missing_junk_history");
  std::ofstream(dir + "/history.h5") << "not an HDF5 file";
  std::tie(code, message) = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find(dir + "/history.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("nothing was changed"), std::string::npos) << message;
  EXPECT_EQ(std::filesystem::file_size(dir + "/history.h5"), 16u);
  dir = tempDir("missing_foreign_history");
  writeCheckpoint(dir, makeState(1));
  std::filesystem::rename(checkpointPath(dir), dir + "/history.h5");
  std::tie(code, message) = failure([&] { findCheckpoint(dir); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find(dir + "/history.h5"), std::string::npos) << message;

  // a history without a complete generation (killed during the first): a fresh run
  dir = tempDir("missing_empty_history");
  { HistoryWriter writer(dir + "/history.h5", HistoryAttributes{}, kMeasures); }
  EXPECT_FALSE(findCheckpoint(dir).has_value());
}

TEST(Checkpoint, RemoveCheckpointsClearsEveryFile) {
  std::string dir = tempDir("remove");
  writeCheckpoint(dir, makeState(1));
  writeCheckpoint(dir, makeState(2));
  std::ofstream(checkpointPath(dir) + ".tmp") << "partial";
  removeCheckpoints(dir);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// a checkpoint written by cambrian before the plug-in renovation (format version 1, one column
// per outcome field) reads: the population, its genomes and outcomes
TEST(Checkpoint, ReadsAVersionOneCheckpoint) {
  const std::string path =
      std::string(CAMBRIAN_SOURCE_DIR) + "/tests/store/data/v1_run/checkpoint.h5";
  CheckpointState state = readCheckpoint(path);
  EXPECT_EQ(state.seed, 21u);
  EXPECT_EQ(state.next_generation, 3u);
  ASSERT_EQ(state.population.individuals.size(), 8u);
  for (const Individual& individual : state.population.individuals) {
    EXPECT_EQ(individual.genome.encoding().name(), "directed_graph");
    EXPECT_TRUE(individual.evaluated);
    if (individual.outcome.status == EvalStatus::ok) {
      EXPECT_FALSE(std::isnan(individual.outcome.measure("distance")));
    }
  }
  // written again, it is a version-2 checkpoint with the same population
  std::string dir = tempDir("rewritten_v1");
  writeCheckpoint(dir, state);
  CheckpointState back = readCheckpoint(checkpointPath(dir));
  for (std::size_t i = 0; i < 8; ++i) {
    const Individual& a = state.population.individuals[i];
    const Individual& b = back.population.individuals[i];
    EXPECT_EQ(a.genomeBytes(), b.genomeBytes());
    EXPECT_EQ(a.outcome.measures, b.outcome.measures);
    EXPECT_EQ(std::memcmp(&a.outcome.fitness, &b.outcome.fitness, sizeof(double)), 0);
  }
}

}  // namespace
}  // namespace cambrian
