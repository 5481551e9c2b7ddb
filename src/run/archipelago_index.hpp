// cambrian: the run-level index of an archipelago, DIR/archipelago.ini: which islands the run
// has, where each writes, and how they trade.
#pragma once

#include "evolution/migration.hpp"

#include <cstdint>
#include <string>

namespace cambrian {

/// The index's text: an [islands] section (count, interval, migrants, topology, ranks) and one
/// [island_K] section per island (directory below DIR, seed, the job ranks it has), in INI form
/// (the ranks are those of this start: a resume at another rank count writes them again).
std::string archipelagoIndexText(const MigrationSettings& settings, int ranks,
                                 std::uint64_t run_seed);

/// Island `island`'s directory name below the run's output directory: island_K, K zero-padded
/// to the width of the largest island number.
std::string islandDirectoryName(int island, int islands);

/// Writes DIR/archipelago.ini (atomically); throws Error(output_file) naming it.
void writeArchipelagoIndex(const std::string& out_dir, const MigrationSettings& settings, int ranks,
                           std::uint64_t run_seed);

}  // namespace cambrian
