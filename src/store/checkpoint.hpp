// cambrian: the checkpoint file (checkpoint.h5) — everything rank 0 needs to continue a run
// bit-identically from a generation boundary: the last evaluated population (ids, parents,
// origins, genomes, outcomes), the next id, the run digest so far and the settings. Written
// atomically (temporary file, fsync, rename, previous one kept); layout in docs/hdf5-schema.md,
// rules in docs/checkpoints.md.
#pragma once

#include "evolution/population.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

struct HistoryAttributes;

/// Version of the checkpoint layout; a reader refuses files with a newer one. Version 2 stores
/// each outcome in its one byte form (version 1, one column per outcome field, is still read).
constexpr int kCheckpointFormatVersion = 2;

/// Value of the root attribute "format" that marks a cambrian checkpoint file.
constexpr const char* kCheckpointFormatName = "cambrian-checkpoint";

/// The state a run continues from.
struct CheckpointState {
  std::string config_text;            ///< the full effective settings as INI text
  std::string config_hash;            ///< hash of the settings that change results
  std::uint64_t seed = 0;             ///< run seed
  std::uint64_t next_generation = 0;  ///< generation the run continues with (population's + 1)
  std::uint64_t next_id = 0;          ///< id the next new individual gets (Breeder::nextId)
  std::uint64_t digest = 0;           ///< RunDigest::value() over every generation so far
  int rank_count = 1;                 ///< MPI ranks of the run that wrote it (information only)
  std::string cambrian_version;       ///< version of the cambrian that wrote it (read only)
  std::string git_hash;               ///< and its git commit (read only)
  Population population;              ///< the last evaluated generation, every field kept
  /// steady-state evolution: `population` holds the members and, unevaluated, the creatures
  /// handed out and not yet taken in; each individual's bred_after is kept (dataset
  /// /population/bred_after, present only then)
  bool steady_state = false;
  /// islands: the island's migration state (MigrationExchange::checkpointState; opaque here),
  /// dataset /migrations; empty without islands (no dataset)
  std::vector<std::uint8_t> migrations;
};

/// DIR/checkpoint.h5.
std::string checkpointPath(const std::string& dir);
/// DIR/checkpoint.prev.h5, the checkpoint before the current one.
std::string previousCheckpointPath(const std::string& dir);

/// Stage names passed to the write observer: "write" (the temporary file holds every dataset
/// but is not closed yet) and "rename" (temporary file complete and synced, previous one kept,
/// not yet renamed into place).
using CheckpointStageObserver = std::function<void(const std::string& stage)>;

/// Writes DIR/checkpoint.h5 atomically: DIR/checkpoint.h5.tmp is written, closed and fsynced,
/// the current checkpoint is kept as DIR/checkpoint.prev.h5 (hard link, so checkpoint.h5 never
/// disappears), the temporary file is renamed into place and DIR is fsynced. `observer` (may be
/// empty) is called at each stage. Throws Error(output_file) naming the path on failure; the
/// previous checkpoint then stays intact.
void writeCheckpoint(const std::string& dir, const CheckpointState& state,
                     const CheckpointStageObserver& observer = {});

/// Reads and checks a checkpoint file. Throws Error(checkpoint) naming `path` and what is wrong
/// when it is missing, not HDF5, truncated, corrupt (state hash mismatch), foreign (format
/// attribute) or of a newer format version.
CheckpointState readCheckpoint(const std::string& path);
/// readCheckpoint without the child process that meets libhdf5's faults first (the fuzz target).
CheckpointState readCheckpointHere(const std::string& path);

/// The checkpoint a run in DIR continues from: nullopt when DIR holds none and none is expected
/// (a fresh run). Throws Error(checkpoint) naming the file when checkpoint.h5 is unreadable, or
/// missing although checkpoint.prev.h5 exists or DIR/history.h5 records a written checkpoint;
/// the message says whether checkpoint.prev.h5 is good (no automatic fallback) and that
/// `--fresh` starts over. A history of this run (`this_run`: same config hash and seed) that
/// holds generation 0 only is no obstacle: it is what a run killed between generation 0's append
/// and its first checkpoint leaves, and starting fresh writes the same row again; nor is an
/// unreadable history.h5 beside this run's history.h5.starting marker.
std::optional<CheckpointState> findCheckpoint(const std::string& dir,
                                              const HistoryAttributes* this_run = nullptr);

/// DIR/history.h5.starting: written (this run's config hash and seed) just before a fresh run
/// creates DIR/history.h5, removed once its first checkpoint is written or the run closes. A
/// run killed in between can leave an unreadable history.h5 (killed inside HDF5's first
/// writes); findCheckpoint lets the same run (same hash and seed) start that history again,
/// and still refuses to touch an unreadable history.h5 without the marker.
std::string historyStartingPath(const std::string& dir);
/// Writes DIR/history.h5.starting for `run`. Throws Error(output_file) naming it on failure.
void markHistoryStarting(const std::string& dir, const HistoryAttributes& run);
/// Removes DIR/history.h5.starting (if there is one; a failure is ignored: the marker only ever
/// allows this run to start its own unreadable history again).
void clearHistoryStarting(const std::string& dir);

/// Removes DIR/checkpoint.h5, checkpoint.prev.h5 and checkpoint.h5.tmp (a fresh start).
/// Throws Error(output_file) naming a file that cannot be removed.
void removeCheckpoints(const std::string& dir);

}  // namespace cambrian
