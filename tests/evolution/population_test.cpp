#include "evolution/population.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

// a population whose fitnesses are given in id order
Population withFitness(const std::vector<double>& fitness) {
  Population p;
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    Individual individual;
    individual.id = 10 + i;
    individual.outcome.fitness = fitness[i];
    individual.evaluated = true;
    p.individuals.push_back(individual);
  }
  return p;
}

TEST(Population, RankingIsFitnessDescendingTiesById) {
  Population p = withFitness({1, 3, 3, 0.5, 3});
  EXPECT_EQ(p.ranking(), (std::vector<std::size_t>{1, 2, 4, 0, 3}));
}

TEST(Population, UnevaluatedAndNonFiniteCountAsWorst) {
  Population p = withFitness({1, std::nan(""), 2});
  p.individuals[2].evaluated = false;
  EXPECT_EQ(p.individuals[1].fitness(), kWorstFitness);
  EXPECT_EQ(p.individuals[2].fitness(), kWorstFitness);
  EXPECT_EQ(p.ranking().front(), 0u);
  EXPECT_FALSE(p.allEvaluated());
}

TEST(Population, IndexOfFindsIdsAndRejectsStrangers) {
  Population p = withFitness({1, 2, 3});
  EXPECT_EQ(p.indexOf(12), 2u);
  EXPECT_THROW(p.indexOf(99), std::out_of_range);
}

TEST(Population, OriginNames) {
  EXPECT_STREQ(originName(Origin::graft), "graft");
  EXPECT_STREQ(originName(Origin::elite), "elite");
}

}  // namespace
}  // namespace cambrian
