// cambrian: the job's ranks split into islands.
#include "parallel/island_layout.hpp"

#include "cambrian/error.hpp"

#include <string>

namespace cambrian {

IslandPlace islandPlace(int rank, int ranks, int islands) {
  if (islands < 1 || ranks < islands)
    throw ConfigError("islands.count = " + std::to_string(islands) + " needs at least as many " +
                      "ranks (the job has " + std::to_string(ranks) + "): one breeding rank each");
  const int base = ranks / islands, larger = ranks % islands;
  // islands 0..larger-1 hold base + 1 ranks, the rest base
  const int in_larger = larger * (base + 1);
  IslandPlace place;
  if (rank < in_larger) {
    place.island = rank / (base + 1);
    place.size = base + 1;
    place.first = place.island * (base + 1);
  } else {
    place.island = larger + (rank - in_larger) / base;
    place.size = base;
    place.first = in_larger + (place.island - larger) * base;
  }
  place.rank = rank - place.first;
  return place;
}

}  // namespace cambrian
