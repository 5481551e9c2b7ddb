// Tests of the islands' layout: contiguous blocks, the larger ones first, every rank placed once.
#include "parallel/island_layout.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cambrian {
namespace {

TEST(IslandLayout, ContiguousBlocksTheLargerFirst) {
  // 10 ranks, 4 islands: 3 3 2 2
  std::vector<int> island, rank, size, first;
  for (int r = 0; r < 10; ++r) {
    IslandPlace place = islandPlace(r, 10, 4);
    island.push_back(place.island);
    rank.push_back(place.rank);
    size.push_back(place.size);
    first.push_back(place.first);
  }
  EXPECT_EQ(island, (std::vector<int>{0, 0, 0, 1, 1, 1, 2, 2, 3, 3}));
  EXPECT_EQ(rank, (std::vector<int>{0, 1, 2, 0, 1, 2, 0, 1, 0, 1}));
  EXPECT_EQ(size, (std::vector<int>{3, 3, 3, 3, 3, 3, 2, 2, 2, 2}));
  EXPECT_EQ(first, (std::vector<int>{0, 0, 0, 3, 3, 3, 6, 6, 8, 8}));
}

TEST(IslandLayout, EveryRankOnceAtEveryCount) {
  for (int ranks = 1; ranks <= 20; ++ranks) {
    for (int islands = 1; islands <= ranks; ++islands) {
      std::vector<int> per_island(static_cast<std::size_t>(islands), 0);
      for (int r = 0; r < ranks; ++r) {
        IslandPlace place = islandPlace(r, ranks, islands);
        ASSERT_GE(place.island, 0);
        ASSERT_LT(place.island, islands);
        EXPECT_EQ(place.first + place.rank, r);
        ++per_island[static_cast<std::size_t>(place.island)];
      }
      for (int island = 0; island < islands; ++island) {
        int size = per_island[static_cast<std::size_t>(island)];
        EXPECT_TRUE(size == ranks / islands || size == ranks / islands + 1);
      }
    }
  }
}

TEST(IslandLayout, FewerRanksThanIslandsIsAConfigErrorNamingTheKey) {
  try {
    islandPlace(0, 3, 4);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("islands.count = 4"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("has 3"), std::string::npos);
  }
}

}  // namespace
}  // namespace cambrian
