// Tests of the archipelago's index: every island with its directory, seed and ranks.
#include "run/archipelago_index.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

TEST(ArchipelagoIndex, NamesEveryIslandWithItsDirectorySeedAndRanks) {
  MigrationSettings settings;
  settings.islands = 3;
  settings.interval = 5;
  settings.migrants = 1;
  settings.topology = MigrationTopology::random;
  const std::string text = archipelagoIndexText(settings, 8, 42);
  EXPECT_NE(text.find("[islands]\ncount = 3\ninterval = 5\nmigrants = 1\ntopology = random\n"
                      "ranks = 8\n"),
            std::string::npos);
  // 8 ranks in 3 islands: 3, 3, 2
  EXPECT_NE(text.find("[island_0]\ndirectory = island_0\nseed = 42\nfirst_rank = 0\nranks = 3\n"),
            std::string::npos);
  EXPECT_NE(text.find("[island_2]\ndirectory = island_2\nseed = " +
                      std::to_string(islandSeed(42, 2)) + "\nfirst_rank = 6\nranks = 2\n"),
            std::string::npos);
}

TEST(ArchipelagoIndex, DirectoryNamesArePaddedToTheLargestIsland) {
  EXPECT_EQ(islandDirectoryName(3, 4), "island_3");
  EXPECT_EQ(islandDirectoryName(3, 16), "island_03");
  EXPECT_EQ(islandDirectoryName(12, 101), "island_012");
}

}  // namespace
}  // namespace cambrian
