// Tests of outcome reuse: copies of a parent's genome take its outcome, copies of a sibling
// wait for the sibling's, a timed-out parent is evaluated again, other genomes are left alone.
#include "evolution/outcome_reuse.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

// an individual with a one-node genome of `density`, evaluated to `fitness` when given
Individual someone(std::uint64_t id, double density, double fitness = -1) {
  Individual individual;
  individual.id = id;
  graph::Genome genome;
  genome.nodes.resize(1);
  genome.nodes[0].density = density;
  individual.genome = graph::makeGenotype(genome);
  if (fitness >= 0) {
    individual.outcome.fitness = fitness;
    individual.outcome.steps = 42;
    individual.outcome.measures = {{"distance", fitness}};
    individual.evaluated = true;
    individual.eval_seconds = 0.5;
    individual.worker_rank = 1;
  }
  return individual;
}

TEST(OutcomeReuse, ACopyOfAParentTakesItsOutcomeAndIsNotEvaluated) {
  Population parents;
  parents.individuals = {someone(1, 1000, 2.5), someone(2, 900, 1.5)};
  Population children;
  children.individuals = {someone(3, 900), someone(4, 800)};
  OutcomeReuse reuse = reuseKnownOutcomes(children, &parents);
  EXPECT_EQ(reuse.from_parents, 1u);
  EXPECT_TRUE(reuse.siblings.empty());
  const Individual& copy = children.individuals[0];
  EXPECT_TRUE(copy.evaluated);
  EXPECT_EQ(copy.outcome.fitness, 1.5);
  EXPECT_EQ(copy.outcome.steps, 42u);
  ASSERT_EQ(copy.outcome.measures.size(), 1u);
  EXPECT_EQ(copy.outcome.measures[0].value, 1.5);
  EXPECT_EQ(copy.eval_seconds, 0);  // not simulated: no time, no rank
  EXPECT_EQ(copy.worker_rank, -1);
  EXPECT_FALSE(children.individuals[1].evaluated);  // another genome: evaluated as usual
}

TEST(OutcomeReuse, ATimedOutParentIsNotReused) {
  Population parents;
  parents.individuals = {someone(1, 1000, 0)};
  parents.individuals[0].outcome.status = EvalStatus::timeout;
  Population children;
  children.individuals = {someone(2, 1000)};
  OutcomeReuse reuse = reuseKnownOutcomes(children, &parents);
  EXPECT_EQ(reuse.from_parents, 0u);
  EXPECT_FALSE(children.individuals[0].evaluated);
}

TEST(OutcomeReuse, CopiesOfASiblingWaitForItsOutcome) {
  Population generation;
  generation.individuals = {someone(1, 700), someone(2, 600), someone(3, 700), someone(4, 700)};
  OutcomeReuse reuse = reuseKnownOutcomes(generation, nullptr);
  EXPECT_EQ(reuse.from_parents, 0u);
  using Pair = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(reuse.siblings, (std::vector<Pair>{{2, 0}, {3, 0}}));
  // the first of a genome and other genomes are handed out, the copies not
  EXPECT_FALSE(generation.individuals[0].evaluated);
  EXPECT_FALSE(generation.individuals[1].evaluated);
  EXPECT_TRUE(generation.individuals[2].evaluated);
  EXPECT_TRUE(generation.individuals[3].evaluated);

  // the evaluation, then the copies
  generation.individuals[0] = someone(1, 700, 3.25);
  generation.individuals[1] = someone(2, 600, 1.0);
  copySiblingOutcomes(generation, reuse);
  for (std::size_t i : {2u, 3u}) {
    EXPECT_EQ(generation.individuals[i].outcome.fitness, 3.25);
    EXPECT_EQ(generation.individuals[i].worker_rank, -1);
    EXPECT_EQ(generation.individuals[i].eval_seconds, 0);
    EXPECT_EQ(generation.individuals[i].id, i + 1);  // still themselves
  }
}

TEST(OutcomeReuse, EvaluatedIndividualsAreLeftAlone) {
  // elites carry their own outcome already, even when a parent has the same genome
  Population parents;
  parents.individuals = {someone(1, 1000, 2.5)};
  Population children;
  children.individuals = {someone(2, 1000, 2.5)};
  children.individuals[0].worker_rank = -1;
  children.individuals[0].eval_seconds = 0;
  OutcomeReuse reuse = reuseKnownOutcomes(children, &parents);
  EXPECT_EQ(reuse.from_parents, 0u);
  EXPECT_TRUE(reuse.siblings.empty());
}

}  // namespace
}  // namespace cambrian
