#include "store/history.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "core/hash.hpp"
#include "store/hdf5_io.hpp"
#include "store/held_file.hpp"
#include "store/read_in_child.hpp"

#include <hdf5.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <limits>
#include <sstream>
#include <thread>
#include <type_traits>
#include <unistd.h>
#include <unordered_map>
#include <utility>

namespace cambrian {

// the store module's HDF5 helpers
using namespace hdf5;

namespace {

// rows per chunk of the per-row datasets; bytes per chunk of the genome byte stream
constexpr hsize_t kRowChunk = 1024;
// the most genome bytes gathered for one write of the byte stream
constexpr std::size_t kGenomeBytesPerWrite = 8 << 20;
// rows per chunk of /generations (one row per append: small, so little is deflated again)
constexpr hsize_t kGenerationChunk = 64;
constexpr hsize_t kByteChunk = 65536;
constexpr int kDeflateLevel = 4;
constexpr int kGenomeDeflateLevel = 0;

// a column of a table group: name, stored type, width (1, or the measure count), unit, meaning
struct Column {
  const char* name;
  hid_t (*type)();
  hsize_t width;
  const char* units;
  const char* description;
  bool added_later = false;  ///< may be missing from files of the same format version: reads as 0
};

// the per-individual columns (genome_bytes is a separate byte stream)
const std::vector<Column>& individualColumns() {
  static const std::vector<Column> columns = {
      {"generation", nativeType<std::uint64_t>, 1, "1", "generation the row belongs to"},
      {"id", nativeType<std::uint64_t>, 1, "1", "individual id, unique in the run"},
      {"parent_a", nativeType<std::uint64_t>, 1, "1",
       "first parent id; 18446744073709551615 (UINT64_MAX) when absent"},
      {"parent_b", nativeType<std::uint64_t>, 1, "1",
       "second parent id; 18446744073709551615 (UINT64_MAX) when absent"},
      {"operator", nativeType<std::uint8_t>, 1, "1",
       "what made the individual; index into the names attribute"},
      {"fitness", nativeType<double>, 1, "task", "fitness (task units; failures get 0)"},
      {"status", nativeType<std::uint8_t>, 1, "1",
       "how the evaluation ended; index into the names attribute"},
      {"measures", nativeType<double>, 0, "see units attribute",
       "the task's measures, one column per name in the names attribute; NaN when absent"},
      {"parts", nativeType<std::int32_t>, 1, "1", "body parts of the developed creature"},
      {"joints", nativeType<std::int32_t>, 1, "1", "joints of the developed creature"},
      {"neurons", nativeType<std::int32_t>, 1, "1", "neurons of the developed creature"},
      {"steps", nativeType<std::uint64_t>, 1, "1", "physics steps simulated"},
      {"eval_seconds", nativeType<double>, 1, "s",
       "evaluation wall time (0 for elites copied unevaluated)"},
      {"worker_rank", nativeType<std::int32_t>, 1, "1",
       "MPI rank that evaluated it; -1 for copies, 0 for in-process runs"},
      {"genome_offset", nativeType<std::uint64_t>, 1, "byte",
       "offset of the genome in genome_bytes"},
      {"genome_size", nativeType<std::uint64_t>, 1, "byte", "length of the genome in genome_bytes"},
      {"bred_after", nativeType<std::uint64_t>, 1, "1",
       "steady-state runs: results taken in before the individual was bred (rows are in the "
       "order results were taken in); 0 in generational runs",
       true},
  };
  return columns;
}

// the per-generation columns
const std::vector<Column>& generationColumns() {
  auto u64 = nativeType<std::uint64_t>;
  auto f64 = nativeType<double>;
  static const std::vector<Column> columns = {
      {"generation", u64, 1, "1", "generation number, from 0"},
      {"count", u64, 1, "1", "individuals in the generation"},
      {"failed", u64, 1, "1", "individuals whose status is not ok"},
      {"best", f64, 1, "task", "best fitness"},
      {"mean", f64, 1, "task", "mean fitness"},
      {"stddev", f64, 1, "task", "standard deviation of fitness"},
      {"worst", f64, 1, "task", "worst fitness"},
      {"q25", f64, 1, "task", "first quartile of fitness (linear interpolation)"},
      {"median", f64, 1, "task", "median fitness"},
      {"q75", f64, 1, "task", "third quartile of fitness"},
      {"best_id", u64, 1, "1", "id of the best individual (ties: lowest id)"},
      {"evaluations", u64, 1, "1", "individuals evaluated (elites are not)"},
      {"workers", nativeType<std::int32_t>, 1, "1", "evaluating ranks"},
      {"distinct_genomes", u64, 1, "1", "distinct genome byte strings (diversity)"},
      {"rank0_serial_seconds", f64, 1, "s", "rank 0 busy outside the evaluation span"},
      {"rank0_cpu_seconds", f64, 1, "s", "CPU time rank 0 used in the generation (getrusage)",
       true},
      {"rank0_dispatch_seconds", f64, 1, "s",
       "rank 0 handing out creatures and taking in results, waits left out", true},
      {"evaluation_span_seconds", f64, 1, "s", "first request sent to last result received"},
      {"worker_busy_seconds", f64, 1, "s", "sum of evaluation wall times"},
      {"worker_idle_seconds", f64, 1, "s", "workers * span - busy"},
      {"checkpoint_seconds", f64, 1, "s", "time writing the checkpoint (0: none written)"},
      {"wall_seconds", f64, 1, "s", "the whole generation on rank 0"},
      {"unix_time", f64, 1, "s since 1970-01-01T00:00:00Z", "wall clock when the row was written"},
      {"epoch", u64, 1, "1", "the epoch the generation was rated in (evolution.epochs), from 0",
       true},
      {"fitness_deviation", f64, 1, "1",
       "standard deviation of the fitnesses divided by the largest |fitness| (the wwd scheme's "
       "diversity)",
       true},
      {"mutation_multiplier", f64, 1, "1",
       "the next generation's mutation scaled by it (evolution.scheme = wwd; else 1; 0 in files "
       "written before it)",
       true},
  };
  return columns;
}

// names of the enum values 0..n-1
std::vector<std::string> originNames() {
  std::vector<std::string> names;
  for (int i = 0; i < kOriginKinds; ++i)
    names.push_back(originName(static_cast<Origin>(i)));
  return names;
}

std::vector<std::string> statusNames() {
  std::vector<std::string> names;
  for (int i = 0; i < kEvalStatusKinds; ++i)
    names.push_back(statusName(static_cast<EvalStatus>(i)));
  return names;
}

// an empty extendible chunked dataset of `width` columns (1: a 1-D dataset), shuffled and
// deflated at `deflate_level` (0: stored as is)
Handle createTable(hid_t group, const char* name, hid_t type, hsize_t width, hsize_t chunk,
                   int deflate_level, bool two_dimensional = false) {
  int rank = width == 1 && !two_dimensional ? 1 : 2;
  hsize_t dims[2] = {0, width};
  hsize_t max_dims[2] = {H5S_UNLIMITED, width};
  hsize_t chunk_dims[2] = {chunk, width};
  Handle space(H5Screate_simple(rank, dims, max_dims), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(properties.get(), rank, chunk_dims);
  if (deflate_level > 0) {
    H5Pset_shuffle(properties.get());
    H5Pset_deflate(properties.get(), static_cast<unsigned>(deflate_level));
  }
  return Handle(
      H5Dcreate2(group, name, type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
      H5Dclose);
}

// appends `rows` rows of `width` values to a dataset; false on failure
bool appendRows(hid_t dataset, hid_t memory_type, const void* data, hsize_t rows, hsize_t width) {
  Handle space(H5Dget_space(dataset), H5Sclose);
  hsize_t dims[2] = {0, width};
  int rank = H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (rank < 1)
    return false;
  hsize_t start = dims[0];
  dims[0] += rows;
  if (H5Dset_extent(dataset, dims) < 0)
    return false;
  return rows == 0 || writeRows(dataset, memory_type, data, start, rows, width);
}

// the values of one field of every row, as the column's type
template <class T, class Row, class Get>
std::vector<T> gather(const std::vector<Row>& rows, Get get) {
  std::vector<T> values;
  values.reserve(rows.size());
  for (const Row& row : rows)
    values.push_back(static_cast<T>(get(row)));
  return values;
}

// a whole dataset as T values (rows * width); false when missing or unreadable; width 0: any
// width, read into `width`
template <class T>
bool readTable(hid_t group, const char* name, hsize_t& width, std::vector<T>& values,
               hsize_t& rows) {
  std::vector<hsize_t> dims;
  Handle dataset = openDataset(group, name, 2, dims);
  if (!dataset.valid())
    return false;
  hsize_t found = dims.size() == 1 ? 1 : dims[1];
  if (width != 0 && found != width)
    return false;
  width = found;
  rows = dims[0];
  return readValues(dataset.get(), rows * width, values);
}

// the same for a one-column dataset
template <class T>
bool readColumn(hid_t group, const char* name, std::vector<T>& values, hsize_t& rows) {
  hsize_t width = 1;
  return readTable(group, name, width, values, rows);
}

// calls visit(name, field) for every field of a generation record, in column order
template <class G, class Visit>
void forEachGenerationField(G& g, Visit visit) {
  visit("generation", g.generation);
  visit("count", g.stats.count);
  visit("failed", g.stats.failed);
  visit("best", g.stats.best);
  visit("mean", g.stats.mean);
  visit("stddev", g.stats.stddev);
  visit("worst", g.stats.worst);
  visit("q25", g.stats.q25);
  visit("median", g.stats.median);
  visit("q75", g.stats.q75);
  visit("best_id", g.stats.best_id);
  visit("evaluations", g.evaluations);
  visit("workers", g.workers);
  visit("distinct_genomes", g.distinct_genomes);
  visit("rank0_serial_seconds", g.rank0_serial_seconds);
  visit("rank0_cpu_seconds", g.rank0_cpu_seconds);
  visit("rank0_dispatch_seconds", g.rank0_dispatch_seconds);
  visit("evaluation_span_seconds", g.evaluation_span_seconds);
  visit("worker_busy_seconds", g.worker_busy_seconds);
  visit("worker_idle_seconds", g.worker_idle_seconds);
  visit("checkpoint_seconds", g.checkpoint_seconds);
  visit("wall_seconds", g.wall_seconds);
  visit("unix_time", g.unix_time);
  visit("epoch", g.epoch);
  visit("fitness_deviation", g.fitness_deviation);
  visit("mutation_multiplier", g.mutation_multiplier);
}

double unixNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// the parent ids of a row: kNoId where absent
std::uint64_t parentAt(const Individual& individual, std::size_t k) {
  return individual.parents.size() > k ? individual.parents[k] : kNoId;
}

}  // namespace

std::string utcTimestamp() {
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// ---------------------------------------------------------------------------------------------
// writer

struct HistoryWriter::Impl {
  Handle file;                                          // open only while writing
  std::unordered_map<std::string, Handle> individuals;  // column name -> dataset
  std::unordered_map<std::string, Handle> generations;
  Handle genome_bytes;
  std::vector<std::string> measure_names;  // the measure columns, in order
  std::uint64_t genome_end = 0;            // bytes in genome_bytes so far
  std::vector<std::uint8_t> byte_buffer;   // genomes on their way to the file (kept: no
                                           // fresh megabytes to fault in every generation)

  // the datasets, then the file: afterwards the file on disk is closed and consistent
  bool closeFile() {
    individuals.clear();
    generations.clear();
    genome_bytes.reset();
    return file.reset() >= 0;
  }

  // `path` must still name the writer's file (`held`, a descriptor kept across the appends,
  // while HDF5 closes the file between generations). Deleted: the file is copied back from it
  // and the notice says so. Replaced by another file: it is saved as PATH.own, the other file
  // left alone, and Error(output_file) says so.
  void stayAtPath(const std::string& path, std::uint64_t generations_in) {
    if (held < 0)
      return;
    const PathState state = pathStateOf(held, path);
    if (state == PathState::same)
      return;
    const std::string what = state == PathState::missing ? "deleted" : "replaced by another file";
    if (file.valid() && !closeFile())
      throw Error(ExitCode::output_file, path + ": " + what +
                                             " while this run was writing it, and the open "
                                             "file cannot be closed");
    const std::string target = state == PathState::missing ? path : path + ".own";
    copyOpenFileTo(held, target);
    const std::string rows = "its " + std::to_string(generations_in) + " generation(s) so far";
    if (state == PathState::replaced)
      throw Error(ExitCode::output_file,
                  path +
                      ": replaced by another file while this run was writing it; the run's "
                      "own history (" +
                      rows + ") is saved as " + target +
                      " and the other file is left as it is: put the run's history back at " +
                      path);
    ::close(held);
    held = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    notice = path + ": deleted while this run was writing it; written back (" + rows +
             "), and the run goes on";
  }

  // the file at `path` opened for writing, written back first where it was deleted; looked at
  // again where the opening fails (deleted between the look and the opening: the writer runs
  // beside the evaluations, so anyone may remove the file at any moment)
  bool openAtPath(const std::string& path) {
    stayAtPath(path, generations_written);
    if (openFile(path))
      return true;
    stayAtPath(path, generations_written);
    return openFile(path);
  }

  int held = -1;  // the file, kept open across generations to notice and undo a deletion
  ~Impl() {
    if (held >= 0)
      ::close(held);
  }

  std::string notice;                     // what the last append repaired, for the run
  std::uint64_t generations_written = 0;  // generation rows in the file

  // reopens the file for SWMR writing and its datasets; false when any of it fails
  bool openFile(const std::string& path) {
    if (file.valid())
      return true;
    // no HDF5 file lock, so a reader holding the file open (HDFView, h5dump) never stops the
    // run: the run's own lock (run.lock) keeps other writers out
    file = openFileForSwmrWriting(path);
    if (!file.valid())
      return false;
    if (held < 0)
      held = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    auto openAll = [&](const char* group, const std::vector<Column>& columns,
                       std::unordered_map<std::string, Handle>& datasets) {
      for (const Column& column : columns) {
        std::string name = std::string("/") + group + "/" + column.name;
        Handle dataset(H5Dopen2(file.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
        if (!dataset.valid())
          return false;
        datasets.emplace(column.name, std::move(dataset));
      }
      return true;
    };
    genome_bytes = Handle(H5Dopen2(file.get(), "/individuals/genome_bytes", H5P_DEFAULT), H5Dclose);
    if (genome_bytes.valid() && openAll("individuals", individualColumns(), individuals) &&
        openAll("generations", generationColumns(), generations))
      return true;
    closeFile();
    return false;
  }
};

std::uint64_t historyChunkRows(std::uint64_t population) {
  if (population == 0)
    return kRowChunk;
  return population * ((64 + population - 1) / population);
}

HistoryWriter::HistoryWriter(const std::string& path, HistoryAttributes attributes,
                             const std::vector<MeasureInfo>& measures,
                             std::uint64_t individual_rows_per_chunk)
    : path_(path), impl_(std::make_unique<Impl>()) {
  QuietErrors quiet;
  auto fail = [&](const std::string& what) {
    std::string reason = systemReason();
    impl_.reset();
    throw Error(ExitCode::output_file, path_ + ": " + what + (reason.empty() ? "" : ": " + reason));
  };
  if (measures.empty())
    throw Error(ExitCode::failure, path_ + ": a history needs at least one measure column");
  for (const MeasureInfo& measure : measures)
    impl_->measure_names.push_back(measure.name);

  // the file, newest format (SWMR needs it)
  impl_->file = createFile(path_, H5F_LIBVER_LATEST);
  if (!impl_->file.valid())
    fail("cannot create HDF5 file");
  impl_->held = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  hid_t file = impl_->file.get();

  // provenance on the root group
  if (attributes.config_hash.empty())
    attributes.config_hash = hashText(attributes.config_text);
  if (attributes.start_time.empty())
    attributes.start_time = utcTimestamp();
  if (attributes.cambrian_version.empty())
    attributes.cambrian_version = kVersion;
  if (attributes.git_hash.empty())
    attributes.git_hash = kGitHash;
  bool ok = writeFormat(file, kHistoryFormatName, kHistoryFormatVersion,
                        attributes.cambrian_version, attributes.git_hash) &&
            writeString(file, "config_text", attributes.config_text) &&
            writeString(file, "config_hash", attributes.config_hash) &&
            writeStrings(file, "run_only_settings", attributes.run_only_settings) &&
            writeScalar<std::uint64_t>(file, "seed", attributes.seed) &&
            writeString(file, "bullet_precision", attributes.bullet_precision) &&
            writeString(file, "start_time", attributes.start_time) &&
            writeScalar<std::int32_t>(file, "rank_count", attributes.rank_count);
  if (!ok)
    fail("cannot write the root attributes");

  // one group per table, one dataset per column, with units and descriptions
  const hsize_t measure_count = measures.size();
  auto makeGroup = [&](const char* name, const std::vector<Column>& columns,
                       std::unordered_map<std::string, Handle>& datasets, hsize_t chunk,
                       const char* about) {
    Handle group(H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!group.valid() || !writeString(group.get(), "description", about))
      fail(std::string("cannot create group /") + name);
    for (const Column& column : columns) {
      bool matrix = column.width == 0;
      Handle dataset =
          createTable(group.get(), column.name, column.type(),
                      matrix ? measure_count : column.width, chunk, kDeflateLevel, matrix);
      if (!dataset.valid() || !describe(dataset.get(), column.units, column.description))
        fail(std::string("cannot create dataset /") + name + "/" + column.name);
      datasets.emplace(column.name, std::move(dataset));
    }
    return group;
  };
  hsize_t individual_chunk = individual_rows_per_chunk > 0 ? individual_rows_per_chunk : kRowChunk;
  Handle individuals = makeGroup("individuals", individualColumns(), impl_->individuals,
                                 individual_chunk, "one row per evaluated (or copied) individual");
  Handle generations = makeGroup("generations", generationColumns(), impl_->generations,
                                 kGenerationChunk, "one row per generation");

  // enum names and measure names / units
  std::vector<std::string> measure_units;
  for (const MeasureInfo& measure : measures)
    measure_units.push_back(measure.unit);
  hid_t measure_set = impl_->individuals.at("measures").get();
  H5Adelete(measure_set, "units");
  if (!writeStrings(impl_->individuals.at("operator").get(), "names", originNames()) ||
      !writeStrings(impl_->individuals.at("status").get(), "names", statusNames()) ||
      !writeStrings(measure_set, "names", impl_->measure_names) ||
      !writeStrings(measure_set, "units", measure_units))
    fail("cannot write the names attributes of /individuals");

  // the genome byte stream
  impl_->genome_bytes = createTable(individuals.get(), "genome_bytes", H5T_NATIVE_UINT8, 1,
                                    kByteChunk, kGenomeDeflateLevel);
  if (!impl_->genome_bytes.valid() ||
      !describe(impl_->genome_bytes.get(), "byte",
                "genomes in their byte form (encoding tag, version, fields), concatenated; row i "
                "is genome_bytes[genome_offset[i] : genome_offset[i] + genome_size[i]]"))
    fail("cannot create dataset /individuals/genome_bytes");

  // closed until the first append: between appends any HDF5 tool can open the file
  if (!impl_->closeFile())
    fail("cannot close HDF5 file");
}

HistoryWriter::~HistoryWriter() {
  try {
    close();
  } catch (...) {
    // destructor: the caller did not ask for errors
  }
}

void HistoryWriter::appendGeneration(const std::vector<Individual>& rows,
                                     GenerationRecord generation) {
  if (!impl_)
    throw Error(ExitCode::output_file, path_ + ": history file is closed");
  Impl& m = *impl_;

  // the measures by name into their columns (NaN where absent), before anything is written
  const std::size_t width = m.measure_names.size();
  std::vector<double> measures(rows.size() * width, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (const Measure& measure : rows[r].outcome.measures) {
      auto column = std::find(m.measure_names.begin(), m.measure_names.end(), measure.name);
      if (column == m.measure_names.end())
        throw Error(ExitCode::failure, path_ + ": individual " + std::to_string(rows[r].id) +
                                           " has the measure '" + measure.name +
                                           "', which the run's task does not declare");
      measures[r * width + static_cast<std::size_t>(column - m.measure_names.begin())] =
          measure.value;
    }
  }

  QuietErrors quiet;
  if (!m.openAtPath(path_))
    throw Error(ExitCode::output_file, path_ + ": cannot open the history file to append to it");
  bool ok = true;
  auto append = [&](std::unordered_map<std::string, Handle>& datasets, const char* name,
                    const auto& values, hsize_t columns) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    if (ok)
      ok = appendRows(datasets.at(name).get(), nativeType<T>(), values.data(),
                      values.size() / columns, columns);
  };
  using u64 = std::uint64_t;
  using i32 = std::int32_t;
  using u8 = std::uint8_t;
  using R = Individual;

  // genome bytes first (rows never point past the stream), a few megabytes at a time: a
  // generation's genomes are never held twice
  std::vector<u8>& bytes = m.byte_buffer;
  std::vector<u64> offsets, sizes;
  auto flushBytes = [&] {
    if (ok && !bytes.empty())
      ok = appendRows(m.genome_bytes.get(), H5T_NATIVE_UINT8, bytes.data(), bytes.size(), 1);
    if (ok)
      m.genome_end += bytes.size();
    bytes.clear();
  };
  bytes.reserve(kGenomeBytesPerWrite);
  for (const R& row : rows) {
    const std::vector<u8>& genome = row.genomeBytes();
    if (bytes.size() + genome.size() > kGenomeBytesPerWrite)
      flushBytes();
    offsets.push_back(m.genome_end + bytes.size());
    sizes.push_back(genome.size());
    bytes.insert(bytes.end(), genome.begin(), genome.end());
  }
  flushBytes();

  // the individual columns
  auto& d = m.individuals;
  append(d, "generation", gather<u64>(rows, [](const R& r) { return r.generation; }), 1);
  append(d, "id", gather<u64>(rows, [](const R& r) { return r.id; }), 1);
  append(d, "parent_a", gather<u64>(rows, [](const R& r) { return parentAt(r, 0); }), 1);
  append(d, "parent_b", gather<u64>(rows, [](const R& r) { return parentAt(r, 1); }), 1);
  append(d, "operator", gather<u8>(rows, [](const R& r) { return r.origin; }), 1);
  append(d, "fitness", gather<double>(rows, [](const R& r) { return r.fitness(); }), 1);
  append(d, "status", gather<u8>(rows, [](const R& r) { return r.outcome.status; }), 1);
  append(d, "measures", measures, width);
  append(d, "parts", gather<i32>(rows, [](const R& r) { return r.outcome.parts; }), 1);
  append(d, "joints", gather<i32>(rows, [](const R& r) { return r.outcome.joints; }), 1);
  append(d, "neurons", gather<i32>(rows, [](const R& r) { return r.outcome.neurons; }), 1);
  append(d, "steps", gather<u64>(rows, [](const R& r) { return r.outcome.steps; }), 1);
  append(d, "eval_seconds", gather<double>(rows, [](const R& r) { return r.eval_seconds; }), 1);
  append(d, "worker_rank", gather<i32>(rows, [](const R& r) { return r.worker_rank; }), 1);
  append(d, "genome_offset", offsets, 1);
  append(d, "genome_size", sizes, 1);
  append(d, "bred_after", gather<u64>(rows, [](const R& r) { return r.bred_after; }), 1);

  // the generation row
  if (generation.unix_time == 0)
    generation.unix_time = unixNow();
  const GenerationRecord& g = generation;
  auto& e = m.generations;
  forEachGenerationField(g, [&](const char* name, auto value) {
    append(e, name, std::vector<decltype(value)>{value}, 1);
  });

  // durable before the next generation starts
  if (ok && H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL) >= 0) {
    ++m.generations_written;
  } else {
    std::string reason = systemReason();
    throw Error(ExitCode::output_file, path_ + ": cannot append generation " +
                                           std::to_string(g.generation) +
                                           (reason.empty() ? "" : ": " + reason));
  }
}

std::string HistoryWriter::takeNotice() {
  if (!impl_)
    return "";
  return std::exchange(impl_->notice, std::string());
}

void HistoryWriter::completeLastGeneration(const GenerationRecord& record) {
  if (!impl_)
    throw Error(ExitCode::output_file, path_ + ": history file is closed");
  QuietErrors quiet;
  if (!impl_->openAtPath(path_))
    throw Error(ExitCode::output_file, path_ + ": cannot open the history file to complete it");

  // the last row of each column, rewritten in place (SWMR allows changing existing data)
  hid_t any = impl_->generations.at("wall_seconds").get();
  Handle space(H5Dget_space(any), H5Sclose);
  hsize_t rows = 0;
  if (H5Sget_simple_extent_dims(space.get(), &rows, nullptr) != 1 || rows == 0) {
    impl_->closeFile();
    return;
  }
  hsize_t offset = rows - 1;
  const std::pair<const char*, double> cells[] = {
      {"rank0_serial_seconds", record.rank0_serial_seconds},
      {"rank0_cpu_seconds", record.rank0_cpu_seconds},
      {"checkpoint_seconds", record.checkpoint_seconds},
      {"wall_seconds", record.wall_seconds}};
  for (const auto& [column, value] : cells) {
    if (!writeRows(impl_->generations.at(column).get(), H5T_NATIVE_DOUBLE, &value, offset, 1, 1))
      throw Error(ExitCode::output_file,
                  path_ + ": cannot write " + column + " of row " + std::to_string(offset));
  }
  // the generation is complete: the file is closed until the next append
  if (!impl_->closeFile())
    throw Error(ExitCode::output_file,
                path_ + ": cannot close after row " + std::to_string(offset));
}

void HistoryWriter::renameTo(const std::string& path) {
  std::error_code error;
  std::filesystem::rename(path_, path, error);
  if (error)
    throw Error(ExitCode::output_file,
                path + ": cannot rename " + path_ + " into place: " + error.message());
  path_ = path;
}

std::unique_ptr<HistoryWriter> resumeHistory(const std::string& path, std::uint64_t generations,
                                             HistoryAttributes attributes,
                                             const std::vector<MeasureInfo>& measures,
                                             HistoryRows& kept,
                                             std::uint64_t individual_rows_per_chunk,
                                             std::optional<std::uint64_t> run_digest) {
  // the old rows (a crashed writer's file opens for SWMR reading)
  kept = HistoryRows{};
  std::vector<Individual> individuals;
  std::vector<GenerationRecord> rows;
  HistoryAttributes stored;
  {
    HistoryReader reader(path);
    individuals = reader.individuals();
    rows = reader.generations();
    stored = reader.attributes();
    if (attributes.start_time.empty())
      attributes.start_time = stored.start_time;
  }
  if (rows.size() < generations)
    throw InputError(path + ": holds " + std::to_string(rows.size()) +
                     " generation rows, the checkpoint continues from generation " +
                     std::to_string(generations));
  for (std::uint64_t g = 0; g < generations; ++g) {
    if (rows[g].generation != g)
      throw InputError(path + ": generation row " + std::to_string(g) + " holds generation " +
                       std::to_string(rows[g].generation) + " (corrupt history)");
  }

  // the rows to keep are the checkpoint's run: the same digest over them (ids, genomes, fitness)
  if (run_digest) {
    RunDigest digest;
    for (const Individual& individual : individuals) {
      if (individual.generation >= generations)
        break;
      digest.add(individual);
    }
    if (digest.value() != *run_digest) {
      std::ostringstream message;
      message << path << ": belongs to another run than the checkpoint (its rows of generations 0.."
              << generations - 1 << " give run digest " << hex16(digest.value())
              << ", the checkpoint's run " << hex16(*run_digest) << "; the history's seed "
              << stored.seed << ", config hash " << stored.config_hash << "): nothing was changed";
      throw InputError(message.str());
    }
  }

  // a new file with the kept rows, generation by generation, renamed over the old one
  auto writer = std::make_unique<HistoryWriter>(path + ".resume.tmp", attributes, measures,
                                                individual_rows_per_chunk);
  std::size_t next = 0;
  for (std::uint64_t g = 0; g < generations; ++g) {
    std::vector<Individual> group;
    while (next < individuals.size() && individuals[next].generation == g)
      group.push_back(std::move(individuals[next++]));
    if (group.size() != rows[g].stats.count)
      throw InputError(path + ": generation " + std::to_string(g) + " has " +
                       std::to_string(group.size()) + " individual rows, its row says " +
                       std::to_string(rows[g].stats.count) + " (corrupt history)");
    writer->appendGeneration(group, rows[g]);
    kept.individuals.insert(kept.individuals.end(), group.begin(), group.end());
    kept.generations.push_back(rows[g]);
  }
  writer->renameTo(path);
  return writer;
}

void HistoryWriter::close() {
  if (!impl_)
    return;
  QuietErrors quiet;
  std::unique_ptr<Impl> m = std::move(impl_);
  if (!m->closeFile())
    throw Error(ExitCode::output_file, path_ + ": cannot close HDF5 file");
}

// ---------------------------------------------------------------------------------------------
// reader

struct HistoryReader::Impl {
  Handle file;
};

namespace {

// reopenings of a file opened plainly that the writer took up meanwhile
constexpr int kReopenings = 5;

// the history opened (plainly, or for SWMR reading while a writer holds it), else an invalid
// handle and `problem`. While the writer opens or closes the file, both opens fail for a moment
// (about one open in 700 under load): an HDF5 file that does not open is tried again after 20,
// 40, 80, 160 and 320 ms, so only a file damaged for good costs the wait
Handle openWhileWritten(const std::string& path, std::string& problem) {
  Handle file = openFile(path, "history", true, problem);
  for (int attempt = 0; !file.valid() && attempt < kReopenings; ++attempt) {
    if (H5Fis_hdf5(path.c_str()) <= 0)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20 << attempt));
    file = openFile(path, "history", true, problem);
  }
  return file;
}

// read(file)'s value. The writer closes the file between generations, so a reader may open it
// plainly and then see the writer take it up again (the plain view points past the file's end:
// "addr overflow"), or read it for SWMR while the writer puts it down (a dataset unreadable for a
// moment: about one read in 600 under load). Such a read is made again on the file opened anew,
// up to kReopenings times.
template <class Read>
auto readWhileWritten(const std::string& path, Handle& file, Read read) {
  for (int attempt = 0;; ++attempt) {
    try {
      if (!file.valid())
        throw InputError(path + ": HDF5 file cannot be opened again while its writer takes it up");
      return read();
    } catch (const InputError&) {
      if (attempt == kReopenings)
        throw;
      // the writer may be between opening and taking the file up: a plain open and a SWMR
      // open then both fail for a moment
      file.reset();
      std::this_thread::sleep_for(std::chrono::milliseconds(50 * (attempt + 1)));
      std::string problem;
      file = openFile(path, "history", true, problem);
    }
  }
}

}  // namespace

HistoryReader::HistoryReader(const std::string& path, HistoryReadMode mode)
    : path_(path), impl_(std::make_unique<Impl>()) {
  // libhdf5's faults on a damaged file end a child that reads all of it, not this process
  if (mode == HistoryReadMode::child_first) {
    try {
      readInChildFirst(path_, ExitCode::input_file, [&] {
        HistoryReader whole(path_, HistoryReadMode::this_process_only);
        whole.measures();
        whole.individuals();
        whole.generations();
      });
    } catch (const Error& e) {
      throw InputError(e.what());
    }
  }
  QuietErrors quiet;
  auto fail = [&](const std::string& what) { throw InputError(path_ + ": " + what); };

  // missing, not HDF5, truncated or corrupt (a file still being written opens for SWMR reading)
  std::string problem;
  impl_->file = openWhileWritten(path_, problem);
  if (!impl_->file.valid())
    fail(problem);
  hid_t file = impl_->file.get();

  // a cambrian history of a version we read
  std::int32_t version = 0;
  problem = checkFormat(file, "history", kHistoryFormatName, kHistoryFormatVersion, version);
  if (!problem.empty())
    fail(problem);
  HistoryAttributes& a = attributes_;
  a.format_version = version;
  std::int32_t ranks = 0;
  bool ok = readString(file, "cambrian_version", a.cambrian_version) &&
            readString(file, "git_hash", a.git_hash) &&
            readString(file, "config_text", a.config_text) &&
            readString(file, "config_hash", a.config_hash) && readScalar(file, "seed", a.seed) &&
            readString(file, "bullet_precision", a.bullet_precision) &&
            readString(file, "start_time", a.start_time) && readScalar(file, "rank_count", ranks);
  if (!ok)
    fail("a root attribute is missing or of the wrong type (corrupt history)");
  a.rank_count = ranks;
  // older files do not list their run-only settings
  readStrings(file, "run_only_settings", a.run_only_settings);
  for (const char* group : {"individuals", "generations"}) {
    if (H5Lexists(file, group, H5P_DEFAULT) <= 0)
      fail(std::string("group /") + group + " missing (corrupt history)");
  }
}

HistoryReader::~HistoryReader() = default;

std::vector<MeasureInfo> HistoryReader::measures() const {
  return readWhileWritten(path_, impl_->file, [&] {
    QuietErrors quiet;
    Handle dataset(H5Dopen2(impl_->file.get(), "/individuals/measures", H5P_DEFAULT), H5Dclose);
    std::vector<std::string> names, units;
    if (!dataset.valid() || !readStrings(dataset.get(), "names", names))
      throw InputError(path_ + ": /individuals/measures or its names attribute is missing");
    readStrings(dataset.get(), "units", units);
    std::vector<MeasureInfo> measures;
    for (std::size_t i = 0; i < names.size(); ++i)
      measures.push_back({names[i], i < units.size() ? units[i] : ""});
    return measures;
  });
}

std::vector<Individual> HistoryReader::individuals() const {
  return readWhileWritten(path_, impl_->file, [&] {
    std::vector<MeasureInfo> measure_columns = measures();
    QuietErrors quiet;
    Handle group(H5Gopen2(impl_->file.get(), "individuals", H5P_DEFAULT), H5Gclose);
    if (!group.valid())
      throw InputError(path_ + ": cannot open group /individuals");

    // every column, then the rows all of them hold (a live file may be mid-append)
    std::vector<std::uint64_t> generation, id, parent_a, parent_b, offset, size, steps, bred_after;
    std::vector<std::uint8_t> origin, status, bytes;
    std::vector<double> fitness, measures, eval_seconds;
    std::vector<std::int32_t> parts, joints, neurons, worker_rank;
    hsize_t rows = std::numeric_limits<hsize_t>::max();
    auto column = [&](const char* name, auto& values) {
      hsize_t n = 0;
      if (!readColumn(group.get(), name, values, n))
        throw InputError(path_ + ": dataset /individuals/" + name + " missing or unreadable");
      rows = std::min(rows, n);
    };
    column("generation", generation);
    column("id", id);
    column("parent_a", parent_a);
    column("parent_b", parent_b);
    column("operator", origin);
    column("fitness", fitness);
    column("status", status);
    hsize_t width = measure_columns.size(), measure_rows = 0;
    if (!readTable(group.get(), "measures", width, measures, measure_rows))
      throw InputError(path_ +
                       ": dataset /individuals/measures missing, unreadable or not one "
                       "column per name in its names attribute");
    rows = std::min(rows, measure_rows);
    column("parts", parts);
    column("joints", joints);
    column("neurons", neurons);
    column("steps", steps);
    column("eval_seconds", eval_seconds);
    column("worker_rank", worker_rank);
    column("genome_offset", offset);
    column("genome_size", size);
    // written since: absent in older files, where it reads as 0
    if (H5Lexists(group.get(), "bred_after", H5P_DEFAULT) > 0)
      column("bred_after", bred_after);
    bred_after.resize(std::max<std::size_t>(bred_after.size(), generation.size()), 0);
    hsize_t byte_count = 0;
    if (!readColumn(group.get(), "genome_bytes", bytes, byte_count))
      throw InputError(path_ + ": dataset /individuals/genome_bytes missing or unreadable");
    // only the rows of generations whose row is in (their individuals are written first)
    std::uint64_t complete = 0;
    for (const GenerationRecord& g : generations())
      complete += g.stats.count;
    rows = std::min<hsize_t>(rows, complete);

    // rows, checked against the byte stream and the enums
    std::vector<Individual> result;
    result.reserve(rows);
    for (hsize_t i = 0; i < rows; ++i) {
      if (offset[i] > byte_count || size[i] > byte_count - offset[i])
        break;  // bytes of a row still being appended
      if (origin[i] >= kOriginKinds || status[i] >= kEvalStatusKinds)
        throw InputError(path_ + ": /individuals row " + std::to_string(i) +
                         ": operator or status out of range (corrupt history)");
      Individual row;
      row.generation = generation[i];
      row.id = id[i];
      for (std::uint64_t parent : {parent_a[i], parent_b[i]}) {
        if (parent != kNoId)
          row.parents.push_back(parent);
      }
      row.origin = static_cast<Origin>(origin[i]);
      Outcome& outcome = row.outcome;
      outcome.fitness = fitness[i];
      outcome.status = static_cast<EvalStatus>(status[i]);
      for (std::size_t k = 0; k < measure_columns.size(); ++k) {
        double value = measures[i * width + k];
        if (!std::isnan(value))
          outcome.measures.push_back({measure_columns[k].name, value});
      }
      outcome.parts = parts[i];
      outcome.joints = joints[i];
      outcome.neurons = neurons[i];
      outcome.steps = steps[i];
      row.evaluated = true;
      row.eval_seconds = eval_seconds[i];
      row.worker_rank = worker_rank[i];
      row.bred_after = bred_after[i];
      try {
        row.genome = decodeGenome(bytes.data() + offset[i], size[i]);
      } catch (const Error& e) {
        throw InputError(path_ + ": genome of individual " + std::to_string(row.id) + ": " +
                         e.what());
      }
      result.push_back(std::move(row));
    }
    return result;
  });
}

std::vector<GenerationRecord> HistoryReader::generations() const {
  return readWhileWritten(path_, impl_->file, [&] {
    QuietErrors quiet;
    Handle group(H5Gopen2(impl_->file.get(), "generations", H5P_DEFAULT), H5Gclose);
    if (!group.valid())
      throw InputError(path_ + ": cannot open group /generations");

    // every column as doubles or integers, then the rows all of them hold
    std::unordered_map<std::string, std::vector<double>> reals;
    std::unordered_map<std::string, std::vector<std::uint64_t>> integers;
    hsize_t rows = std::numeric_limits<hsize_t>::max();
    std::vector<const Column*> absent;
    for (const Column& c : generationColumns()) {
      hsize_t n = 0;
      bool real = c.type() == H5T_NATIVE_DOUBLE;
      if (c.added_later && H5Lexists(group.get(), c.name, H5P_DEFAULT) <= 0) {
        absent.push_back(&c);
        continue;
      }
      bool ok = real ? readColumn(group.get(), c.name, reals[c.name], n)
                     : readColumn(group.get(), c.name, integers[c.name], n);
      if (!ok)
        throw InputError(path_ + ": dataset /generations/" + c.name + " missing or unreadable");
      rows = std::min(rows, n);
    }
    // columns an older file lacks read as zeros
    for (const Column* c : absent) {
      if (c->type() == H5T_NATIVE_DOUBLE)
        reals[c->name].assign(rows, 0.0);
      else
        integers[c->name].assign(rows, 0);
    }
    std::vector<GenerationRecord> result;
    result.reserve(rows);
    for (hsize_t i = 0; i < rows; ++i) {
      GenerationRecord g;
      forEachGenerationField(g, [&](const char* name, auto& field) {
        using T = std::decay_t<decltype(field)>;
        if constexpr (std::is_floating_point_v<T>)
          field = reals.at(name)[i];
        else
          field = static_cast<T>(integers.at(name)[i]);
      });
      // a generation is in the history once its row is: an append cut short (killed, disk full)
      // leaves rows the writer extended but never filled, which read as zeros
      if (g.generation != i || !(g.unix_time > 0))
        break;
      result.push_back(g);
    }
    return result;
  });
}

}  // namespace cambrian
