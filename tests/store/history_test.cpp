// Tests of the history file: round trips of the one individual and generation records, measures
// by name, live reading, crash survival, bad files, resume.
#include "store/history.hpp"

#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "core/hash.hpp"
#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>

namespace cambrian {
namespace {

// a fresh path in the test temp directory
std::string tempPath(const std::string& name) {
  std::string path = testing::TempDir() + "/cambrian_history_test_" + name;
  std::filesystem::remove(path);
  return path;
}

// the measure columns of the test histories
const std::vector<MeasureInfo> kMeasures = {{"distance", "m"}, {"height", "m"}};

// a few individuals of generation g with distinct genomes and a measure
std::vector<Individual> makeRows(std::uint64_t g, int count) {
  std::vector<Individual> rows;
  for (int i = 0; i < count; ++i) {
    Individual row;
    row.generation = g;
    row.id = g * 100 + static_cast<std::uint64_t>(i);
    row.origin = i == 0 ? Origin::elite : (i % 2 ? Origin::crossover : Origin::mutation);
    if (g > 0) {
      row.parents.push_back((g - 1) * 100);
      if (row.origin == Origin::crossover)
        row.parents.push_back((g - 1) * 100 + 1);
    }
    row.evaluated = true;
    Outcome& o = row.outcome;
    o.fitness = 0.5 * static_cast<double>(g) + 0.125 * i;
    o.status = i == 3 ? EvalStatus::exploded : EvalStatus::ok;
    o.measures = {{"distance", 1.5 + i}};
    o.parts = 2 + i;
    o.joints = 1 + i;
    o.neurons = 3 * i;
    o.steps = 2400;
    row.eval_seconds = 0.01 * i;
    row.worker_rank = i % 3;
    row.bred_after = g * 5 + static_cast<std::uint64_t>(i) / 2;
    row.genome = graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 1000 + g, 0, i));
    rows.push_back(row);
  }
  return rows;
}

GenerationRecord makeGeneration(std::uint64_t g) {
  GenerationRecord row;
  row.generation = g;
  row.stats.count = 5;
  row.stats.failed = 1;
  row.stats.best = 1.0 + static_cast<double>(g);
  row.stats.mean = 0.5;
  row.stats.median = 0.25;
  row.stats.q25 = 0.125;
  row.stats.q75 = 0.75;
  row.stats.best_id = g * 100 + 4;
  row.evaluations = 4;
  row.workers = 2;
  row.distinct_genomes = 5;
  row.rank0_cpu_seconds = 0.0625;
  row.rank0_dispatch_seconds = 0.03125;
  row.wall_seconds = 0.3;
  return row;
}

// the genome bytes of individual `id` in a history; empty when absent
std::vector<std::uint8_t> bytesOf(const HistoryReader& reader, std::uint64_t id) {
  for (const Individual& row : reader.individuals()) {
    if (row.id == id)
      return row.genomeBytes();
  }
  return {};
}

HistoryAttributes makeAttributes() {
  HistoryAttributes a;
  a.config_text = "[evolution]\npopulation = 5\n";
  a.run_only_settings = {"run.out", "run.quiet"};
  a.seed = 42;
  a.rank_count = 3;
  return a;
}

// writes `generations` generations and closes
void writeHistory(const std::string& path, int generations) {
  HistoryWriter writer(path, makeAttributes(), kMeasures);
  for (int g = 0; g < generations; ++g)
    writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
  writer.close();
}

// the InputError message of opening and reading `path` ("" when none)
std::string openError(const std::string& path) {
  try {
    HistoryReader reader(path);
    reader.individuals();
    reader.generations();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), ExitCode::input_file);
    return e.what();
  }
  return "";
}

TEST(History, RoundTripsAttributesRowsAndGenomeBytes) {
  std::string path = tempPath("round_trip.h5");
  writeHistory(path, 3);
  HistoryReader reader(path);
  const HistoryAttributes& a = reader.attributes();
  EXPECT_EQ(a.format_version, kHistoryFormatVersion);
  EXPECT_EQ(a.cambrian_version, kVersion);
  EXPECT_EQ(a.git_hash, kGitHash);
  EXPECT_EQ(a.config_text, "[evolution]\npopulation = 5\n");
  EXPECT_EQ(a.config_hash, hashText(a.config_text));
  EXPECT_EQ(a.run_only_settings, (std::vector<std::string>{"run.out", "run.quiet"}));
  EXPECT_EQ(reader.measures(), kMeasures);
  EXPECT_EQ(a.seed, 42u);
  EXPECT_EQ(a.rank_count, 3);
  EXPECT_EQ(a.bullet_precision, "float64");
  EXPECT_EQ(a.start_time.size(), 20u);
  EXPECT_EQ(a.start_time.back(), 'Z');

  std::vector<Individual> rows = reader.individuals();
  ASSERT_EQ(rows.size(), 15u);
  for (int g = 0; g < 3; ++g) {
    std::vector<Individual> expected = makeRows(static_cast<std::uint64_t>(g), 5);
    for (int i = 0; i < 5; ++i) {
      const Individual& got = rows[static_cast<std::size_t>(g * 5 + i)];
      const Individual& want = expected[static_cast<std::size_t>(i)];
      EXPECT_EQ(got.generation, want.generation);
      EXPECT_EQ(got.id, want.id);
      EXPECT_EQ(got.parents, want.parents);
      EXPECT_EQ(got.origin, want.origin);
      EXPECT_EQ(got.fitness(), want.fitness());
      EXPECT_TRUE(got.evaluated);
      EXPECT_EQ(got.outcome.status, want.outcome.status);
      // the measures by name; a declared one an outcome lacks is absent again
      EXPECT_EQ(got.outcome.measures, want.outcome.measures);
      EXPECT_TRUE(std::isnan(got.outcome.measure("height")));
      EXPECT_EQ(got.outcome.parts, want.outcome.parts);
      EXPECT_EQ(got.outcome.joints, want.outcome.joints);
      EXPECT_EQ(got.outcome.neurons, want.outcome.neurons);
      EXPECT_EQ(got.outcome.steps, want.outcome.steps);
      EXPECT_EQ(got.eval_seconds, want.eval_seconds);
      EXPECT_EQ(got.worker_rank, want.worker_rank);
      EXPECT_EQ(got.bred_after, want.bred_after);
      EXPECT_EQ(got.genomeBytes(), want.genomeBytes());
      EXPECT_TRUE(got.genome == want.genome);
    }
  }
  EXPECT_TRUE(rows[0].parents.empty());

  std::vector<GenerationRecord> generations = reader.generations();
  ASSERT_EQ(generations.size(), 3u);
  EXPECT_EQ(generations[2].generation, 2u);
  EXPECT_EQ(generations[2].stats.best, 3.0);
  EXPECT_EQ(generations[2].stats.best_id, 204u);
  EXPECT_EQ(generations[1].workers, 2);
  EXPECT_EQ(generations[1].distinct_genomes, 5u);
  EXPECT_EQ(generations[1].rank0_cpu_seconds, 0.0625);
  EXPECT_EQ(generations[1].rank0_dispatch_seconds, 0.03125);
  EXPECT_EQ(generations[1].wall_seconds, 0.3);
  EXPECT_GT(generations[0].unix_time, 1.6e9);

  EXPECT_EQ(bytesOf(reader, 103), makeRows(1, 5)[3].genomeBytes());
}

TEST(History, ReadsAFileWrittenBeforeTheColumnsAddedLaterAsZero) {
  // a history whose /generations lacks the column added after format version 1
  std::string path = tempPath("without_rank0_cpu.h5");
  writeHistory(path, 2);
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Ldelete(file, "generations/rank0_cpu_seconds", H5P_DEFAULT), 0);
  ASSERT_GE(H5Ldelete(file, "generations/rank0_dispatch_seconds", H5P_DEFAULT), 0);
  // and /individuals without the steady state's bred_after
  ASSERT_GE(H5Ldelete(file, "individuals/bred_after", H5P_DEFAULT), 0);
  H5Fclose(file);

  {
    HistoryReader reader(path);
    std::vector<Individual> rows = reader.individuals();
    ASSERT_EQ(rows.size(), 10u);
    EXPECT_EQ(rows[9].bred_after, 0u);
    std::vector<GenerationRecord> generations = reader.generations();
    ASSERT_EQ(generations.size(), 2u);
    EXPECT_EQ(generations[1].rank0_cpu_seconds, 0.0);
    EXPECT_EQ(generations[1].rank0_dispatch_seconds, 0.0);
    EXPECT_EQ(generations[1].wall_seconds, 0.3);
    EXPECT_EQ(generations[1].stats.best, 2.0);
  }

  // a column that was always there is still required
  file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Ldelete(file, "generations/wall_seconds", H5P_DEFAULT), 0);
  H5Fclose(file);
  EXPECT_NE(openError(path).find("/generations/wall_seconds missing"), std::string::npos);
}

// a measure the task did not declare is refused before anything is written
TEST(History, RefusesAMeasureTheTaskDidNotDeclare) {
  std::string path = tempPath("undeclared.h5");
  HistoryWriter writer(path, makeAttributes(), kMeasures);
  std::vector<Individual> rows = makeRows(0, 2);
  rows[1].outcome.measures.push_back({"speed", 3});
  try {
    writer.appendGeneration(rows, makeGeneration(0));
    FAIL() << "an undeclared measure was stored";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'speed'"), std::string::npos) << e.what();
  }
  writer.close();
  EXPECT_TRUE(HistoryReader(path).individuals().empty());
  // and a history needs a measure column
  EXPECT_THROW(HistoryWriter(tempPath("no_measures.h5"), makeAttributes(), {}), Error);
}

// a task with one measure still gets a two-dimensional /individuals/measures
TEST(History, OneMeasureIsStillAColumnOfAMatrix) {
  std::string path = tempPath("one_measure.h5");
  {
    HistoryWriter writer(path, makeAttributes(), {{"distance", "m"}});
    writer.appendGeneration(makeRows(0, 3), makeGeneration(0));
  }
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t dataset = H5Dopen2(file, "/individuals/measures", H5P_DEFAULT);
  hid_t space = H5Dget_space(dataset);
  EXPECT_EQ(H5Sget_simple_extent_ndims(space), 2);
  H5Sclose(space);
  H5Dclose(dataset);
  H5Fclose(file);
  EXPECT_EQ(HistoryReader(path).individuals()[2].outcome.measure("distance"), 3.5);
}

TEST(History, ReadableByAnotherProcessWhileTheWriterHoldsItOpen) {
  // a child process writes generation by generation, waiting for the parent to read each one
  std::string path = tempPath("live.h5");
  int to_parent[2], to_child[2];
  ASSERT_EQ(pipe(to_parent), 0);
  ASSERT_EQ(pipe(to_child), 0);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(to_parent[0]);
    close(to_child[1]);
    char token = 'x';
    try {
      HistoryWriter writer(path, makeAttributes(), kMeasures);
      for (int g = 0; g < 2; ++g) {
        writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
        if (write(to_parent[1], &token, 1) != 1 || read(to_child[0], &token, 1) != 1)
          _exit(4);
      }
      writer.close();
      bool closed = false;
      try {
        writer.appendGeneration(makeRows(2, 1), makeGeneration(2));
      } catch (const Error&) {
        closed = true;
      }
      _exit(closed ? 0 : 6);
    } catch (...) {
      _exit(3);
    }
  }
  close(to_parent[1]);
  close(to_child[0]);
  char token = 0;
  for (std::size_t g = 1; g <= 2; ++g) {
    ASSERT_EQ(read(to_parent[0], &token, 1), 1);
    {
      HistoryReader reader(path);
      EXPECT_EQ(reader.individuals().size(), 5 * g);
      EXPECT_EQ(reader.generations().size(), g);
      EXPECT_EQ(bytesOf(reader, (g - 1) * 100 + 4), makeRows(g - 1, 5)[4].genomeBytes());
    }
    ASSERT_EQ(write(to_child[1], &token, 1), 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  close(to_parent[0]);
  close(to_child[1]);
  EXPECT_EQ(HistoryReader(path).generations().size(), 2u);
}

TEST(History, AReaderThatOpenedItBetweenGenerationsReadsOnWhenTheWriterGoesOn) {
  // the reader opens the file while the writer has it closed (between generations), then the
  // writer takes it up and appends: the reader's reads must still succeed
  std::string path = tempPath("between.h5");
  int to_parent[2], to_child[2];
  ASSERT_EQ(pipe(to_parent), 0);
  ASSERT_EQ(pipe(to_child), 0);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(to_parent[0]);
    close(to_child[1]);
    char token = 'x';
    try {
      HistoryWriter writer(path, makeAttributes(), kMeasures);
      writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
      writer.completeLastGeneration(GenerationRecord{});
      if (write(to_parent[1], &token, 1) != 1 || read(to_child[0], &token, 1) != 1)
        _exit(4);
      for (int g = 1; g < 4; ++g)
        writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
      // the file stays held by the writer while the parent reads
      if (write(to_parent[1], &token, 1) != 1 || read(to_child[0], &token, 1) != 1)
        _exit(4);
      writer.close();
      _exit(0);
    } catch (...) {
      _exit(3);
    }
  }
  close(to_parent[1]);
  close(to_child[0]);
  char token = 0;
  ASSERT_EQ(read(to_parent[0], &token, 1), 1);
  {
    HistoryReader reader(path, HistoryReadMode::this_process_only);
    ASSERT_EQ(write(to_child[1], &token, 1), 1);
    ASSERT_EQ(read(to_parent[0], &token, 1), 1);
    std::vector<Individual> rows;
    std::vector<GenerationRecord> generations;
    EXPECT_NO_THROW(rows = reader.individuals());
    EXPECT_NO_THROW(generations = reader.generations());
    EXPECT_EQ(rows.size(), 5 * generations.size());
    EXPECT_GE(generations.size(), 1u);
  }
  ASSERT_EQ(write(to_child[1], &token, 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  close(to_parent[0]);
  close(to_child[1]);
  EXPECT_EQ(HistoryReader(path).generations().size(), 4u);
}

TEST(History, EveryOpenSucceedsWhileTheWriterTakesTheFileUpAndPutsItDown) {
  // a writer that opens and closes the file every generation, as fast as it can, and a reader
  // that opens it over and over meanwhile: no open may fail (a live report once failed so)
  std::string path = tempPath("busy.h5");
  int to_parent[2];
  ASSERT_EQ(pipe(to_parent), 0);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(to_parent[0]);
    char token = 'x';
    try {
      HistoryWriter writer(path, makeAttributes(), kMeasures);
      writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
      writer.completeLastGeneration(GenerationRecord{});
      if (write(to_parent[1], &token, 1) != 1)
        _exit(4);
      for (int g = 1; g < 300; ++g) {
        writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
        writer.completeLastGeneration(GenerationRecord{});
      }
      writer.close();
      _exit(0);
    } catch (...) {
      _exit(3);
    }
  }
  close(to_parent[1]);
  char token = 0;
  ASSERT_EQ(read(to_parent[0], &token, 1), 1);
  int opened = 0;
  std::vector<std::string> failures;
  int status = 0;
  while (waitpid(child, &status, WNOHANG) == 0) {
    try {
      HistoryReader reader(path, HistoryReadMode::this_process_only);
      EXPECT_GE(reader.generations().size(), 1u);
      ++opened;
    } catch (const Error& e) {
      failures.push_back(e.what());
    }
  }
  close(to_parent[0]);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_GT(opened, 0);
  EXPECT_TRUE(failures.empty()) << failures.size() << " of " << opened + failures.size()
                                << " opens failed, the first: " << failures.front();
}

// the output and exit code of a shell command
std::pair<int, std::string> shell(const std::string& command) {
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe)
    return {-1, ""};
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
    output.append(buffer, n);
  int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

TEST(History, ToolsWithoutSwmrReadItBetweenGenerations) {
  // after each completed generation the file is closed: h5dump (no SWMR) reads it
  std::string path = tempPath("tools.h5");
  HistoryWriter writer(path, makeAttributes(), kMeasures);
  EXPECT_EQ(shell("h5dump -H " + path).first, 0);
  for (int g = 0; g < 2; ++g) {
    writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
    writer.completeLastGeneration(GenerationRecord{});
    auto [code, output] = shell("h5dump -d /generations/generation " + path);
    EXPECT_EQ(code, 0) << output;
    EXPECT_NE(
        output.find("DATASPACE  SIMPLE { ( " + std::to_string(g + 1) + " ) / ( H5S_UNLIMITED ) }"),
        std::string::npos)
        << output;
  }
}

TEST(History, AReaderHoldingTheFileOpenDoesNotStopTheWriter) {
  // another process opens the file the plain way (HDF5's default file lock) and keeps it open
  std::string path = tempPath("held.h5");
  HistoryWriter writer(path, makeAttributes(), kMeasures);
  writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
  writer.completeLastGeneration(GenerationRecord{});
  int ready[2], release[2];
  ASSERT_EQ(pipe(ready), 0);
  ASSERT_EQ(pipe(release), 0);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    char token = file >= 0 ? 'y' : 'n';
    if (write(ready[1], &token, 1) != 1 || read(release[0], &token, 1) != 1)
      _exit(4);
    _exit(file >= 0 && H5Fclose(file) >= 0 ? 0 : 3);
  }
  char token = 0;
  ASSERT_EQ(read(ready[0], &token, 1), 1);
  EXPECT_EQ(token, 'y');

  // the writer appends and completes a generation while the reader holds the file
  EXPECT_NO_THROW({
    writer.appendGeneration(makeRows(1, 5), makeGeneration(1));
    writer.completeLastGeneration(GenerationRecord{});
  });
  ASSERT_EQ(write(release[1], &token, 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_EQ(HistoryReader(path).generations().size(), 2u);
}

TEST(History, SurvivesAWriterKilledMidRun) {
  // a child writes three generations, reports, and is killed without closing the file
  std::string path = tempPath("killed.h5");
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ready[0]);
    try {
      auto* writer = new HistoryWriter(path, makeAttributes(), kMeasures);
      for (int g = 0; g < 3; ++g)
        writer->appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
    } catch (...) {
      _exit(3);
    }
    char done = 'x';
    if (write(ready[1], &done, 1) != 1)
      _exit(4);
    pause();
    _exit(5);
  }
  close(ready[1]);
  char done = 0;
  ASSERT_EQ(read(ready[0], &done, 1), 1);
  close(ready[0]);
  kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));

  // everything up to the last flushed generation is there
  HistoryReader reader(path);
  EXPECT_EQ(reader.attributes().seed, 42u);
  EXPECT_EQ(reader.individuals().size(), 15u);
  ASSERT_EQ(reader.generations().size(), 3u);
  EXPECT_EQ(reader.generations()[2].stats.best, 3.0);
  EXPECT_EQ(bytesOf(reader, 202), makeRows(2, 5)[2].genomeBytes());
}

// the writer works beside the evaluations, so the file may go at any moment: between an
// append and the completion of its row, or between the writer's look and its opening
TEST(History, AFileDeletedBetweenAppendAndCompletionIsWrittenBackWhole) {
  std::string path = tempPath("deleted_mid_generation.h5");
  {
    HistoryWriter writer(path, makeAttributes(), kMeasures);
    writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
    writer.completeLastGeneration(makeGeneration(0));
    writer.appendGeneration(makeRows(1, 5), makeGeneration(1));
    std::filesystem::remove(path);
    GenerationRecord completed = makeGeneration(1);
    completed.wall_seconds = 7.25;
    writer.completeLastGeneration(completed);
    EXPECT_NE(writer.takeNotice().find("deleted while this run was writing it; written back"),
              std::string::npos);
    writer.appendGeneration(makeRows(2, 5), makeGeneration(2));
    EXPECT_EQ(writer.takeNotice(), "");
    writer.close();
  }
  HistoryReader reader(path);
  std::vector<GenerationRecord> generations = reader.generations();
  ASSERT_EQ(generations.size(), 3u);
  EXPECT_EQ(generations[1].wall_seconds, 7.25);
  EXPECT_EQ(reader.individuals().size(), 15u);
}

TEST(History, MissingFileIsAnInputErrorNamingIt) {
  std::string path = tempPath("missing.h5");
  std::string message = openError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("no such"), std::string::npos) << message;
}

TEST(History, NonHdf5FileIsAnInputErrorNamingIt) {
  std::string path = tempPath("text.h5");
  std::ofstream(path) << "generation\tid\n0\t1\n";
  std::string message = openError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
}

TEST(History, TruncatedFileIsAnInputErrorNamingIt) {
  std::string path = tempPath("truncated.h5");
  writeHistory(path, 3);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  std::string message = openError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_FALSE(message.empty());
}

TEST(History, CorruptFileIsAnInputErrorNamingIt) {
  // the signature survives, the rest is noise
  std::string path = tempPath("corrupt.h5");
  writeHistory(path, 2);
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(8);
    for (int i = 0; i < 4096; ++i)
      file.put(static_cast<char>((i * 131 + 7) & 0xff));
  }
  std::string message = openError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(History, ForeignHdf5FileIsAnInputErrorNamingIt) {
  // a valid HDF5 file with a dataset but none of the history's attributes
  std::string path = tempPath("foreign.h5");
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  hsize_t size = 4;
  hid_t space = H5Screate_simple(1, &size, nullptr);
  hid_t dataset =
      H5Dcreate2(file, "data", H5T_NATIVE_INT, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  int values[4] = {1, 2, 3, 4};
  H5Dwrite(dataset, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values);
  H5Dclose(dataset);
  H5Sclose(space);
  H5Fclose(file);
  std::string message = openError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not a cambrian history"), std::string::npos) << message;
}

TEST(History, UnwritablePathIsAnOutputError) {
  try {
    HistoryWriter writer("/nonexistent-dir/history.h5", makeAttributes(), kMeasures);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::output_file);
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/history.h5"), std::string::npos);
  }
}

TEST(History, FreshFileHasNoRowsAndBadGenomeBytesNameTheFile) {
  std::string path = tempPath("empty.h5");
  HistoryWriter writer(path, makeAttributes(), kMeasures);
  {
    HistoryReader reader(path);
    EXPECT_TRUE(reader.individuals().empty());
    EXPECT_TRUE(reader.generations().empty());
  }
  writer.appendGeneration(makeRows(0, 2), makeGeneration(0));
  writer.close();

  // the first genome's tag overwritten: no encoding reads it
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  hid_t dataset = H5Dopen2(file, "/individuals/genome_bytes", H5P_DEFAULT);
  hsize_t start = 0, count = 4;
  hid_t space = H5Dget_space(dataset);
  H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
  hid_t memory = H5Screate_simple(1, &count, nullptr);
  const std::uint8_t zeros[4] = {0, 0, 0, 0};
  ASSERT_GE(H5Dwrite(dataset, H5T_NATIVE_UINT8, memory, space, H5P_DEFAULT, zeros), 0);
  H5Sclose(memory);
  H5Sclose(space);
  H5Dclose(dataset);
  H5Fclose(file);
  HistoryReader reader(path);
  try {
    reader.individuals();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("individual 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cambrian

namespace cambrian {
namespace {

TEST(HistoryResume, CutsBackAKilledWritersFileAndAppends) {
  // a child writes four generations and is killed without closing the file
  std::string path = tempPath("resume.h5");
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      auto* writer = new HistoryWriter(path, makeAttributes(), kMeasures);
      for (int g = 0; g < 4; ++g)
        writer->appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
      GenerationRecord times = makeGeneration(3);
      times.checkpoint_seconds = 0.5;
      writer->completeLastGeneration(times);
    } catch (...) {
      _exit(3);
    }
    raise(SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));

  // generations 0 and 1 kept, 2 and 3 dropped, then a new generation 2 appended
  HistoryRows kept;
  HistoryAttributes attributes = makeAttributes();
  attributes.rank_count = 7;
  auto writer = resumeHistory(path, 2, attributes, kMeasures, kept);
  ASSERT_EQ(kept.generations.size(), 2u);
  EXPECT_EQ(kept.individuals.size(), 10u);
  EXPECT_EQ(kept.individuals[7].genomeBytes(), makeRows(1, 5)[2].genomeBytes());
  EXPECT_EQ(kept.individuals[7].outcome.measures, makeRows(1, 5)[2].outcome.measures);
  EXPECT_FALSE(std::filesystem::exists(path + ".resume.tmp"));
  GenerationRecord next = makeGeneration(2);
  next.stats.best = 99;
  writer->appendGeneration(makeRows(2, 5), next);
  GenerationRecord times = next;
  times.rank0_serial_seconds = 0.125;
  times.rank0_cpu_seconds = 0.375;
  times.checkpoint_seconds = 0.25;
  times.wall_seconds = 1.5;
  writer->completeLastGeneration(times);
  writer->close();

  HistoryReader reader(path);
  EXPECT_EQ(reader.attributes().rank_count, 7);
  ASSERT_EQ(reader.generations().size(), 3u);
  EXPECT_EQ(reader.generations()[2].stats.best, 99.0);
  // the last row's timings rewritten in place, the rest of it and the rows before untouched
  EXPECT_EQ(reader.generations()[2].checkpoint_seconds, 0.25);
  EXPECT_EQ(reader.generations()[2].rank0_serial_seconds, 0.125);
  EXPECT_EQ(reader.generations()[2].rank0_cpu_seconds, 0.375);
  EXPECT_EQ(reader.generations()[2].wall_seconds, 1.5);
  EXPECT_EQ(reader.generations()[2].rank0_dispatch_seconds, 0.03125);
  EXPECT_EQ(reader.generations()[1].checkpoint_seconds, 0.0);
  EXPECT_EQ(reader.generations()[1].wall_seconds, 0.3);
  EXPECT_EQ(reader.individuals().size(), 15u);
  EXPECT_EQ(bytesOf(reader, 202), makeRows(2, 5)[2].genomeBytes());
}

TEST(HistoryResume, AHistoryOfAnotherRunIsRefusedAndLeftAlone) {
  // the checkpoint's digest over generations 0 and 1 of this history, and of another run's
  std::string path = tempPath("other_run.h5");
  {
    HistoryWriter writer(path, makeAttributes(), kMeasures);
    for (int g = 0; g < 3; ++g)
      writer.appendGeneration(makeRows(static_cast<std::uint64_t>(g), 5), makeGeneration(g));
  }
  RunDigest ours;
  for (int g = 0; g < 2; ++g)
    for (const Individual& row : makeRows(static_cast<std::uint64_t>(g), 5))
      ours.add(row);
  std::vector<Individual> changed = makeRows(1, 5);
  changed[3].outcome.fitness += 1e-9;
  RunDigest theirs;
  for (const Individual& row : makeRows(0, 5))
    theirs.add(row);
  for (const Individual& row : changed)
    theirs.add(row);
  ASSERT_NE(ours.value(), theirs.value());

  auto bytes = [&path] {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const std::string before = bytes();
  HistoryRows kept;
  try {
    resumeHistory(path, 2, makeAttributes(), kMeasures, kept, 0, theirs.value());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": belongs to another run than the checkpoint"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(bytes(), before);  // nothing rewritten
  EXPECT_FALSE(std::filesystem::exists(path + ".resume.tmp"));
  // its own run's digest: resumed
  auto writer = resumeHistory(path, 2, makeAttributes(), kMeasures, kept, 0, ours.value());
  EXPECT_EQ(kept.individuals.size(), 10u);
}

// every dataset of a group `more` rows longer, the new rows never written (read as zeros): what
// an append cut short by a kill or a full disk leaves
void extendUnwritten(const std::string& path, const char* group_name, hsize_t more) {
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  hid_t group = H5Gopen2(file, group_name, H5P_DEFAULT);
  ASSERT_GE(group, 0);
  hsize_t count = 0;
  ASSERT_GE(H5Gget_num_objs(group, &count), 0);
  for (hsize_t i = 0; i < count; ++i) {
    char name[256] = {};
    H5Gget_objname_by_idx(group, i, name, sizeof name);
    hid_t dataset = H5Dopen2(group, name, H5P_DEFAULT);
    hid_t space = H5Dget_space(dataset);
    hsize_t dims[2] = {};
    int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    dims[0] += std::string(name) == "genome_bytes" ? more * 100 : more;
    ASSERT_GE(H5Dset_extent(dataset, dims), 0) << name << " rank " << rank;
    H5Sclose(space);
    H5Dclose(dataset);
  }
  H5Gclose(group);
  H5Fclose(file);
}

TEST(History, RowsOfAnAppendCutShortAreNotRead) {
  std::string path = tempPath("torn.h5");
  writeHistory(path, 2);
  // generation 2's individual rows and its generation row extended, never filled
  extendUnwritten(path, "individuals", 5);
  extendUnwritten(path, "generations", 1);
  {
    HistoryReader reader(path);
    EXPECT_EQ(reader.generations().size(), 2u);
    std::vector<Individual> rows = reader.individuals();
    ASSERT_EQ(rows.size(), 10u);
    EXPECT_EQ(rows.back().generation, 1u);
  }
  // resume keeps the two generations and drops the torn rows
  HistoryRows kept;
  auto writer = resumeHistory(path, 2, makeAttributes(), kMeasures, kept);
  EXPECT_EQ(kept.individuals.size(), 10u);
  writer->appendGeneration(makeRows(2, 5), makeGeneration(2));
  writer->close();
  HistoryReader again(path);
  EXPECT_EQ(again.generations().size(), 3u);
  EXPECT_EQ(again.individuals().size(), 15u);

  // individuals written, the generation row not: the generation is not in the history yet
  std::string half = tempPath("torn_half.h5");
  {
    HistoryWriter half_writer(half, makeAttributes(), kMeasures);
    half_writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
    GenerationRecord unfinished = makeGeneration(1);
    unfinished.generation = 0;  // what a zero-filled row reads as
    half_writer.appendGeneration(makeRows(1, 5), unfinished);
  }
  HistoryReader reader(half);
  EXPECT_EQ(reader.generations().size(), 1u);
  EXPECT_EQ(reader.individuals().size(), 5u);
}

TEST(HistoryResume, TooFewGenerationsIsAnInputErrorNamingTheFile) {
  std::string path = tempPath("short.h5");
  {
    HistoryWriter writer(path, makeAttributes(), kMeasures);
    writer.appendGeneration(makeRows(0, 5), makeGeneration(0));
  }
  HistoryRows kept;
  try {
    resumeHistory(path, 3, makeAttributes(), kMeasures, kept);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": holds 1 generation rows"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cambrian
