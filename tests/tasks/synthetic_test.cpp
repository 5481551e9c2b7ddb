// Tests of the synthetic task: its fitness from the genome's sizes, its cost laws, the work it
// really does.
#include "tasks/synthetic.hpp"

#include "cambrian/rng.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace cambrian {
namespace {

using graph::Genome;

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

// the sizes of a directed-graph genome, as the encoding reports them
GenomeSize sizeOf(const Genome& genome) {
  return graph::DirectedGraphEncoding().size(graph::makeGenotype(genome));
}

double syntheticFitness(const Genome& genome) {
  return SyntheticTask::fitness(sizeOf(genome));
}

double syntheticCostMicroseconds(const Genome& genome, const SyntheticTask& task,
                                 std::uint64_t seed) {
  return task.costMicroseconds(sizeOf(genome), seed);
}

Outcome evaluateSynthetic(const Genome& genome, const SyntheticTask& task, std::uint64_t seed) {
  return task.evaluateGenome(graph::makeGenotype(genome), graph::DirectedGraphEncoding(), seed);
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
  SyntheticTask task;
  task.cost_us = 1000;
  task.cost_per_gene_us = 100;
  task.noise = 0.5;
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
  task.noise = 0;
  EXPECT_EQ(syntheticCostMicroseconds(genome, task, 3), 1200.0);
}

// mean and standard deviation of a sample
struct Moments {
  double mean = 0, sd = 0;
};
Moments momentsOf(const std::vector<double>& xs) {
  Moments m;
  for (double x : xs)
    m.mean += x;
  m.mean /= static_cast<double>(xs.size());
  for (double x : xs)
    m.sd += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(m.sd / static_cast<double>(xs.size() - 1));
  return m;
}

// the costs of `genome` under `task` for eval seeds 0..n-1
std::vector<double> costs(const Genome& genome, const SyntheticTask& task, std::uint64_t n) {
  std::vector<double> xs;
  for (std::uint64_t seed = 0; seed < n; ++seed)
    xs.push_back(syntheticCostMicroseconds(genome, task, seed));
  return xs;
}

TEST(SyntheticTask, UniformIsTheDefaultAndKeepsItsFormula) {
  SyntheticTask task;
  EXPECT_EQ(task.distribution, SyntheticDistribution::uniform);
  task.cost_us = 1000;
  task.cost_per_gene_us = 100;
  task.noise = 0.4;
  // bit for bit the first uniform of the creature's evaluation stream, as before
  for (std::uint64_t seed : {0ull, 1ull, 77ull, 123456789ull}) {
    Rng rng(seed, RngPurpose::evaluation);
    double expected = 1200.0 * (1 + 0.4 * (2 * rng.uniform() - 1));
    EXPECT_EQ(syntheticCostMicroseconds(twoNodes(), task, seed), expected) << "seed " << seed;
  }
}

TEST(SyntheticTask, LognormalHasTheMeanCostAndTheCoefficientOfVariation) {
  SyntheticTask task;
  task.distribution = SyntheticDistribution::lognormal;
  task.cost_us = 1000;
  task.cost_per_gene_us = 100;
  task.noise = 0.9;  // ignored by lognormal
  for (double cv : {0.25, 0.5, 1.5}) {
    task.cv = cv;
    std::vector<double> xs = costs(twoNodes(), task, 40000);
    Moments m = momentsOf(xs);
    // sample mean and CV near the settings (4 standard errors of the mean; the CV's error
    // grows with the tail: about 0.5 % at CV 0.5, 3 % at 1.5)
    double n = static_cast<double>(xs.size());
    EXPECT_NEAR(m.mean / 1200, 1, 4 * cv / std::sqrt(n)) << "cv " << cv;
    EXPECT_NEAR(m.sd / m.mean / cv, 1, cv < 1 ? 0.03 : 0.12) << "cv " << cv;
    // and lognormal in shape: ln(cost / mean) is normal with mean -s^2/2 and sd s
    double s2 = std::log(1 + cv * cv);
    std::vector<double> logs;
    for (double x : xs) {
      ASSERT_GT(x, 0);
      logs.push_back(std::log(x / 1200));
    }
    Moments l = momentsOf(logs);
    EXPECT_NEAR(l.mean, -s2 / 2, 4 * std::sqrt(s2 / n)) << "cv " << cv;
    EXPECT_NEAR(l.sd / std::sqrt(s2), 1, 4 / std::sqrt(2 * n)) << "cv " << cv;
  }
}

TEST(SyntheticTask, EveryDistributionIsDeterministicPerSeed) {
  SyntheticTask task;
  task.cost_us = 500;
  task.noise = 0.3;
  for (SyntheticDistribution d : {SyntheticDistribution::uniform, SyntheticDistribution::lognormal,
                                  SyntheticDistribution::fixed}) {
    task.distribution = d;
    // the same seed twice gives the same bits
    std::vector<double> a = costs(twoNodes(), task, 200), b = costs(twoNodes(), task, 200);
    EXPECT_EQ(a, b);
    // and the outcome's cost measure is that cost
    Outcome outcome = evaluateSynthetic(twoNodes(), task, 17);
    EXPECT_EQ(outcome.measure("cost_us"), syntheticCostMicroseconds(twoNodes(), task, 17));
  }
  // different seeds differ where the law has a spread
  task.distribution = SyntheticDistribution::lognormal;
  std::vector<double> xs = costs(twoNodes(), task, 50);
  EXPECT_NE(momentsOf(xs).sd, 0);
}

TEST(SyntheticTask, FixedHasNoSpread) {
  SyntheticTask task;
  task.distribution = SyntheticDistribution::fixed;
  task.cost_us = 1000;
  task.cost_per_gene_us = 100;
  task.noise = 0.5;  // ignored by fixed
  task.cv = 2;       // ignored by fixed
  for (double x : costs(twoNodes(), task, 500))
    EXPECT_EQ(x, 1200.0);
}

TEST(SyntheticTask, LognormalWithoutVariationIsTheMeanCost) {
  SyntheticTask task;
  task.distribution = SyntheticDistribution::lognormal;
  task.cost_us = 800;
  task.cv = 0;
  for (double x : costs(twoNodes(), task, 100))
    EXPECT_EQ(x, 800.0);
}

TEST(SyntheticTask, SpendsAtLeastItsCostAndReportsIt) {
  SyntheticTask task;
  task.cost_us = 3000;
  auto start = std::chrono::steady_clock::now();
  Outcome outcome = evaluateSynthetic(twoNodes(), task, 1);
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(outcome.status, EvalStatus::ok);
  EXPECT_GE(elapsed, 0.003);
  EXPECT_GE(outcome.wall_seconds, 0.003);
  EXPECT_EQ(outcome.measure("cost_us"), 3000.0);
  EXPECT_DOUBLE_EQ(outcome.fitness, syntheticFitness(twoNodes()));
}

// asleep instead of spinning: the same outcome, and at least the cost spent
TEST(SyntheticTask, SleepingSpendsItsCostWithTheSameOutcome) {
  SyntheticTask spinning, sleeping;
  spinning.cost_us = sleeping.cost_us = 2000;
  sleeping.work = SyntheticWork::sleep;
  Outcome spun = evaluateSynthetic(twoNodes(), spinning, 4);
  Outcome slept = evaluateSynthetic(twoNodes(), sleeping, 4);
  EXPECT_GE(slept.wall_seconds, 0.002);
  EXPECT_EQ(slept.fitness, spun.fitness);
  EXPECT_EQ(slept.measures, spun.measures);
  EXPECT_EQ(slept.status, EvalStatus::ok);
}

TEST(SyntheticTask, OutcomeApartFromWallTimeIsDeterministic) {
  SyntheticTask task;
  task.cost_us = 200;
  task.noise = 0.3;
  Outcome a = evaluateSynthetic(twoNodes(), task, 9), b = evaluateSynthetic(twoNodes(), task, 9);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_EQ(a.measures, b.measures);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.parts, 2);
}

// the task declares its measures and needs no body
TEST(SyntheticTask, DeclaresItsMeasures) {
  SyntheticTask task;
  EXPECT_FALSE(task.needsBody());
  std::vector<MeasureInfo> measures = task.measures();
  ASSERT_EQ(measures.size(), 2u);
  EXPECT_EQ(measures[0].name, "cost_us");
  EXPECT_EQ(measures[1].name, "nodes");
  Outcome outcome = evaluateSynthetic(twoNodes(), task, 3);
  for (const Measure& measure : outcome.measures)
    EXPECT_NE(std::find(measures.begin(), measures.end(),
                        MeasureInfo{measure.name, measure.name == "cost_us" ? "us" : "1"}),
              measures.end());
}

}  // namespace
}  // namespace cambrian
