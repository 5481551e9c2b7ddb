// cambrian: DIR/archipelago.ini, the islands of a run.
#include "run/archipelago_index.hpp"

#include "cambrian/error.hpp"

#include "parallel/island_layout.hpp"
#include "run/tables.hpp"

#include <filesystem>
#include <sstream>

namespace cambrian {

std::string islandDirectoryName(int island, int islands) {
  const std::size_t width = std::to_string(islands - 1).size();
  const std::string number = std::to_string(island);
  return "island_" + std::string(width - number.size(), '0') + number;
}

std::string archipelagoIndexText(const MigrationSettings& settings, int ranks,
                                 std::uint64_t run_seed) {
  std::ostringstream text;
  text << "# cambrian archipelago: the islands of this run (docs/parallel.md, \"Islands\")\n"
       << "[islands]\n"
       << "count = " << settings.islands << "\n"
       << "interval = " << settings.interval << "\n"
       << "migrants = " << settings.migrants << "\n"
       << "topology = " << migrationTopologyName(settings.topology) << "\n"
       << "ranks = " << ranks << "\n";
  for (int island = 0; island < settings.islands; ++island) {
    // the island's first rank is its breeding rank; the rest evaluate
    int first = ranks, size = 0;
    for (int rank = 0; rank < ranks; ++rank) {
      IslandPlace place = islandPlace(rank, ranks, settings.islands);
      if (place.island == island) {
        first = place.first;
        size = place.size;
        break;
      }
    }
    text << "\n[" << islandDirectoryName(island, settings.islands) << "]\n"
         << "directory = " << islandDirectoryName(island, settings.islands) << "\n"
         << "seed = " << islandSeed(run_seed, island) << "\n"
         << "first_rank = " << first << "\n"
         << "ranks = " << size << "\n";
  }
  return text.str();
}

void writeArchipelagoIndex(const std::string& out_dir, const MigrationSettings& settings, int ranks,
                           std::uint64_t run_seed) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error)
    throw Error(ExitCode::output_file,
                out_dir + ": cannot create the output directory: " + error.message());
  writeTextFileAtomically(out_dir + "/archipelago.ini",
                          archipelagoIndexText(settings, ranks, run_seed));
}

}  // namespace cambrian
