// cambrian: where a run writes, how much it says and when it checkpoints and stops (the [run]
// keys), plus what the run driver is handed by the command that starts it.
#pragma once

#include "cambrian/outcome.hpp"

#include "evolution/breeder.hpp"
#include "evolution/migration.hpp"

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cambrian {

class SettingsSchema;

/// Where a run writes and how much it says.
struct RunSettings {
  std::string out_dir = "cambrian-run";  ///< history.h5, individuals.tsv, generations.tsv go here
  bool quiet = false;                    ///< no progress lines, only the digest
  bool verbose = false;                  ///< timing details after each progress line
  /// the live line within a generation: "auto" (when standard output is a terminal), "live"
  /// or "plain" (generation lines only)
  std::string progress = "auto";
  int checkpoint_every = 0;       ///< checkpoint every this many generations (0: no cadence)
  double checkpoint_minutes = 1;  ///< ... or when this many minutes passed since the last (0: off)
  double max_hours = 0;           ///< stop cleanly before this wall time (0: no limit)
  std::string test_kill_at;       ///< testing: "POINT:GENERATION" where rank 0 SIGKILLs itself
  bool reuse_outcomes = true;     ///< copies of an evaluated genome take its outcome
  double lock_wait = 60;          ///< seconds to wait for DIR/run.lock held by a run that has ended
  /// steady state: a history whose recorded order of results this run follows (empty: results
  /// are taken in as they arrive)
  std::string arrival_order;

  // handed over by the command (not settings)
  ViabilityCheck viable;  ///< birth test for new individuals (none: accept all), rank 0 only
  /// islands: this island's side of the migrations (null: no islands, or islands that do not
  /// trade); must outlive the run
  MigrationExchange* migrations = nullptr;
  bool repeatable = false;  ///< the task's outcome is a function of genome and settings only
  bool history = true;      ///< write DIR/history.h5 generation by generation (SWMR)
  bool terminal = false;    ///< standard output is a terminal (progress "auto" goes live)
  bool fresh = false;       ///< ignore and remove an existing checkpoint, start over
  std::string config_text;  ///< the effective settings as INI text, stored in the history
  std::string earlier_config_text;     ///< what each setting was in runs stored before it existed,
                                       ///< same form (SettingsSchema::earlierRunsIniText; resume)
  std::set<std::string> run_only;      ///< keys that change no result (the schema's run-only keys)
  std::vector<MeasureInfo> measures;   ///< the task's measures: history and table columns
  int rank_count = 1;                  ///< MPI ranks of the run, stored in the history
  bool (*stop_requested)() = nullptr;  ///< polled at generation ends: true stops cleanly
  const char* (*stop_reason)() = nullptr;  ///< what asked for the stop (for the message)

  /// Declares the [run] keys (all run-only), bound to this object, with their ranges.
  void declareSettings(SettingsSchema& schema);
  /// Whether the live line within a generation is shown (progress, terminal, quiet).
  bool liveProgress() const {
    return !quiet && (progress == "live" || (progress == "auto" && terminal));
  }
};

}  // namespace cambrian
