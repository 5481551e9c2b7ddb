// cambrian: the islands' breeding ranks trading their best over MPI (evolution/migration.hpp
// says who goes where).
#pragma once

#include "evolution/migration.hpp"
#include "evolution/population.hpp"
#include "parallel/mpi_context.hpp"

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
class Archipelago {
 public:
  /// `breeders`: the islands' breeding ranks, rank = island (must outlive this object);
  /// `generations`: the run's generations (no batch is sent that no generation would take in).
  Archipelago(MpiContext& breeders, const MigrationSettings& settings, std::uint64_t run_seed,
              std::uint64_t generations);
  /// Sends after `evaluated` where due, and returns the immigrants the next generation takes
  /// (in source order, each source's best first; empty where none are due). Null where it had to
  /// wait and `stop_requested` turned true or another island said it stopped: this island
  /// stops too, before breeding (nothing it waits for would come).
  std::optional<std::vector<Individual>> exchange(const Population& evaluated,
                                                  bool (*stop_requested)() = nullptr);
  /// Ends this island's part when its run ends or stops: tells every other island how many
  /// batches it sent there (so none waits for more), then takes in what the others sent it and
  /// waits for its own sends to be taken, so no message is left under way at MPI_Finalize.
  /// Every breeding rank calls it once.
  void close();

 private:
  // receives every waiting batch into arrived_, and the other islands' final counts
  void drain();
  // whether the batch (event, source) can still come: not there yet, and its source has not
  // closed with every batch it sent here taken in
  bool mayStillCome(std::uint64_t event, int source) const;
  MpiContext& breeders_;
  MigrationSettings settings_;
  std::uint64_t run_seed_;
  std::uint64_t generations_;
  std::map<std::pair<std::uint64_t, int>, std::vector<Individual>> arrived_;  // (event, source)
  std::vector<std::uint64_t> sent_;      // batches sent to each island
  std::vector<std::uint64_t> received_;  // batches received from each island
  std::vector<std::int64_t> closed_;     // each island's final count of batches to here; -1: open
};

/// A batch in its byte form: the event generation, the source island, then each individual's
/// id, genome bytes and outcome.
std::vector<std::uint8_t> encodeMigrants(std::uint64_t event, int source,
                                         const std::vector<const Individual*>& individuals);
/// Reads what encodeMigrants wrote; throws InputError naming the field on bad bytes.
std::vector<Individual> decodeMigrants(const std::vector<std::uint8_t>& bytes, std::uint64_t& event,
                                       int& source);

}  // namespace cambrian
