// cambrian: the run history file (history.h5) — provenance, one row per evaluated individual
// with its genome bytes, one row per generation. Rank 0 appends to it generation by generation
// in HDF5 SWMR mode, so readers (h5py, h5dump, HistoryReader) can open it while the run writes.
// The layout is documented in docs/hdf5-schema.md.
#pragma once

#include "cambrian/genome.hpp"
#include "cambrian/outcome.hpp"

#include "evolution/population.hpp"
#include "evolution/run_record.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

/// Version of the history layout; a reader refuses files with a newer one.
constexpr int kHistoryFormatVersion = 1;

/// Value of the root attribute "format" that marks a cambrian history file.
constexpr const char* kHistoryFormatName = "cambrian-history";

/// The fixed jury measure columns of /individuals/measures: name and unit. A measure an
/// outcome does not carry is NaN.
struct HistoryMeasure {
  const char* name;
  const char* unit;
};

/// Number of measure columns.
constexpr std::size_t kHistoryMeasureCount = 6;

/// The measure columns, in column order (distance, body_length, body_lengths, height, cost_us,
/// nodes).
const std::array<HistoryMeasure, kHistoryMeasureCount>& historyMeasures();

/// The root attributes of a history file.
struct HistoryAttributes {
  int format_version = kHistoryFormatVersion;
  std::string cambrian_version;              ///< kVersion of the writing binary
  std::string git_hash;                      ///< kGitHash of the writing binary
  std::string config_text;                   ///< the full effective settings as INI text
  std::string config_hash;                   ///< configHash(config_text)
  std::uint64_t seed = 0;                    ///< run seed
  std::string bullet_precision = "float64";  ///< Bullet's scalar type
  std::string start_time;                    ///< ISO 8601 UTC, e.g. 2024-05-01T12:00:00Z
  int rank_count = 1;                        ///< MPI ranks of the run
};

/// FNV-1a 64-bit hash of `config_text` as 16 lower-case hex digits.
std::string configHash(const std::string& config_text);

/// The current time as ISO 8601 UTC with seconds ("2024-05-01T12:00:00Z").
std::string utcTimestamp();

/// One row of /individuals.
struct HistoryIndividual {
  std::uint64_t generation = 0;
  std::uint64_t id = kNoId;
  std::uint64_t parent_a = kNoId;  ///< first parent; kNoId (UINT64_MAX) when absent
  std::uint64_t parent_b = kNoId;  ///< second parent; kNoId when absent
  Origin origin = Origin::random;  ///< stored as "operator"
  double fitness = kWorstFitness;
  EvalStatus status = EvalStatus::ok;
  std::array<double, kHistoryMeasureCount> measures{};  ///< NaN where absent
  int parts = 0, joints = 0, neurons = 0;
  std::uint64_t steps = 0;           ///< physics steps simulated
  double eval_seconds = 0;           ///< evaluation wall time, 0 for copies
  int worker_rank = -1;              ///< evaluating rank, -1 for copies
  std::vector<std::uint8_t> genome;  ///< serializeGenome bytes
};

/// The row of an individual of an evaluated population (genome serialized, measures matched
/// by name to the fixed columns; measures outside the fixed set are dropped).
HistoryIndividual makeHistoryIndividual(const Individual& individual);

/// One row of /generations.
struct HistoryGeneration {
  std::uint64_t generation = 0;
  std::uint64_t count = 0;   ///< individuals
  std::uint64_t failed = 0;  ///< individuals whose status is not ok
  double best = 0, mean = 0, stddev = 0, worst = 0, q25 = 0, median = 0, q75 = 0;
  std::uint64_t best_id = kNoId;
  std::uint64_t evaluations = 0;       ///< individuals evaluated (elites are not)
  int workers = 0;                     ///< evaluating ranks
  std::uint64_t distinct_genomes = 0;  ///< distinct genome byte strings in the generation
  double rank0_serial_seconds = 0;
  double rank0_cpu_seconds = 0;       ///< CPU time of rank 0 in the generation (0 in older files)
  double rank0_dispatch_seconds = 0;  ///< rank 0 handing out and taking in (0 in older files)
  double evaluation_span_seconds = 0;
  double worker_busy_seconds = 0;
  double worker_idle_seconds = 0;
  double checkpoint_seconds = 0;  ///< time writing the checkpoint (0: no checkpoints yet)
  double wall_seconds = 0;        ///< the whole generation on rank 0
  double unix_time = 0;           ///< seconds since 1970-01-01 UTC when the row was appended
};

/// The timing cells of a generation row known only after the row is appended.
struct GenerationTimes {
  double rank0_serial_seconds = 0;  ///< now including the append and the checkpoint
  double rank0_cpu_seconds = 0;
  double checkpoint_seconds = 0;  ///< the checkpoint written after the generation (0: none)
  double wall_seconds = 0;        ///< breeding to the end of the checkpoint, or of the append
};

/// The row of a generation: its record plus the diversity of `population`.
HistoryGeneration makeHistoryGeneration(const GenerationRecord& record,
                                        const Population& population);

/// Number of distinct serialized genomes in `population`.
std::uint64_t distinctGenomes(const Population& population);

/// Writes history.h5: creates (truncating) the file with the root attributes and empty
/// datasets, switches it to SWMR write mode, then appends one generation per call and flushes,
/// so everything up to the last append survives a crash. Throws Error(output_file) naming the
/// path when the file cannot be created or written.
class HistoryWriter {
 public:
  /// Creates `path`; `attributes.config_hash` and `start_time` are filled in when empty.
  /// `individual_rows_per_chunk` (0: 1024) sizes the chunks of /individuals: a multiple of the
  /// rows one append brings (historyChunkRows) fills whole chunks, so no deflated chunk is ever
  /// read back and compressed again.
  HistoryWriter(const std::string& path, HistoryAttributes attributes,
                std::uint64_t individual_rows_per_chunk = 0);
  /// Closes the file (errors are swallowed; call close() to see them).
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  /// Appends the individuals and the row of one generation, then flushes the file.
  /// `generation.unix_time` is set to now when 0.
  void appendGeneration(const std::vector<HistoryIndividual>& individuals,
                        HistoryGeneration generation);
  /// Rewrites the timing cells of the last generation row in place, once what follows its
  /// append (the append itself, a checkpoint) is done, and flushes; does nothing when no row
  /// exists yet.
  void completeLastGeneration(const GenerationTimes& times);
  /// Renames the open file to `path` (same file system) and makes it the writer's path.
  void renameTo(const std::string& path);
  /// Flushes and closes the file; further appends throw.
  void close();
  /// The file's path.
  const std::string& path() const { return path_; }

 private:
  struct Impl;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

/// The rows a resumed history keeps.
struct HistoryRows {
  std::vector<HistoryIndividual> individuals;  ///< in file order
  std::vector<HistoryGeneration> generations;  ///< generation i at index i
};

/// Reopens the history of a resumed run: reads `path` (also after a crash of its writer), keeps
/// the rows of generations 0..generations-1 and drops later ones (they will be recomputed),
/// rewrites it through `path`.resume.tmp renamed over `path` with `attributes` (start_time of
/// the old file kept) and returns the writer, in SWMR mode, ready to append generation
/// `generations`; `kept` receives the rows kept. Throws InputError naming the file when it is
/// unreadable or lacks one of those generations, Error(output_file) when it cannot be rewritten.
std::unique_ptr<HistoryWriter> resumeHistory(const std::string& path, std::uint64_t generations,
                                             HistoryAttributes attributes, HistoryRows& kept,
                                             std::uint64_t individual_rows_per_chunk = 0);

/// Rows per chunk of /individuals for a run appending `population` rows a generation: the
/// smallest multiple of it of at least 64 rows (population 300: 300; 12: 72).
std::uint64_t historyChunkRows(std::uint64_t population);

/// Reads a history file, complete or still being written (opened for SWMR reading). Rows are
/// those every column holds. A missing, truncated, corrupt, non-HDF5 or foreign file throws
/// InputError naming the file and what is wrong.
class HistoryReader {
 public:
  /// Opens and checks `path` (format attribute, version, groups).
  explicit HistoryReader(const std::string& path);
  ~HistoryReader();
  HistoryReader(const HistoryReader&) = delete;
  HistoryReader& operator=(const HistoryReader&) = delete;

  /// The root attributes.
  const HistoryAttributes& attributes() const { return attributes_; }
  /// Every individual row in file order, with genome bytes.
  std::vector<HistoryIndividual> individuals() const;
  /// Every generation row in file order.
  std::vector<HistoryGeneration> generations() const;
  /// The genome bytes of the individual `id` (its first row); InputError when absent.
  std::vector<std::uint8_t> genomeBytes(std::uint64_t id) const;
  /// The genome of the individual `id`, deserialized; InputError when absent or malformed.
  Genome genome(std::uint64_t id) const;
  /// The file's path.
  const std::string& path() const { return path_; }

 private:
  struct Impl;
  std::string path_;
  HistoryAttributes attributes_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cambrian
