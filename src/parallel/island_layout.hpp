// cambrian: which ranks form which island: the job's ranks split into contiguous blocks.
#pragma once

namespace cambrian {

/// Where a rank of the job sits in an archipelago.
struct IslandPlace {
  int island = 0;  ///< its island, 0..islands-1
  int rank = 0;    ///< its rank within the island (0: the island's breeding rank)
  int size = 1;    ///< ranks of the island
  int first = 0;   ///< the job rank of the island's breeding rank
};

/// The place of job rank `rank` of `ranks` among `islands` islands: contiguous blocks of ranks,
/// the first ranks % islands islands one rank larger (so one island per node, with the nodes'
/// ranks in order, is the natural layout). Throws Error(config) when there are fewer ranks than
/// islands, naming islands.count and the rank count.
IslandPlace islandPlace(int rank, int ranks, int islands);

}  // namespace cambrian
