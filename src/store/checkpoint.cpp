#include "store/checkpoint.hpp"

#include "cambrian/error.hpp"
#include "cambrian/genome.hpp"
#include "cambrian/version.hpp"

#include "store/hdf5_io.hpp"
#include "store/history.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <set>
#include <sstream>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace cambrian {

// the store module's HDF5 helpers
using namespace hdf5;

namespace {

// the columns of /population, as flat vectors
struct Columns {
  std::vector<std::uint64_t> id, generation, parent_a, parent_b, steps, genome_offset, genome_size,
      message_offset, message_size, measure_count;
  std::vector<std::uint8_t> origin, evaluated, status, genome_bytes, message_bytes, measure_names;
  std::vector<double> fitness, outcome_wall_seconds, eval_seconds, measure_values;
  std::vector<std::int32_t> parts, joints, neurons, worker_rank;
};

// calls visit(name, column) for every column, in the fixed order the state hash uses
template <class C, class Visit>
void forEachColumn(C& c, Visit visit) {
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

// FNV-1a 64 over raw bytes, continued from `hash`
std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

// the hash of the scalar state and every column (detects corruption the HDF5 layer misses)
std::uint64_t stateHash(const CheckpointState& s, const Columns& columns) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  hash = fnv1a(hash, s.config_text.data(), s.config_text.size());
  for (std::uint64_t v :
       {s.seed, s.next_generation, s.next_id, s.digest, s.population.generation}) {
    hash = fnv1a(hash, &v, sizeof v);
  }
  forEachColumn(columns, [&](const char*, const auto& values) {
    std::uint64_t n = values.size();
    hash = fnv1a(hash, &n, sizeof n);
    hash = fnv1a(hash, values.data(), values.size() * sizeof(values[0]));
  });
  return hash;
}

// appends text and returns (offset, size) in the stream
void appendBytes(std::vector<std::uint8_t>& stream, const void* data, std::size_t size,
                 std::vector<std::uint64_t>& offsets, std::vector<std::uint64_t>& sizes) {
  offsets.push_back(stream.size());
  sizes.push_back(size);
  const auto* p = static_cast<const std::uint8_t*>(data);
  stream.insert(stream.end(), p, p + size);
}

// the population as columns
Columns toColumns(const Population& population) {
  Columns c;
  for (const Individual& i : population.individuals) {
    c.id.push_back(i.id);
    c.generation.push_back(i.generation);
    c.parent_a.push_back(i.parents.size() > 0 ? i.parents[0] : kNoId);
    c.parent_b.push_back(i.parents.size() > 1 ? i.parents[1] : kNoId);
    c.origin.push_back(static_cast<std::uint8_t>(i.origin));
    c.evaluated.push_back(i.evaluated ? 1 : 0);
    const Outcome& o = i.outcome;
    c.fitness.push_back(o.fitness);
    c.status.push_back(static_cast<std::uint8_t>(o.status));
    c.steps.push_back(o.steps);
    c.outcome_wall_seconds.push_back(o.wall_seconds);
    c.parts.push_back(o.parts);
    c.joints.push_back(o.joints);
    c.neurons.push_back(o.neurons);
    c.eval_seconds.push_back(i.eval_seconds);
    c.worker_rank.push_back(i.worker_rank);
    const std::vector<std::uint8_t>& genome = i.genomeBytes();
    appendBytes(c.genome_bytes, genome.data(), genome.size(), c.genome_offset, c.genome_size);
    appendBytes(c.message_bytes, o.message.data(), o.message.size(), c.message_offset,
                c.message_size);
    // measures: names '\0'-terminated in one stream, values in another
    c.measure_count.push_back(o.measures.size());
    for (const Measure& m : o.measures) {
      c.measure_names.insert(c.measure_names.end(), m.name.begin(), m.name.end());
      c.measure_names.push_back(0);
      c.measure_values.push_back(m.value);
    }
  }
  return c;
}

// the population from columns; throws std::runtime_error describing an inconsistency
Population fromColumns(const Columns& c, std::uint64_t generation) {
  Population population;
  population.generation = generation;
  std::size_t n = c.id.size();
  bool same_length = true;
  forEachColumn(c, [&](const char* name, const auto& values) {
    std::string column = name;
    if (column != "genome_bytes" && column != "message_bytes" && column != "measure_names" &&
        column != "measure_values" && values.size() != n)
      same_length = false;
  });
  if (!same_length)
    throw std::runtime_error("/population columns differ in length");
  std::size_t next_name = 0, next_value = 0;
  for (std::size_t k = 0; k < n; ++k) {
    Individual i;
    i.id = c.id[k];
    i.generation = c.generation[k];
    if (c.parent_a[k] != kNoId)
      i.parents.push_back(c.parent_a[k]);
    if (c.parent_b[k] != kNoId)
      i.parents.push_back(c.parent_b[k]);
    if (c.origin[k] > static_cast<std::uint8_t>(Origin::graft) ||
        c.status[k] > static_cast<std::uint8_t>(EvalStatus::failed))
      throw std::runtime_error("/population row " + std::to_string(k) +
                               ": origin or status out of range");
    i.origin = static_cast<Origin>(c.origin[k]);
    i.evaluated = c.evaluated[k] != 0;
    i.outcome.fitness = c.fitness[k];
    i.outcome.status = static_cast<EvalStatus>(c.status[k]);
    i.outcome.steps = c.steps[k];
    i.outcome.wall_seconds = c.outcome_wall_seconds[k];
    i.outcome.parts = c.parts[k];
    i.outcome.joints = c.joints[k];
    i.outcome.neurons = c.neurons[k];
    i.eval_seconds = c.eval_seconds[k];
    i.worker_rank = c.worker_rank[k];
    // genome and message from their streams
    if (c.genome_offset[k] > c.genome_bytes.size() ||
        c.genome_size[k] > c.genome_bytes.size() - c.genome_offset[k] ||
        c.message_offset[k] > c.message_bytes.size() ||
        c.message_size[k] > c.message_bytes.size() - c.message_offset[k])
      throw std::runtime_error("/population row " + std::to_string(k) +
                               ": offset past the end of its byte stream");
    i.genome = deserializeGenome(c.genome_bytes.data() + c.genome_offset[k], c.genome_size[k]);
    i.outcome.message.assign(c.message_bytes.begin() + c.message_offset[k],
                             c.message_bytes.begin() + c.message_offset[k] + c.message_size[k]);
    // measures
    for (std::uint64_t m = 0; m < c.measure_count[k]; ++m) {
      Measure measure;
      while (next_name < c.measure_names.size() && c.measure_names[next_name] != 0)
        measure.name += static_cast<char>(c.measure_names[next_name++]);
      if (next_name >= c.measure_names.size() || next_value >= c.measure_values.size())
        throw std::runtime_error("/population row " + std::to_string(k) + ": measures truncated");
      ++next_name;
      measure.value = c.measure_values[next_value++];
      i.outcome.measures.push_back(std::move(measure));
    }
    population.individuals.push_back(std::move(i));
  }
  return population;
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
    throw Error(ExitCode::output_file, path + ": " + what);
  };
  Handle file = createFile(path, H5F_LIBVER_V110);
  if (!file.valid())
    fail("cannot create HDF5 file");
  Columns columns = toColumns(state.population);

  // the root attributes: format, provenance, counters, state hash
  hid_t f = file.get();
  bool ok = writeFormat(f, kCheckpointFormatName, kCheckpointFormatVersion, kVersion, kGitHash) &&
            writeString(f, "config_text", state.config_text) &&
            writeString(f, "config_hash", resultConfigHash(state.config_text)) &&
            writeScalar<std::uint64_t>(f, "seed", state.seed) &&
            writeScalar<std::uint64_t>(f, "generation", state.population.generation) &&
            writeScalar<std::uint64_t>(f, "next_generation", state.next_generation) &&
            writeScalar<std::uint64_t>(f, "next_id", state.next_id) &&
            writeScalar<std::uint64_t>(f, "digest", state.digest) &&
            writeScalar<std::int32_t>(f, "rank_count", state.rank_count) &&
            writeString(f, "written_time", utcTimestamp()) &&
            writeScalar<std::uint64_t>(f, "state_hash", stateHash(state, columns));
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
  if (!ok)
    fail("cannot write /population");
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

  // the temporary file, complete and on disk
  writeFile(temporary, state, observer);
  if (!syncPath(temporary, false))
    throw Error(ExitCode::output_file,
                temporary + ": fsync failed: " + std::strerror(errno) + " (disk full?)");

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

  // the population, checked against the state hash
  Handle group(H5Gopen2(f, "population", H5P_DEFAULT), H5Gclose);
  if (!group.valid())
    fail("group /population missing (corrupt checkpoint)");
  Columns columns;
  std::string bad_column;
  forEachColumn(columns, [&](const char* name, auto& values) {
    if (bad_column.empty() && !readColumn(group.get(), name, values))
      bad_column = name;
  });
  if (!bad_column.empty())
    fail("dataset /population/" + bad_column + " missing or unreadable (corrupt checkpoint)");
  try {
    state.population = fromColumns(columns, generation);
  } catch (const std::exception& e) {
    fail(std::string(e.what()) + " (corrupt checkpoint)");
  }
  if (stateHash(state, columns) != hash)
    fail("state_hash does not match the contents (corrupt checkpoint)");
  if (!state.population.allEvaluated() || state.population.individuals.empty())
    fail("the population of generation " + std::to_string(generation) +
         " is empty or not fully evaluated (corrupt checkpoint)");
  return state;
}

std::optional<CheckpointState> findCheckpoint(const std::string& dir) {
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
    std::vector<HistoryGeneration> generations;
    try {
      generations = HistoryReader(history).generations();
    } catch (const Error& e) {
      throw Error(ExitCode::checkpoint,
                  std::string(e.what()) + "; there is no " + path +
                      " to continue from, and the history is not one this run could replace "
                      "safely: nothing was changed" +
                      fresh);
    }
    bool recorded = false;
    for (const HistoryGeneration& g : generations)
      recorded = recorded || g.checkpoint_seconds > 0;
    if (recorded)
      throw Error(ExitCode::checkpoint, path + ": missing, but " + history +
                                            " records that checkpoints were written" + fresh);
    if (!generations.empty())
      throw Error(ExitCode::checkpoint,
                  history + ": holds " + std::to_string(generations.size()) +
                      " generation(s) but there is no " + path +
                      " to continue from (the run stopped before its first checkpoint was "
                      "written): nothing was changed" +
                      fresh);
  }
  return std::nullopt;
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

bool isRunOnlySetting(const std::string& key) {
  static const std::set<std::string> run_only = {
      "evolution.generations",
      "run.out",
      "run.quiet",
      "run.verbose",
      "run.max_hours",
      "run.checkpoint_every",
      "run.checkpoint_minutes",
      "run.test_kill_at",
      "run.test_worker_abort_at",
      "run.dispatch_order",
      "run.dispatch_seed",
  };
  return run_only.count(key) > 0;
}

std::map<std::string, std::string> settingsOfConfigText(const std::string& config_text) {
  std::map<std::string, std::string> settings;
  std::istringstream lines(config_text);
  std::string line, section;
  while (std::getline(lines, line)) {
    // [section] headers, then key = value lines
    if (!line.empty() && line.front() == '[' && line.back() == ']') {
      section = line.substr(1, line.size() - 2);
      continue;
    }
    std::size_t equals = line.find(" = ");
    if (equals == std::string::npos)
      continue;
    settings[section + "." + line.substr(0, equals)] = line.substr(equals + 3);
  }
  return settings;
}

std::string resultConfigText(const std::string& config_text) {
  // the lines of the text minus run-only keys (sections kept in order)
  std::istringstream lines(config_text);
  std::string line, section, text;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.front() == '[' && line.back() == ']')
      section = line.substr(1, line.size() - 2);
    std::size_t equals = line.find(" = ");
    if (equals != std::string::npos && isRunOnlySetting(section + "." + line.substr(0, equals)))
      continue;
    text += line + "\n";
  }
  return text;
}

std::string resultConfigHash(const std::string& config_text) {
  return configHash(resultConfigText(config_text));
}

void checkResumeSettings(const std::string& path, const std::string& saved_config_text,
                         const std::string& current_config_text,
                         const std::string& default_config_text) {
  std::map<std::string, std::string> saved = settingsOfConfigText(saved_config_text);
  std::map<std::string, std::string> current = settingsOfConfigText(current_config_text);
  std::map<std::string, std::string> defaults = settingsOfConfigText(default_config_text);

  // every key of either side, in order
  std::set<std::string> keys;
  for (const auto& [key, value] : saved)
    keys.insert(key);
  for (const auto& [key, value] : current)
    keys.insert(key);
  for (const std::string& key : keys) {
    if (isRunOnlySetting(key))
      continue;
    auto old_value = saved.find(key);
    auto new_value = current.find(key);
    // a key added since the checkpoint, left at its default: the old behaviour
    auto default_value = defaults.find(key);
    if (old_value == saved.end() && new_value != current.end() && default_value != defaults.end() &&
        default_value->second == new_value->second)
      continue;
    std::string before = old_value == saved.end() ? "(absent)" : "'" + old_value->second + "'";
    std::string after = new_value == current.end() ? "(absent)" : "'" + new_value->second + "'";
    if (before != after) {
      throw Error(ExitCode::checkpoint,
                  path + ": setting " + key + " was " + before +
                      " when the checkpoint was written and is " + after +
                      " now; it changes results, so the run cannot continue with it (restore the "
                      "old value, or start over with --fresh)");
    }
  }
}

}  // namespace cambrian
