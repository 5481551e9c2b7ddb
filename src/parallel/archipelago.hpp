// cambrian: the islands' breeding ranks trading their best over MPI (evolution/migration.hpp
// says who goes where).
#pragma once

#include "evolution/migration.hpp"
#include "evolution/population.hpp"
#include "parallel/mpi_context.hpp"

#include <cstdint>
#include <map>
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
  /// (in source order, each source's best first); empty where none are due.
  std::vector<Individual> exchange(const Population& evaluated);

 private:
  // receives every waiting batch into arrived_
  void drain();
  MpiContext& breeders_;
  MigrationSettings settings_;
  std::uint64_t run_seed_;
  std::uint64_t generations_;
  std::map<std::pair<std::uint64_t, int>, std::vector<Individual>> arrived_;  // (event, source)
};

/// A batch in its byte form: the event generation, the source island, then each individual's
/// id, genome bytes and outcome.
std::vector<std::uint8_t> encodeMigrants(std::uint64_t event, int source,
                                         const std::vector<const Individual*>& individuals);
/// Reads what encodeMigrants wrote; throws InputError naming the field on bad bytes.
std::vector<Individual> decodeMigrants(const std::vector<std::uint8_t>& bytes, std::uint64_t& event,
                                       int& source);

}  // namespace cambrian
