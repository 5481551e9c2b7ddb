#include "tasks/synthetic.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace cambrian {
namespace {

// a small genome with known sizes
Genome twoNodes() {
  Genome genome;
  genome.nodes.resize(2);
  genome.nodes[0].dimensions = {0.3, 0.3, 0.3};
  genome.nodes[1].dimensions = {0.6, 0.3, 0.0};
  genome.connections.resize(1);
  genome.connections[0].to = 1;
  return genome;
}

TEST(SyntheticTask, FitnessIsMeanSidePerNodePlusConnectionBonus) {
  EXPECT_DOUBLE_EQ(syntheticFitness(twoNodes()), 0.3 + 0.3 + 0.1);
  EXPECT_EQ(syntheticFitness(Genome{}), 0.0);
}

TEST(SyntheticTask, BiggerBoxesScoreHigher) {
  Genome bigger = twoNodes();
  bigger.nodes[0].dimensions.x = 0.9;
  EXPECT_GT(syntheticFitness(bigger), syntheticFitness(twoNodes()));
}

TEST(SyntheticTask, CostIsDeterministicAndWithinTheNoiseBand) {
  TaskSettings task;
  task.synthetic_cost_us = 1000;
  task.synthetic_cost_per_gene_us = 100;
  task.synthetic_noise = 0.5;
  Genome genome = twoNodes();
  bool differs = false;
  double first = syntheticCostMicroseconds(genome, task, 0);
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    double cost = syntheticCostMicroseconds(genome, task, seed);
    EXPECT_EQ(cost, syntheticCostMicroseconds(genome, task, seed));
    EXPECT_GE(cost, 1200 * 0.5);
    EXPECT_LE(cost, 1200 * 1.5);
    differs = differs || cost != first;
  }
  EXPECT_TRUE(differs);
  task.synthetic_noise = 0;
  EXPECT_EQ(syntheticCostMicroseconds(genome, task, 3), 1200.0);
}

TEST(SyntheticTask, SpendsAtLeastItsCostAndReportsIt) {
  TaskSettings task;
  task.kind = TaskKind::synthetic;
  task.synthetic_cost_us = 3000;
  auto start = std::chrono::steady_clock::now();
  Outcome outcome = evaluateSynthetic(twoNodes(), task, 1);
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(outcome.status, EvalStatus::ok);
  EXPECT_GE(elapsed, 0.003);
  EXPECT_GE(outcome.wall_seconds, 0.003);
  EXPECT_EQ(outcome.measure("cost_us"), 3000.0);
  EXPECT_DOUBLE_EQ(outcome.fitness, syntheticFitness(twoNodes()));
}

TEST(SyntheticTask, OutcomeApartFromWallTimeIsDeterministic) {
  TaskSettings task;
  task.kind = TaskKind::synthetic;
  task.synthetic_cost_us = 200;
  task.synthetic_noise = 0.3;
  Outcome a = evaluateSynthetic(twoNodes(), task, 9), b = evaluateSynthetic(twoNodes(), task, 9);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_EQ(a.measures, b.measures);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.parts, 2);
}

}  // namespace
}  // namespace cambrian
