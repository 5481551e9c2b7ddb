#include "store/checkpoint.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "core/bytes.hpp"
#include "core/hash.hpp"
#include "core/outcome_bytes.hpp"
#include "core/small_file.hpp"
#include "store/hdf5_io.hpp"
#include "store/history.hpp"
#include "store/read_in_child.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace cambrian {

// the store module's HDF5 helpers
using namespace hdf5;

namespace {

// the genomes' byte forms one after another, as a column to write: never gathered into one
// string (at 100,000 graph genomes that would be half a gigabyte more)
struct ByteParts {
  std::vector<const std::vector<std::uint8_t>*> parts;
  std::uint64_t size = 0;  // bytes in all parts
};

// the columns of /population (version 2): one row per individual, genomes and outcomes in
// their byte forms; the genome bytes a ByteParts when written, one string when read
template <class GenomeBytes>
struct ColumnsOf {
  std::vector<std::uint64_t> id, generation, parent_a, parent_b, genome_offset, genome_size,
      outcome_offset, outcome_size;
  std::vector<std::uint8_t> origin, evaluated, outcome_bytes;
  GenomeBytes genome_bytes;
  std::vector<double> eval_seconds;
  std::vector<std::int32_t> worker_rank;
};
using Columns = ColumnsOf<std::vector<std::uint8_t>>;
using ColumnsToWrite = ColumnsOf<ByteParts>;

// calls visit(name, column) for every column, in the fixed order the state hash uses
template <class C, class Visit>
void forEachColumn(C& c, Visit visit) {
  visit("id", c.id);
  visit("generation", c.generation);
  visit("parent_a", c.parent_a);
  visit("parent_b", c.parent_b);
  visit("origin", c.origin);
  visit("evaluated", c.evaluated);
  visit("eval_seconds", c.eval_seconds);
  visit("worker_rank", c.worker_rank);
  visit("genome_offset", c.genome_offset);
  visit("genome_size", c.genome_size);
  visit("genome_bytes", c.genome_bytes);
  visit("outcome_offset", c.outcome_offset);
  visit("outcome_size", c.outcome_size);
  visit("outcome_bytes", c.outcome_bytes);
}

// the columns of version 1 (read only): every outcome field a column of its own
struct ColumnsV1 {
  std::vector<std::uint64_t> id, generation, parent_a, parent_b, steps, genome_offset, genome_size,
      message_offset, message_size, measure_count;
  std::vector<std::uint8_t> origin, evaluated, status, genome_bytes, message_bytes, measure_names;
  std::vector<double> fitness, outcome_wall_seconds, eval_seconds, measure_values;
  std::vector<std::int32_t> parts, joints, neurons, worker_rank;
};

template <class C, class Visit>
void forEachColumnV1(C& c, Visit visit) {
  visit("id", c.id);
  visit("generation", c.generation);
  visit("parent_a", c.parent_a);
  visit("parent_b", c.parent_b);
  visit("origin", c.origin);
  visit("evaluated", c.evaluated);
  visit("fitness", c.fitness);
  visit("status", c.status);
  visit("steps", c.steps);
  visit("outcome_wall_seconds", c.outcome_wall_seconds);
  visit("parts", c.parts);
  visit("joints", c.joints);
  visit("neurons", c.neurons);
  visit("eval_seconds", c.eval_seconds);
  visit("worker_rank", c.worker_rank);
  visit("genome_offset", c.genome_offset);
  visit("genome_size", c.genome_size);
  visit("genome_bytes", c.genome_bytes);
  visit("message_offset", c.message_offset);
  visit("message_size", c.message_size);
  visit("message_bytes", c.message_bytes);
  visit("measure_count", c.measure_count);
  visit("measure_names", c.measure_names);
  visit("measure_values", c.measure_values);
}

// a column into the state hash: its length, then its values' bytes
template <class T>
void hashColumn(Fnv1a& hash, const std::vector<T>& values) {
  std::uint64_t n = values.size();
  hash.add(&n, sizeof n);
  hash.add(values.data(), values.size() * sizeof(values[0]));
}
void hashColumn(Fnv1a& hash, const ByteParts& bytes) {
  hash.add(&bytes.size, sizeof bytes.size);
  for (const std::vector<std::uint8_t>* part : bytes.parts)
    hash.add(part->data(), part->size());
}

// steady-state: every individual's bred_after, in row order
std::vector<std::uint64_t> bredAfterColumn(const Population& population) {
  std::vector<std::uint64_t> column;
  column.reserve(population.individuals.size());
  for (const Individual& i : population.individuals)
    column.push_back(i.bred_after);
  return column;
}

// the hash of the scalar state and every column (detects corruption the HDF5 layer misses)
template <class C, class ForEach>
std::uint64_t stateHash(const CheckpointState& s, const C& columns, ForEach forEach) {
  Fnv1a hash;
  hash.add(s.config_text.data(), s.config_text.size());
  for (std::uint64_t v :
       {s.seed, s.next_generation, s.next_id, s.digest, s.population.generation}) {
    hash.add(&v, sizeof v);
  }
  forEach(columns, [&](const char*, const auto& values) { hashColumn(hash, values); });
  // islands only (a checkpoint without them hashes as before)
  if (!s.migrations.empty())
    hashColumn(hash, s.migrations);
  // steady-state only (likewise)
  if (s.steady_state)
    hashColumn(hash, bredAfterColumn(s.population));
  return hash.value();
}

// appends bytes to a stream and their (offset, size)
void appendBytes(std::vector<std::uint8_t>& stream, const std::vector<std::uint8_t>& bytes,
                 std::vector<std::uint64_t>& offsets, std::vector<std::uint64_t>& sizes) {
  offsets.push_back(stream.size());
  sizes.push_back(bytes.size());
  stream.insert(stream.end(), bytes.begin(), bytes.end());
}

// the population as columns
ColumnsToWrite toColumns(const Population& population) {
  ColumnsToWrite c;
  std::vector<std::uint8_t> outcome;
  for (const Individual& i : population.individuals) {
    c.id.push_back(i.id);
    c.generation.push_back(i.generation);
    c.parent_a.push_back(i.parents.size() > 0 ? i.parents[0] : kNoId);
    c.parent_b.push_back(i.parents.size() > 1 ? i.parents[1] : kNoId);
    c.origin.push_back(static_cast<std::uint8_t>(i.origin));
    c.evaluated.push_back(i.evaluated ? 1 : 0);
    c.eval_seconds.push_back(i.eval_seconds);
    c.worker_rank.push_back(i.worker_rank);
    const std::vector<std::uint8_t>& genome = i.genomeBytes();
    c.genome_offset.push_back(c.genome_bytes.size);
    c.genome_size.push_back(genome.size());
    c.genome_bytes.parts.push_back(&genome);
    c.genome_bytes.size += genome.size();
    outcome.clear();
    ByteWriter writer(outcome);
    writeOutcome(writer, i.outcome);
    appendBytes(c.outcome_bytes, outcome, c.outcome_offset, c.outcome_size);
  }
  return c;
}

// the bytes [offset, offset + size) of a stream; throws std::runtime_error past its end
const std::uint8_t* slice(const std::vector<std::uint8_t>& stream, std::uint64_t offset,
                          std::uint64_t size, std::size_t row, const char* what) {
  if (offset > stream.size() || size > stream.size() - offset)
    throw std::runtime_error("/population row " + std::to_string(row) + ": " + what +
                             " offset past the end of its byte stream");
  return stream.data() + offset;
}

// the individual fields every version stores alike
template <class C>
Individual individualFrom(const C& c, std::size_t k) {
  Individual i;
  i.id = c.id[k];
  i.generation = c.generation[k];
  if (c.parent_a[k] != kNoId)
    i.parents.push_back(c.parent_a[k]);
  if (c.parent_b[k] != kNoId)
    i.parents.push_back(c.parent_b[k]);
  if (c.origin[k] >= kOriginKinds)
    throw std::runtime_error("/population row " + std::to_string(k) + ": origin out of range");
  i.origin = static_cast<Origin>(c.origin[k]);
  i.evaluated = c.evaluated[k] != 0;
  i.eval_seconds = c.eval_seconds[k];
  i.worker_rank = c.worker_rank[k];
  i.genome = decodeGenome(slice(c.genome_bytes, c.genome_offset[k], c.genome_size[k], k, "genome"),
                          c.genome_size[k]);
  return i;
}

// whether every per-row column of `c` has `n` rows (the byte streams aside)
template <class C, class ForEach>
bool sameLength(const C& c, std::size_t n, ForEach forEach) {
  bool same = true;
  forEach(c, [&](const char* name, const auto& values) {
    std::string column = name;
    bool stream =
        column.ends_with("_bytes") || column == "measure_names" || column == "measure_values";
    if (!stream && values.size() != n)
      same = false;
  });
  return same;
}

// the population from the columns of either version: every row's shared fields, then its
// outcome from `outcomeOf(k)`; throws std::runtime_error describing an inconsistency
template <class C, class ForEach, class OutcomeOf>
Population populationFrom(const C& c, std::uint64_t generation, ForEach forEach,
                          OutcomeOf outcomeOf) {
  Population population;
  population.generation = generation;
  const std::size_t n = c.id.size();
  if (!sameLength(c, n, forEach))
    throw std::runtime_error("/population columns differ in length");
  for (std::size_t k = 0; k < n; ++k) {
    Individual i = individualFrom(c, k);
    i.outcome = outcomeOf(k);
    population.individuals.push_back(std::move(i));
  }
  return population;
}

// the population from version-2 columns: each outcome in its byte form
Population fromColumns(const Columns& c, std::uint64_t generation) {
  auto forEach = [](auto& columns, auto visit) { forEachColumn(columns, visit); };
  return populationFrom(c, generation, forEach, [&](std::size_t k) {
    ByteReader reader(slice(c.outcome_bytes, c.outcome_offset[k], c.outcome_size[k], k, "outcome"),
                      c.outcome_size[k], "/population row " + std::to_string(k) + " outcome");
    Outcome outcome = readOutcome(reader);
    reader.expectEnd();
    return outcome;
  });
}

// the population from version-1 columns: each outcome field a column of its own
Population fromColumnsV1(const ColumnsV1& c, std::uint64_t generation) {
  auto forEach = [](auto& columns, auto visit) { forEachColumnV1(columns, visit); };
  std::size_t next_name = 0, next_value = 0;
  return populationFrom(c, generation, forEach, [&](std::size_t k) {
    Outcome o;
    if (c.status[k] >= kEvalStatusKinds)
      throw std::runtime_error("/population row " + std::to_string(k) + ": status out of range");
    o.fitness = c.fitness[k];
    o.status = static_cast<EvalStatus>(c.status[k]);
    o.steps = c.steps[k];
    o.wall_seconds = c.outcome_wall_seconds[k];
    o.parts = c.parts[k];
    o.joints = c.joints[k];
    o.neurons = c.neurons[k];
    const std::uint8_t* message =
        slice(c.message_bytes, c.message_offset[k], c.message_size[k], k, "message");
    o.message.assign(message, message + c.message_size[k]);
    for (std::uint64_t m = 0; m < c.measure_count[k]; ++m) {
      Measure measure;
      while (next_name < c.measure_names.size() && c.measure_names[next_name] != 0)
        measure.name += static_cast<char>(c.measure_names[next_name++]);
      if (next_name >= c.measure_names.size() || next_value >= c.measure_values.size())
        throw std::runtime_error("/population row " + std::to_string(k) + ": measures truncated");
      ++next_name;
      measure.value = c.measure_values[next_value++];
      o.measures.push_back(std::move(measure));
    }
    return o;
  });
}

// a 1-D dataset holding `values` (fletcher32-checked chunks when not empty); false on failure
template <class T>
bool writeColumn(hid_t group, const char* name, const std::vector<T>& values) {
  hsize_t size = values.size();
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (size > 0) {
    hsize_t chunk = std::min<hsize_t>(size, 65536);
    H5Pset_chunk(properties.get(), 1, &chunk);
    H5Pset_fletcher32(properties.get());
  }
  return writeDataset(group, name, {size}, nativeType<T>(), values.data(), properties.get())
      .valid();
}

// the genome byte stream as one 1-D dataset like writeColumn's, written a few megabytes (whole
// chunks) at a time
bool writeColumn(hid_t group, const char* name, const ByteParts& bytes) {
  constexpr hsize_t kChunk = 65536, kBlock = 128 * kChunk;
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (bytes.size > 0) {
    hsize_t chunk = std::min<hsize_t>(bytes.size, kChunk);
    H5Pset_chunk(properties.get(), 1, &chunk);
    H5Pset_fletcher32(properties.get());
  }
  Handle dataset =
      writeDataset(group, name, {bytes.size}, H5T_NATIVE_UINT8, nullptr, properties.get());
  if (!dataset.valid())
    return false;
  std::vector<std::uint8_t> block;
  block.reserve(kBlock);
  hsize_t written = 0;
  auto flush = [&] {
    bool ok = writeRows(dataset.get(), H5T_NATIVE_UINT8, block.data(), written, block.size(), 1);
    written += block.size();
    block.clear();
    return ok;
  };
  for (const std::vector<std::uint8_t>* part : bytes.parts) {
    for (std::size_t from = 0; from < part->size();) {
      std::size_t take = std::min<std::size_t>(part->size() - from, kBlock - block.size());
      block.insert(block.end(), part->begin() + from, part->begin() + from + take);
      from += take;
      if (block.size() == kBlock && !flush())
        return false;
    }
  }
  return block.empty() || flush();
}

// a whole 1-D dataset; false when missing, of another shape or unreadable (checksum errors)
template <class T>
bool readColumn(hid_t group, const char* name, std::vector<T>& values) {
  std::vector<hsize_t> dims;
  Handle dataset = openDataset(group, name, 1, dims);
  return dataset.valid() && readValues(dataset.get(), dims[0], values);
}

// fsync of a file or directory by path; false on failure
bool syncPath(const std::string& path, bool directory) {
  int fd = ::open(path.c_str(), directory ? (O_RDONLY | O_DIRECTORY) : O_RDONLY);
  if (fd < 0)
    return false;
  bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

// the HDF5 file at `path` written with `state`; throws Error(output_file)
void writeFile(const std::string& path, const CheckpointState& state,
               const CheckpointStageObserver& observer) {
  QuietErrors quiet;
  auto fail = [&](const std::string& what) {
    std::string reason = systemReason();
    throw Error(ExitCode::output_file, path + ": " + what + (reason.empty() ? "" : ": " + reason));
  };
  Handle file = createFile(path, H5F_LIBVER_V110);
  if (!file.valid())
    fail("cannot create HDF5 file");
  ColumnsToWrite columns = toColumns(state.population);

  // the root attributes: format, provenance, counters, state hash
  hid_t f = file.get();
  bool ok = writeFormat(f, kCheckpointFormatName, kCheckpointFormatVersion, kVersion, kGitHash) &&
            writeString(f, "config_text", state.config_text) &&
            writeString(f, "config_hash", state.config_hash) &&
            writeScalar<std::uint64_t>(f, "seed", state.seed) &&
            writeScalar<std::uint64_t>(f, "generation", state.population.generation) &&
            writeScalar<std::uint64_t>(f, "next_generation", state.next_generation) &&
            writeScalar<std::uint64_t>(f, "next_id", state.next_id) &&
            writeScalar<std::uint64_t>(f, "digest", state.digest) &&
            writeScalar<std::int32_t>(f, "rank_count", state.rank_count) &&
            writeString(f, "written_time", utcTimestamp()) &&
            writeScalar<std::uint64_t>(
                f, "state_hash",
                stateHash(state, columns, [](auto& c, auto visit) { forEachColumn(c, visit); }));
  if (!ok)
    fail("cannot write the root attributes");

  // the population, column by column
  Handle group(H5Gcreate2(f, "population", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid())
    fail("cannot create group /population");
  forEachColumn(columns, [&](const char* name, const auto& values) {
    if (ok)
      ok = writeColumn(group.get(), name, values);
  });
  if (ok && state.steady_state)
    ok = writeColumn(group.get(), "bred_after", bredAfterColumn(state.population));
  if (!ok)
    fail("cannot write /population");
  if (!state.migrations.empty() && !writeColumn(f, "migrations", state.migrations))
    fail("cannot write /migrations");
  if (observer)
    observer("write");
  group.reset();
  if (file.reset() < 0)
    fail("cannot close HDF5 file");
}

// whether a path exists (errors read as absent)
bool exists(const std::string& path) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

}  // namespace

std::string checkpointPath(const std::string& dir) {
  return dir + "/checkpoint.h5";
}

std::string previousCheckpointPath(const std::string& dir) {
  return dir + "/checkpoint.prev.h5";
}

void writeCheckpoint(const std::string& dir, const CheckpointState& state,
                     const CheckpointStageObserver& observer) {
  std::string path = checkpointPath(dir);
  std::string temporary = path + ".tmp";
  std::string previous = previousCheckpointPath(dir);

  // the temporary file, complete and on disk (or gone: a full disk gets its space back)
  try {
    writeFile(temporary, state, observer);
    if (!syncPath(temporary, false))
      throw Error(ExitCode::output_file, temporary + ": fsync failed: " + std::strerror(errno));
  } catch (const Error&) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }

  // keep the current checkpoint as the previous one (a hard link: checkpoint.h5 stays put)
  if (exists(path)) {
    if (::unlink(previous.c_str()) != 0 && errno != ENOENT)
      throw Error(ExitCode::output_file, previous + ": cannot remove: " + std::strerror(errno));
    if (::link(path.c_str(), previous.c_str()) != 0) {
      std::error_code error;
      std::filesystem::copy_file(path, previous, error);
      if (error)
        throw Error(ExitCode::output_file,
                    previous + ": cannot keep the previous checkpoint: " + error.message());
    }
  }
  if (observer)
    observer("rename");

  // into place, then the directory entry on disk
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw Error(ExitCode::output_file,
                path + ": cannot rename " + temporary + " into place: " + std::strerror(errno));
  if (!syncPath(dir, true))
    throw Error(ExitCode::output_file, dir + ": fsync of the directory failed");
}

CheckpointState readCheckpoint(const std::string& path) {
  // libhdf5's faults on a damaged file end a child, not this process
  readInChildFirst(path, ExitCode::checkpoint, [&] { readCheckpointHere(path); });
  return readCheckpointHere(path);
}

CheckpointState readCheckpointHere(const std::string& path) {
  QuietErrors quiet;
  auto fail = [&](const std::string& what) {
    throw Error(ExitCode::checkpoint, path + ": " + what);
  };

  // missing, not HDF5, truncated or corrupt
  std::string problem;
  Handle file = openFile(path, "checkpoint", false, problem);
  if (!file.valid())
    fail(problem);
  hid_t f = file.get();

  // a cambrian checkpoint of a version we read
  std::int32_t version = 0;
  problem = checkFormat(f, "checkpoint", kCheckpointFormatName, kCheckpointFormatVersion, version);
  if (!problem.empty())
    fail(problem);

  // the scalar state
  CheckpointState state;
  std::uint64_t generation = 0, hash = 0;
  std::int32_t ranks = 0;
  bool ok = readString(f, "config_text", state.config_text) && readScalar(f, "seed", state.seed) &&
            readScalar(f, "generation", generation) &&
            readScalar(f, "next_generation", state.next_generation) &&
            readScalar(f, "next_id", state.next_id) && readScalar(f, "digest", state.digest) &&
            readScalar(f, "rank_count", ranks) && readScalar(f, "state_hash", hash);
  if (!ok)
    fail("a root attribute is missing or of the wrong type (corrupt checkpoint)");
  // who wrote it (for the resume warning; not part of the state)
  readString(f, "cambrian_version", state.cambrian_version);
  readString(f, "git_hash", state.git_hash);
  state.rank_count = ranks;
  if (state.next_generation != generation + 1)
    fail("next_generation " + std::to_string(state.next_generation) +
         " does not follow generation " + std::to_string(generation) + " (corrupt checkpoint)");

  readString(f, "config_hash", state.config_hash);

  // islands: the migration state (in the state hash)
  if (H5Lexists(f, "migrations", H5P_DEFAULT) > 0 && !readColumn(f, "migrations", state.migrations))
    fail("dataset /migrations unreadable (corrupt checkpoint)");

  // the population, checked against the state hash (version 1: its own columns)
  Handle group(H5Gopen2(f, "population", H5P_DEFAULT), H5Gclose);
  if (!group.valid())
    fail("group /population missing (corrupt checkpoint)");
  auto read = [&](auto& columns, auto forEach, auto decode) {
    std::string bad_column;
    forEach(columns, [&](const char* name, auto& values) {
      if (bad_column.empty() && !readColumn(group.get(), name, values))
        bad_column = name;
    });
    if (!bad_column.empty())
      fail("dataset /population/" + bad_column + " missing or unreadable (corrupt checkpoint)");
    try {
      state.population = decode(columns, generation);
    } catch (const std::exception& e) {
      fail(std::string(e.what()) + " (corrupt checkpoint)");
    }
    // steady-state: each individual's bred_after, one per row
    if (H5Lexists(group.get(), "bred_after", H5P_DEFAULT) > 0) {
      std::vector<std::uint64_t> bred_after;
      if (!readColumn(group.get(), "bred_after", bred_after) ||
          bred_after.size() != state.population.individuals.size())
        fail(
            "dataset /population/bred_after unreadable or not one value per row (corrupt "
            "checkpoint)");
      state.steady_state = true;
      for (std::size_t k = 0; k < bred_after.size(); ++k)
        state.population.individuals[k].bred_after = bred_after[k];
    }
    if (stateHash(state, columns, forEach) != hash)
      fail("state_hash does not match the contents (corrupt checkpoint)");
  };
  if (version == 1) {
    ColumnsV1 columns;
    read(
        columns, [](auto& c, auto visit) { forEachColumnV1(c, visit); }, fromColumnsV1);
  } else {
    Columns columns;
    read(
        columns, [](auto& c, auto visit) { forEachColumn(c, visit); }, fromColumns);
  }
  // (a steady state's creatures in flight are not evaluated yet)
  if ((!state.steady_state && !state.population.allEvaluated()) ||
      state.population.individuals.empty())
    fail("the population of generation " + std::to_string(generation) +
         " is empty or not fully evaluated (corrupt checkpoint)");
  return state;
}

std::optional<CheckpointState> findCheckpoint(const std::string& dir,
                                              const HistoryAttributes* this_run) {
  std::string path = checkpointPath(dir);
  std::string previous = previousCheckpointPath(dir);
  const std::string fresh = "; `cambrian evolve --fresh` starts over (overwriting " + dir + ")";

  // what the previous checkpoint offers, for the messages
  auto previousStatus = [&]() -> std::string {
    if (!exists(previous))
      return "";
    try {
      CheckpointState state = readCheckpoint(previous);
      return "; " + previous + " is good (continues from generation " +
             std::to_string(state.next_generation) + "): rename it to " + path +
             " to continue from there";
    } catch (const Error& e) {
      return "; " + previous + " is unusable too (" + e.what() + ")";
    }
  };

  // the current checkpoint, when there is one
  if (exists(path)) {
    try {
      return readCheckpoint(path);
    } catch (const Error& e) {
      throw Error(ExitCode::checkpoint, std::string(e.what()) + previousStatus() + fresh);
    }
  }

  // none: expected when a previous one exists or the history records one
  if (exists(previous))
    throw Error(ExitCode::checkpoint, path + ": missing, but " + previous +
                                          " exists (the run wrote checkpoints)" + previousStatus() +
                                          fresh);
  // no checkpoint at all: a history is only replaced when it holds no complete generation
  std::string history = dir + "/history.h5";
  if (exists(history)) {
    std::vector<GenerationRecord> generations;
    HistoryAttributes stored;
    try {
      HistoryReader reader(history);
      generations = reader.generations();
      stored = reader.attributes();
    } catch (const Error& e) {
      // this run's own history, killed inside its first writes: started again
      const SmallFile marker = readSmallFile(historyStartingPath(dir), 4096);
      if (this_run && marker.problem.empty() &&
          marker.bytes == this_run->config_hash + " " + std::to_string(this_run->seed) + "\n")
        return std::nullopt;
      throw Error(ExitCode::checkpoint,
                  std::string(e.what()) + "; there is no " + path +
                      " to continue from, and the history is not one this run could replace "
                      "safely: nothing was changed" +
                      fresh);
    }
    bool recorded = false;
    for (const GenerationRecord& g : generations)
      recorded = recorded || g.checkpoint_seconds > 0;
    if (recorded)
      throw Error(ExitCode::checkpoint, path + ": missing, but " + history +
                                            " records that checkpoints were written" + fresh);
    // killed before its first checkpoint: generation 0 of this very run, written again
    bool this_runs_first = this_run && generations.size() == 1 && generations[0].generation == 0 &&
                           stored.config_hash == this_run->config_hash &&
                           stored.seed == this_run->seed;
    if (!generations.empty() && !this_runs_first)
      throw Error(ExitCode::checkpoint,
                  history + ": holds " + std::to_string(generations.size()) +
                      " generation(s) but there is no " + path +
                      " to continue from (the run stopped before its first checkpoint was "
                      "written): nothing was changed" +
                      fresh);
  }
  return std::nullopt;
}

std::string historyStartingPath(const std::string& dir) {
  return dir + "/history.h5.starting";
}

void markHistoryStarting(const std::string& dir, const HistoryAttributes& run) {
  const std::string path = historyStartingPath(dir);
  std::ofstream out(path, std::ios::trunc);
  out << run.config_hash << " " << run.seed << "\n";
  out.close();
  if (!out)
    throw Error(ExitCode::output_file, path + ": cannot write");
}

void clearHistoryStarting(const std::string& dir) {
  std::error_code error;
  std::filesystem::remove(historyStartingPath(dir), error);
}

void removeCheckpoints(const std::string& dir) {
  for (const std::string& path :
       {checkpointPath(dir), previousCheckpointPath(dir), checkpointPath(dir) + ".tmp"}) {
    std::error_code error;
    std::filesystem::remove(path, error);
    if (error)
      throw Error(ExitCode::output_file, path + ": cannot remove: " + error.message());
  }
}

}  // namespace cambrian
