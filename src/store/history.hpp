// cambrian: the run history file (history.h5) — provenance, one row per evaluated individual
// with its genome bytes and the task's measures by name, one row per generation. Rank 0 appends
// to it generation by generation in HDF5 SWMR mode, so readers (h5py, h5dump, HistoryReader) can
// open it while the run writes. The layout is documented in docs/hdf5-schema.md.
#pragma once

#include "cambrian/outcome.hpp"

#include "evolution/generation_record.hpp"
#include "evolution/population.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

/// Version of the history layout; a reader refuses files with a newer one.
constexpr int kHistoryFormatVersion = 1;

/// Value of the root attribute "format" that marks a cambrian history file.
constexpr const char* kHistoryFormatName = "cambrian-history";

/// The root attributes of a history file.
struct HistoryAttributes {
  int format_version = kHistoryFormatVersion;
  std::string cambrian_version;                ///< kVersion of the writing binary
  std::string git_hash;                        ///< kGitHash of the writing binary
  std::string config_text;                     ///< the full effective settings as INI text
  std::string config_hash;                     ///< hash of the settings that change results
  std::vector<std::string> run_only_settings;  ///< keys that change no result (config_hash
                                               ///< leaves them out); empty in older files
  std::uint64_t seed = 0;                      ///< run seed
  std::string bullet_precision = "float64";    ///< Bullet's scalar type
  std::string start_time;                      ///< ISO 8601 UTC, e.g. 2024-05-01T12:00:00Z
  int rank_count = 1;                          ///< MPI ranks of the run
};

/// The current time as ISO 8601 UTC with seconds ("2024-05-01T12:00:00Z").
std::string utcTimestamp();

/// Writes history.h5: creates (truncating) the file with the root attributes and empty
/// datasets, then appends one generation per call and flushes, so everything up to the last
/// append survives a crash; between appends the file is closed (any HDF5 tool can read it).
/// Throws Error(output_file) naming the path when the file cannot be created or written.
class HistoryWriter {
 public:
  /// Creates `path` with one measure column per entry of `measures` (the task's, in order);
  /// `attributes.start_time` and the version fields are filled in when empty.
  /// `individual_rows_per_chunk` (0: 1024) sizes the chunks of /individuals: a multiple of the
  /// rows one append brings (historyChunkRows) fills whole chunks, so no deflated chunk is ever
  /// read back and compressed again.
  HistoryWriter(const std::string& path, HistoryAttributes attributes,
                const std::vector<MeasureInfo>& measures,
                std::uint64_t individual_rows_per_chunk = 0);
  /// Closes the file (errors are swallowed; call close() to see them).
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  /// Appends the individuals and the row of one generation, then flushes the file.
  /// `generation.unix_time` is set to now when 0. Every measure an outcome carries must be one of
  /// the file's (Error(failure) naming it otherwise); a missing one is stored as NaN. The path
  /// must still name the file: deleted since the last append, the file is written back there
  /// from the open descriptor and goes on (notice() says so); replaced by another file, it is
  /// saved as PATH.own and Error(output_file) says how to go on.
  void appendGeneration(const std::vector<Individual>& individuals, GenerationRecord generation);
  /// What the last append had to repair, for the run to print ("" when nothing), then cleared.
  std::string takeNotice();
  /// Rewrites the timing cells of the last generation row (rank0_serial_seconds,
  /// rank0_cpu_seconds, checkpoint_seconds, wall_seconds) from `record`, once what follows its
  /// append (the append itself, a checkpoint) is done, and flushes; does nothing when no row
  /// exists yet.
  void completeLastGeneration(const GenerationRecord& record);
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
  std::vector<Individual> individuals;        ///< in file order
  std::vector<GenerationRecord> generations;  ///< generation i at index i
};

/// Reopens the history of a resumed run: reads `path` (also after a crash of its writer), keeps
/// the rows of generations 0..generations-1 and drops later ones (they will be recomputed),
/// rewrites it through `path`.resume.tmp renamed over `path` with `attributes` (start_time of
/// the old file kept) and `measures`, and returns the writer ready to append generation
/// `generations`; `kept` receives the rows kept. With `run_digest` (the RunDigest value of the
/// run through generation `generations` - 1, as its checkpoint holds it), the kept rows must give
/// that digest: a history of another run (another seed, population or settings) is refused
/// before anything is rewritten. Throws InputError naming the file when it is unreadable, lacks
/// one of those generations or belongs to another run, Error(output_file) when it cannot be
/// rewritten.
std::unique_ptr<HistoryWriter> resumeHistory(const std::string& path, std::uint64_t generations,
                                             HistoryAttributes attributes,
                                             const std::vector<MeasureInfo>& measures,
                                             HistoryRows& kept,
                                             std::uint64_t individual_rows_per_chunk = 0,
                                             std::optional<std::uint64_t> run_digest = {});

/// Rows per chunk of /individuals for a run appending `population` rows a generation: the
/// smallest multiple of it of at least 64 rows (population 300: 300; 12: 72).
std::uint64_t historyChunkRows(std::uint64_t population);

/// How a HistoryReader treats libhdf5's own faults on a damaged file: `child_first` reads the
/// whole file in a child process first (a crash or endless loop there is an InputError naming the
/// file); `this_process_only` skips that (the fuzz target, the child itself).
enum class HistoryReadMode { child_first, this_process_only };

/// Reads a history file, complete or still being written (opened for SWMR reading). Rows are
/// those every column holds. A missing, truncated, corrupt, non-HDF5 or foreign file throws
/// InputError naming the file and what is wrong.
class HistoryReader {
 public:
  /// Opens and checks `path` (format attribute, version, groups).
  explicit HistoryReader(const std::string& path,
                         HistoryReadMode mode = HistoryReadMode::child_first);
  ~HistoryReader();
  HistoryReader(const HistoryReader&) = delete;
  HistoryReader& operator=(const HistoryReader&) = delete;

  /// The root attributes.
  const HistoryAttributes& attributes() const { return attributes_; }
  /// The measure columns (name and unit), in column order.
  std::vector<MeasureInfo> measures() const;
  /// Every individual row of the generations in the history (generations()), in file order:
  /// the genome decoded (InputError naming the row when it does not decode), the outcome's
  /// fitness, status, measures (by name; NaN cells left out), body counts and steps, evaluated
  /// set.
  std::vector<Individual> individuals() const;
  /// Every generation row in file order, up to the first that was never filled in (row i must
  /// hold generation i and a write time): an append cut short by a kill or a full disk leaves
  /// such rows behind, and the generation's individual rows with them.
  std::vector<GenerationRecord> generations() const;
  /// The file's path.
  const std::string& path() const { return path_; }

 private:
  struct Impl;
  std::string path_;
  HistoryAttributes attributes_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cambrian
