// cambrian: the islands' breeding ranks trading their best over MPI (evolution/migration.hpp
// says who goes where).
#pragma once

#include "evolution/migration.hpp"
#include "evolution/population.hpp"
#include "parallel/mpi_context.hpp"

#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace cambrian {

/// One island's side of the migrations. After each generation its breeding rank calls
/// exchange(): where migrants leave after it, this island's go out (posted, never waiting), and
/// the immigrants due now come back: the batches its sources sent one interval earlier, so an
/// island waits only for a neighbour a whole interval behind. Results depend on the island count
/// and topology alone, not on the ranks of each island or on arrival order.
///
/// Resume: a batch sent stays in this island's outbox (and its checkpoints) until its target
/// says its own checkpoint no longer needs it (Tag::needed, after each checkpoint); a resume
/// sends the outbox again, and a batch that arrives twice is taken in once. So a job killed at
/// any moment resumes every island from its own last checkpoint to the straight run's results.
class Archipelago : public MigrationExchange {
 public:
  /// `breeders`: the islands' breeding ranks, rank = island (must outlive this object);
  /// `stop_requested` (may be null): polled while waiting for a batch.
  Archipelago(MpiContext& breeders, const MigrationSettings& settings, std::uint64_t run_seed,
              bool (*stop_requested)() = nullptr);
  /// Sends after `evaluated` where due, and returns the immigrants the next generation takes
  /// (in source order, each source's best first; empty where none are due). Null where it had to
  /// wait and a stop was requested or another island said it stopped: this island stops too,
  /// before breeding (nothing it waits for would come).
  /// Every island learns where the others start (a collective over the breeding ranks) and
  /// checks that it holds every batch they will wait for from it (missingFor); where one does
  /// not, every island throws before running a generation (that one saying why).
  void start(std::uint64_t next_generation, const std::string& directory) override;
  /// Why an island starting where `starts` says (by island) would wait for ever for a batch this
  /// island no longer holds or makes again (the message names both and the generation), or ""
  /// when none would; `directory` is this island's (for the message).
  std::string missingFor(const std::vector<std::uint64_t>& starts,
                         const std::string& directory) const;
  std::optional<std::vector<Individual>> exchange(const Population& evaluated) override;
  /// The outbox: every batch sent that its target may still need.
  std::vector<std::uint8_t> checkpointState() const override;
  /// Noted here; the other islands are told at the next exchange (this may be another thread).
  void checkpointed(std::uint64_t next_generation) override;
  /// Sends the kept outbox again (throws Error(checkpoint) on bytes it cannot read).
  void resume(const std::vector<std::uint8_t>& state) override;
  /// Ends this island's part when its run ends or stops: tells every other island how many
  /// messages it sent there (so none waits for more), then takes in what the others sent it and
  /// waits for its own sends to be taken, so no message is left under way at MPI_Finalize.
  /// Every breeding rank calls it once.
  void close() override;

 private:
  // posts to another island, counted for close()
  void send(int island, Tag tag, std::vector<std::uint8_t> bytes);
  // receives every waiting batch into arrived_, the others' needs and their final counts
  void drain();
  // whether the batch (event, source) can still come: not there yet, and its source has not
  // closed with every message it sent here taken in
  bool mayStillCome(std::uint64_t event, int source) const;
  MpiContext& breeders_;
  MigrationSettings settings_;
  std::uint64_t run_seed_;
  bool (*stop_requested_)();
  std::map<std::pair<std::uint64_t, int>, std::vector<Individual>> arrived_;   // (event, source)
  std::map<std::pair<std::uint64_t, int>, std::vector<std::uint8_t>> outbox_;  // (event, target)
  std::atomic<std::uint64_t> checkpointed_{0};  // next_generation of the last checkpoint
  std::uint64_t announced_ = 0;                 // ... the others were told of
  std::vector<std::uint64_t> sent_;             // messages sent to each island
  std::vector<std::uint64_t> received_;         // messages received from each island
  std::vector<std::int64_t> closed_;  // each island's final count of messages to here; -1: open
};

/// A batch in its byte form: the event generation, the source island, then each individual's
/// id, genome bytes and outcome.
std::vector<std::uint8_t> encodeMigrants(std::uint64_t event, int source,
                                         const std::vector<const Individual*>& individuals);
/// Reads what encodeMigrants wrote; throws InputError naming the field on bad bytes.
std::vector<Individual> decodeMigrants(const std::vector<std::uint8_t>& bytes, std::uint64_t& event,
                                       int& source);

}  // namespace cambrian
