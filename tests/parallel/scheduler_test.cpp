#include "parallel/scheduler.hpp"

#include "evolution/breeder.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

Population smallPopulation() {
  EvolutionSettings settings;
  settings.population = 12;
  Breeder breeder(settings, GenomeLimits{});
  return breeder.initialPopulation();
}

TEST(Scheduler, LongestExpectedFirstTiesById) {
  Population p = smallPopulation();
  p.individuals[3].evaluated = true;
  std::vector<std::size_t> order = schedulingOrder(p);
  EXPECT_EQ(order.size(), 11u);
  auto size = [&](std::size_t i) {
    return p.individuals[i].genome.nodes.size() + p.individuals[i].genome.connections.size();
  };
  for (std::size_t k = 1; k < order.size(); ++k) {
    EXPECT_TRUE(size(order[k - 1]) > size(order[k]) ||
                (size(order[k - 1]) == size(order[k]) && order[k - 1] < order[k]));
    EXPECT_NE(order[k], 3u);
  }
}

TEST(Scheduler, EvaluationSeedIsAPureFunctionOfSeedAndId) {
  EXPECT_EQ(evaluationSeed(1, 5), evaluationSeed(1, 5));
  EXPECT_NE(evaluationSeed(1, 5), evaluationSeed(1, 6));
  EXPECT_NE(evaluationSeed(1, 5), evaluationSeed(2, 5));
}

TEST(Scheduler, InProcessEvaluatorFillsOnlyTheMissingOutcomes) {
  WorkerSettings settings;
  settings.task.kind = TaskKind::synthetic;
  settings.task.synthetic_cost_us = 50;
  InProcessEvaluator evaluator(settings);
  Population p = smallPopulation();
  p.individuals[0].evaluated = true;
  p.individuals[0].outcome.fitness = 123;
  EvaluationSpan span = evaluator.evaluate(p, 1);
  EXPECT_EQ(span.evaluations, 11u);
  EXPECT_TRUE(p.allEvaluated());
  EXPECT_EQ(p.individuals[0].outcome.fitness, 123);
  EXPECT_EQ(p.individuals[1].worker_rank, 0);
  EXPECT_GT(span.busy_seconds, 0);
}

}  // namespace
}  // namespace cambrian
