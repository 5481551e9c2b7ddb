// Tests of steady-state evolution's rules: where a result taken in goes among the members (the
// reverse tournament), and the child bred from the members as they are.
#include "evolution/steady_state.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "evolution/breeder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

std::vector<std::uint64_t> idsOf(const Population& members) {
  std::vector<std::uint64_t> ids;
  for (const Individual& i : members.individuals)
    ids.push_back(i.id);
  return ids;
}

TEST(TakeIntoMembers, JoinsInIdOrderWhileThereIsRoom) {
  const EvolutionSettings s = settingsOf(3, 2);
  Population members;
  EXPECT_TRUE(takeIntoMembers(members, evaluated(5, 0.0), s));
  EXPECT_TRUE(takeIntoMembers(members, evaluated(2, 0.0), s));
  EXPECT_TRUE(takeIntoMembers(members, evaluated(9, 0.0), s));
  EXPECT_EQ(idsOf(members), (std::vector<std::uint64_t>{2, 5, 9}));
}

TEST(TakeIntoMembers, TurnsAwayAResultWorseThanEveryMember) {
  const EvolutionSettings s = settingsOf(4, 2);
  Population members;
  for (std::uint64_t id = 0; id < 4; ++id)
    takeIntoMembers(members, evaluated(id, 1.0 + static_cast<double>(id)), s);
  for (std::uint64_t id = 10; id < 60; ++id) {
    EXPECT_FALSE(takeIntoMembers(members, evaluated(id, 0.5), s)) << id;
    EXPECT_EQ(idsOf(members), (std::vector<std::uint64_t>{0, 1, 2, 3}));
  }
}

TEST(TakeIntoMembers, AResultAsFitAsTheLoserReplacesIt) {
  // every member as fit as the result: the tournament's loser (the oldest drawn) gives way
  const EvolutionSettings s = settingsOf(4, 2);
  Population members;
  for (std::uint64_t id = 0; id < 4; ++id)
    takeIntoMembers(members, evaluated(id, 2.0), s);
  EXPECT_TRUE(takeIntoMembers(members, evaluated(7, 2.0), s));
  EXPECT_EQ(members.individuals.size(), 4u);
  EXPECT_EQ(members.individuals.back().id, 7u);
}

TEST(TakeIntoMembers, ReplacesTheWorstOfAReverseTournament) {
  // members of fitness 1 < 2 < 3 < 4, results better than all: the member that gives way is the
  // worst of 2 drawn with replacement, rank r (0 = worst) with chance ((4-r)^2 - (3-r)^2) / 16
  const EvolutionSettings s = settingsOf(4, 2);
  std::map<double, int> replaced;
  const int draws = 4000;
  for (int k = 0; k < draws; ++k) {
    Population members;
    for (std::uint64_t id = 0; id < 4; ++id)
      takeIntoMembers(members, evaluated(id, 1.0 + static_cast<double>(id)), s);
    const auto id = static_cast<std::uint64_t>(100 + k);
    ASSERT_TRUE(takeIntoMembers(members, evaluated(id, 10.0), s));
    double sum = 0;
    for (const Individual& i : members.individuals)
      sum += i.fitness();
    replaced[1 + 2 + 3 + 4 + 10 - sum] += 1;  // the fitness that left
  }
  const double expected[] = {7.0 / 16, 5.0 / 16, 3.0 / 16, 1.0 / 16};
  for (int r = 0; r < 4; ++r)
    EXPECT_NEAR(replaced[1.0 + r] / static_cast<double>(draws), expected[r], 0.03) << "rank " << r;
}

TEST(TakeIntoMembers, IsAPureFunctionOfMembersResultAndSettings) {
  const EvolutionSettings s = settingsOf(5, 3);
  auto run = [&] {
    Population members;
    for (std::uint64_t id = 0; id < 40; ++id)
      takeIntoMembers(members, evaluated(id, static_cast<double>((id * 7) % 11)), s);
    return idsOf(members);
  };
  EXPECT_EQ(run(), run());
}

// members of random genomes with fitnesses, as a steady state holds them
Population randomMembers(Breeder& breeder, int count) {
  Population members = breeder.initialPopulation();
  members.individuals.resize(static_cast<std::size_t>(count));
  for (Individual& i : members.individuals) {
    i.outcome.fitness = static_cast<double>(i.id % 5);
    i.evaluated = true;
  }
  return members;
}

TEST(SteadyChild, IsAPureFunctionOfTheMembersAndItsId) {
  EvolutionSettings s = settingsOf(12, 2);
  Breeder a(s, kEncoding), b(s, kEncoding);
  Population members = randomMembers(a, 12);
  randomMembers(b, 12);
  members.generation = 3;
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
  Population members = randomMembers(breeder, 12);
  std::map<Origin, int> made;
  const int children = 2000;
  for (int k = 0; k < children; ++k) {
    Individual child = breeder.steadyChild(members, 0);
    made[child.origin] += 1;
    ASSERT_EQ(child.parents.size(), child.origin == Origin::mutation ? 1u : 2u);
    for (std::uint64_t parent : child.parents)
      ASSERT_NO_THROW(members.indexOf(parent)) << "parent " << parent << " is not a member";
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
  Population members = randomMembers(breeder, 12);
  for (std::size_t i = 0; i < members.individuals.size(); ++i)
    members.individuals[i].outcome.fitness = static_cast<double>(i);
  for (int k = 0; k < 200; ++k) {
    for (std::uint64_t parent : breeder.steadyChild(members, 0).parents)
      EXPECT_GE(parent, 9u);
  }
}

TEST(SteadyChild, RefusesToBreedFromNoMembers) {
  Breeder breeder(settingsOf(4, 2), kEncoding);
  EXPECT_THROW(breeder.steadyChild(Population{}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace cambrian
