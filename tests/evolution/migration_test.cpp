// Tests of the island model's rules: topologies, when migrants leave, who leaves, where
// immigrants go, island seeds.
#include "evolution/migration.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace cambrian {
namespace {

MigrationSettings islands(int count, MigrationTopology topology) {
  MigrationSettings settings;
  settings.islands = count;
  settings.topology = topology;
  return settings;
}

// a population whose fitnesses are given in id order (ids from `first_id`)
Population withFitness(const std::vector<double>& fitness, std::uint64_t first_id = 10) {
  Population p;
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    Individual individual;
    individual.id = first_id + i;
    individual.outcome.fitness = fitness[i];
    individual.evaluated = true;
    p.individuals.push_back(individual);
  }
  return p;
}

TEST(Migration, TopologiesNameTheirTargets) {
  EXPECT_EQ(migrationTargets(islands(4, MigrationTopology::ring), 3, 9, 1), std::vector<int>{0});
  EXPECT_EQ(migrationTargets(islands(4, MigrationTopology::ring), 1, 9, 1), std::vector<int>{2});
  EXPECT_EQ(migrationTargets(islands(4, MigrationTopology::full), 2, 9, 1),
            (std::vector<int>{0, 1, 3}));
  EXPECT_TRUE(migrationTargets(islands(1, MigrationTopology::full), 0, 9, 1).empty());
  EXPECT_EQ(parseMigrationTopology("random"), MigrationTopology::random);
  EXPECT_THROW(parseMigrationTopology("star"), std::invalid_argument);
}

// random: one other island each time, drawn again every migration, the same for the same seed;
// every island that is sent to knows its sources
TEST(Migration, RandomTargetsAreOthersDrawnAfreshAndSourcesMatchThem) {
  MigrationSettings settings = islands(5, MigrationTopology::random);
  std::set<int> seen;
  for (std::uint64_t g = 0; g < 40; ++g) {
    std::map<int, std::vector<int>> sources;
    for (int island = 0; island < 5; ++island) {
      std::vector<int> targets = migrationTargets(settings, island, g, 77);
      ASSERT_EQ(targets.size(), 1u);
      EXPECT_NE(targets[0], island);
      EXPECT_EQ(targets, migrationTargets(settings, island, g, 77));
      sources[targets[0]].push_back(island);
      if (island == 0)
        seen.insert(targets[0]);
    }
    for (int island = 0; island < 5; ++island)
      EXPECT_EQ(migrationSources(settings, island, g, 77), sources[island]);
  }
  EXPECT_EQ(seen, (std::set<int>{1, 2, 3, 4}));  // island 0 reached every other over 40 draws
}

TEST(Migration, MigrantsLeaveEveryIntervalWithMoreThanOneIsland) {
  MigrationSettings settings = islands(3, MigrationTopology::ring);
  settings.interval = 5;
  std::vector<std::uint64_t> after;
  for (std::uint64_t g = 0; g < 16; ++g) {
    if (migratesAfter(settings, g))
      after.push_back(g);
  }
  EXPECT_EQ(after, (std::vector<std::uint64_t>{4, 9, 14}));
  EXPECT_FALSE(migratesAfter(islands(1, MigrationTopology::ring), 9));
}

TEST(Migration, TheBestEvaluatedEmigrateTiesToTheLowerId) {
  Population p = withFitness({1, 3, 3, 0.5, 9});
  p.individuals[4].evaluated = false;  // not evaluated: never sent
  EXPECT_EQ(emigrants(p, 2), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(emigrants(p, 10).size(), 4u);
}

// immigrants take the last bred places of the next generation (never an elite's or an evaluated
// one's), with their ids, keeping their genomes and outcomes
TEST(Migration, ImmigrantsTakeTheLastBredPlacesOfTheNextGeneration) {
  Population next = withFitness({0, 0, 0, 0, 0}, 30);  // ids 30..34, generation 4
  next.generation = 4;
  for (Individual& individual : next.individuals) {
    individual.generation = 4;
    individual.evaluated = false;
    individual.origin = Origin::mutation;
    individual.parents = {20};
  }
  next.individuals[0].origin = Origin::elite;
  next.individuals[0].evaluated = true;
  next.individuals[3].evaluated = true;  // an outcome already known (reused): kept
  Population arrivals = withFitness({7, 8}, 100);
  arrivals.individuals[1].worker_rank = 3;
  EXPECT_EQ(placeImmigrants(next, arrivals.individuals), 2u);
  std::vector<Origin> origins;
  for (const Individual& individual : next.individuals)
    origins.push_back(individual.origin);
  EXPECT_EQ(origins, (std::vector<Origin>{Origin::elite, Origin::mutation, Origin::migrant,
                                          Origin::mutation, Origin::migrant}));
  const Individual& first = next.individuals[4];
  EXPECT_EQ(first.id, 34u);
  EXPECT_EQ(first.generation, 4u);
  EXPECT_EQ(first.fitness(), 7);
  EXPECT_TRUE(first.parents.empty());
  EXPECT_EQ(next.individuals[2].id, 32u);
  EXPECT_EQ(next.individuals[2].fitness(), 8);
  EXPECT_EQ(next.individuals[2].worker_rank, -1);
  // no more places than bred ones
  EXPECT_EQ(placeImmigrants(next, withFitness({1, 2, 3, 4}, 200).individuals), 1u);
}

TEST(Migration, IslandZeroKeepsTheRunSeedAndTheOthersHaveTheirOwn) {
  EXPECT_EQ(islandSeed(42, 0), 42u);
  std::set<std::uint64_t> seeds;
  for (int island = 0; island < 8; ++island)
    seeds.insert(islandSeed(42, island));
  EXPECT_EQ(seeds.size(), 8u);
  EXPECT_EQ(islandSeed(42, 3), islandSeed(42, 3));
  EXPECT_NE(islandSeed(42, 3), islandSeed(43, 3));
}

}  // namespace
}  // namespace cambrian
