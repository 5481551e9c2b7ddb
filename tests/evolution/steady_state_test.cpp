// Tests of steady-state evolution's rules: where a result taken in goes among the members (the
// reverse tournament) and the ranking kept beside them, and the child bred from the members.
#include "evolution/steady_state.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "evolution/breeder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace cambrian {
namespace {

const graph::DirectedGraphEncoding kEncoding;

// an evaluated individual of this id and fitness
Individual evaluated(std::uint64_t id, double fitness) {
  Individual individual;
  individual.id = id;
  individual.outcome.fitness = fitness;
  individual.evaluated = true;
  return individual;
}

EvolutionSettings settingsOf(int population, int tournament) {
  EvolutionSettings s;
  s.population = population;
  s.replacement_tournament = tournament;
  s.seed = 3;
  return s;
}

std::vector<std::uint64_t> idsOf(const SteadyMembers& members) {
  std::vector<std::uint64_t> ids;
  for (const Individual& i : members.population().individuals)
    ids.push_back(i.id);
  return ids;
}

TEST(SteadyMembers, JoinsInIdOrderWhileThereIsRoom) {
  const EvolutionSettings s = settingsOf(3, 2);
  SteadyMembers members(s);
  EXPECT_TRUE(members.takeIn(evaluated(5, 0.0)));
  EXPECT_TRUE(members.takeIn(evaluated(2, 0.0)));
  EXPECT_TRUE(members.takeIn(evaluated(9, 0.0)));
  EXPECT_EQ(idsOf(members), (std::vector<std::uint64_t>{2, 5, 9}));
}

TEST(SteadyMembers, TurnsAwayAResultWorseThanEveryMember) {
  const EvolutionSettings s = settingsOf(4, 2);
  SteadyMembers members(s);
  for (std::uint64_t id = 0; id < 4; ++id)
    members.takeIn(evaluated(id, 1.0 + static_cast<double>(id)));
  for (std::uint64_t id = 10; id < 60; ++id) {
    EXPECT_FALSE(members.takeIn(evaluated(id, 0.5))) << id;
    EXPECT_EQ(idsOf(members), (std::vector<std::uint64_t>{0, 1, 2, 3}));
  }
}

TEST(SteadyMembers, AResultAsFitAsTheLoserReplacesIt) {
  // every member as fit as the result: the tournament's loser (the oldest drawn) gives way
  const EvolutionSettings s = settingsOf(4, 2);
  SteadyMembers members(s);
  for (std::uint64_t id = 0; id < 4; ++id)
    members.takeIn(evaluated(id, 2.0));
  EXPECT_TRUE(members.takeIn(evaluated(7, 2.0)));
  EXPECT_EQ(members.size(), 4u);
  EXPECT_EQ(members.population().individuals.back().id, 7u);
}

TEST(SteadyMembers, ReplacesTheWorstOfAReverseTournament) {
  // members of fitness 1 < 2 < 3 < 4, results better than all: the member that gives way is the
  // worst of 2 drawn with replacement, rank r (0 = worst) with chance ((4-r)^2 - (3-r)^2) / 16
  const EvolutionSettings s = settingsOf(4, 2);
  std::map<double, int> replaced;
  const int draws = 4000;
  for (int k = 0; k < draws; ++k) {
    SteadyMembers members(s);
    for (std::uint64_t id = 0; id < 4; ++id)
      members.takeIn(evaluated(id, 1.0 + static_cast<double>(id)));
    const auto id = static_cast<std::uint64_t>(100 + k);
    ASSERT_TRUE(members.takeIn(evaluated(id, 10.0)));
    double sum = 0;
    for (const Individual& i : members.population().individuals)
      sum += i.fitness();
    replaced[1 + 2 + 3 + 4 + 10 - sum] += 1;  // the fitness that left
  }
  const double expected[] = {7.0 / 16, 5.0 / 16, 3.0 / 16, 1.0 / 16};
  for (int r = 0; r < 4; ++r)
    EXPECT_NEAR(replaced[1.0 + r] / static_cast<double>(draws), expected[r], 0.03) << "rank " << r;
}

TEST(SteadyMembers, IsAPureFunctionOfMembersResultAndSettings) {
  const EvolutionSettings s = settingsOf(5, 3);
  auto run = [&] {
    SteadyMembers members(s);
    for (std::uint64_t id = 0; id < 40; ++id)
      members.takeIn(evaluated(id, static_cast<double>((id * 7) % 11)));
    return idsOf(members);
  };
  EXPECT_EQ(run(), run());
}

TEST(SteadyMembers, KeepTheRankingPopulationRankingGives) {
  const EvolutionSettings s = settingsOf(7, 3);
  SteadyMembers members(s);
  for (std::uint64_t id = 0; id < 200; ++id) {
    // repeated fitnesses (ties by id) and a non-finite one (the worst)
    Individual individual = evaluated(id, static_cast<double>((id * 5) % 9));
    if (id % 17 == 0)
      individual.outcome.fitness = std::nan("");
    members.takeIn(std::move(individual));
    const Population& population = members.population();
    std::vector<std::uint64_t> expected;
    std::vector<double> fitness;
    for (std::size_t index : population.ranking()) {
      expected.push_back(population.individuals[index].id);
      fitness.push_back(population.individuals[index].fitness());
    }
    ASSERT_EQ(members.rankedIds(), expected) << "after " << id;
    ASSERT_EQ(members.rankedFitness(), fitness) << "after " << id;
  }
}

// members of random genomes with fitnesses `fitness(i)` (i: the place in id order), in
// generation 3, as a steady state holds them
SteadyMembers randomMembers(const EvolutionSettings& s, Breeder& breeder,
                            double (*fitness)(std::size_t)) {
  SteadyMembers members(s);
  Population initial = breeder.initialPopulation();
  for (std::size_t i = 0; i < initial.individuals.size(); ++i) {
    Individual& individual = initial.individuals[i];
    individual.outcome.fitness = fitness(i);
    individual.evaluated = true;
    members.takeIn(std::move(individual));
  }
  members.setGeneration(3);
  return members;
}
double byFive(std::size_t i) {
  return static_cast<double>(i % 5);
}
double byPlace(std::size_t i) {
  return static_cast<double>(i);
}

TEST(SteadyChild, IsAPureFunctionOfTheMembersAndItsId) {
  EvolutionSettings s = settingsOf(12, 2);
  Breeder a(s, kEncoding), b(s, kEncoding);
  SteadyMembers members = randomMembers(s, a, byFive);
  randomMembers(s, b, byFive);
  for (int k = 0; k < 20; ++k) {
    Individual x = a.steadyChild(members, 40 + static_cast<std::uint64_t>(k));
    Individual y = b.steadyChild(members, 40 + static_cast<std::uint64_t>(k));
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.parents, y.parents);
    EXPECT_EQ(x.origin, y.origin);
    EXPECT_EQ(x.genomeBytes(), y.genomeBytes());
    EXPECT_EQ(x.bred_after, 40u + static_cast<std::uint64_t>(k));
    EXPECT_EQ(x.generation, 3u);
    EXPECT_FALSE(x.evaluated);
    EXPECT_EQ(x.id, 12u + static_cast<std::uint64_t>(k));
  }
}

TEST(SteadyChild, ParentsAreMembersAndOperatorsFollowTheShares) {
  EvolutionSettings s = settingsOf(12, 2);
  s.mutation_fraction = 0.5;
  s.crossover_fraction = 0.3;
  s.graft_fraction = 0.2;
  Breeder breeder(s, kEncoding);
  SteadyMembers members = randomMembers(s, breeder, byFive);
  std::map<Origin, int> made;
  const int children = 2000;
  for (int k = 0; k < children; ++k) {
    Individual child = breeder.steadyChild(members, 0);
    made[child.origin] += 1;
    ASSERT_EQ(child.parents.size(), child.origin == Origin::mutation ? 1u : 2u);
    for (std::uint64_t parent : child.parents)
      ASSERT_NO_THROW(members.population().indexOf(parent))
          << "parent " << parent << " is not a member";
  }
  EXPECT_NEAR(made[Origin::mutation] / double(children), 0.5, 0.04);
  EXPECT_NEAR(made[Origin::crossover] / double(children), 0.3, 0.04);
  EXPECT_NEAR(made[Origin::graft] / double(children), 0.2, 0.04);
}

TEST(SteadyChild, FitterMembersAreChosenMoreOften) {
  // truncation to the best 25 %: every parent is among the three fittest members
  EvolutionSettings s = settingsOf(12, 2);
  s.selection.method = SelectionMethod::truncation;
  s.selection.truncation_fraction = 0.25;
  Breeder breeder(s, kEncoding);
  SteadyMembers members = randomMembers(s, breeder, byPlace);
  for (int k = 0; k < 200; ++k) {
    for (std::uint64_t parent : breeder.steadyChild(members, 0).parents)
      EXPECT_GE(parent, 9u);
  }
}

TEST(SteadyChild, RefusesToBreedFromNoMembers) {
  const EvolutionSettings s = settingsOf(4, 2);
  Breeder breeder(s, kEncoding);
  EXPECT_THROW(breeder.steadyChild(SteadyMembers(s), 0), std::invalid_argument);
}

}  // namespace
}  // namespace cambrian
