#include "evolution/statistics.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

TEST(Statistics, QuantilesInterpolate) {
  std::vector<double> v = {1, 2, 3, 4, 5};
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 3);
  EXPECT_DOUBLE_EQ(quantile(v, 0.25), 2);
  EXPECT_DOUBLE_EQ(quantile(v, 0.1), 1.4);
  EXPECT_DOUBLE_EQ(quantile(v, 1), 5);
  EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0);
}

TEST(Statistics, SummariseAPopulation) {
  Population p;
  double fitness[] = {4, 1, 3, 2};
  for (int i = 0; i < 4; ++i) {
    Individual individual;
    individual.id = static_cast<std::uint64_t>(i);
    individual.evaluated = true;
    individual.outcome.fitness = fitness[i];
    p.individuals.push_back(individual);
  }
  p.individuals[1].outcome.status = EvalStatus::exploded;
  p.individuals[1].outcome.fitness = kWorstFitness;
  FitnessStats s = computeStats(p);
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(s.failed, 1u);
  EXPECT_DOUBLE_EQ(s.best, 4);
  EXPECT_DOUBLE_EQ(s.worst, 0);
  EXPECT_DOUBLE_EQ(s.mean, 9.0 / 4);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_EQ(s.best_id, 0u);
}

}  // namespace
}  // namespace cambrian
