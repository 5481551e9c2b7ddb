#include "parallel/scheduler.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "evolution/breeder.hpp"
#include "parallel/mpi_context.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace cambrian {
namespace {

Population smallPopulation() {
  EvolutionSettings settings;
  settings.population = 12;
  static const graph::DirectedGraphEncoding encoding;
  Breeder breeder(settings, encoding);
  return breeder.initialPopulation();
}

TEST(Scheduler, LongestExpectedFirstTiesById) {
  Population p = smallPopulation();
  p.individuals[3].evaluated = true;
  std::vector<std::size_t> order = schedulingOrder(p);
  EXPECT_EQ(order.size(), 11u);
  auto size = [&](std::size_t i) {
    const graph::Genome& g = graph::graphGenome(p.individuals[i].genome);
    return g.nodes.size() + g.connections.size();
  };
  for (std::size_t k = 1; k < order.size(); ++k) {
    EXPECT_TRUE(size(order[k - 1]) > size(order[k]) ||
                (size(order[k - 1]) == size(order[k]) && order[k - 1] < order[k]));
    EXPECT_NE(order[k], 3u);
  }
}

// genome nodes + connections of individual i
std::size_t sizeOf(const Population& p, std::size_t i) {
  const graph::Genome& g = graph::graphGenome(p.individuals[i].genome);
  return g.nodes.size() + g.connections.size();
}

// the indices of the pending individuals, sorted
std::vector<std::size_t> sorted(std::vector<std::size_t> order) {
  std::sort(order.begin(), order.end());
  return order;
}

// short creatures go in id order (their genomes made as they are handed out), long ones by size
TEST(Scheduler, ShortCreaturesGoInIdOrder) {
  Population p = smallPopulation();
  p.individuals[4].evaluated = true;
  std::vector<std::size_t> by_id = schedulingOrder(p, DispatchSettings{}, 0, 0.001);
  std::vector<std::size_t> expected = {0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11};
  EXPECT_EQ(by_id, expected);
  EXPECT_EQ(schedulingOrder(p, DispatchSettings{}, 0, 0.5), schedulingOrder(p));
  EXPECT_EQ(schedulingOrder(p, DispatchSettings{}, 0, 0), schedulingOrder(p));
  DispatchSettings shuffled;
  shuffled.order = DispatchOrder::shuffled;
  EXPECT_EQ(schedulingOrder(p, shuffled, 3, 0.001), schedulingOrder(p, shuffled, 3));
}

// how deep each worker's queue is: enough work to cover rank 0's sleeps, never more than a share
// of what is left, one in the tail of long creatures
TEST(Scheduler, QueuesAreDeepForShortCreaturesAndShallowInTheTail) {
  const DispatchPace pace;
  // not known yet: two (one evaluated, one queued), one in the tail
  EXPECT_EQ(pace.held(0, 1000, 2), 2);
  EXPECT_EQ(pace.held(0, 7, 2), 1);
  // 10 ms creatures: the next one queued; 1 ms: four more; 100 us: 4 ms of work queued
  EXPECT_EQ(pace.held(0.010, 1000, 2), 2);
  EXPECT_EQ(pace.held(0.001, 1000, 2), 5);
  EXPECT_EQ(pace.held(0.0001, 1000, 2), 41);
  // 10 us: at most kMaxHeld
  EXPECT_EQ(pace.held(0.00001, 100000, 2), DispatchPace::kMaxHeld);
  // a share of what is left: 1 + remaining / (4 x workers)
  EXPECT_EQ(pace.held(0.0001, 80, 2), 11);
  EXPECT_EQ(pace.held(0.0001, 80, 20), 2);
  // the tail: long creatures one at a time, short ones keep their next one queued
  EXPECT_EQ(pace.held(0.5, 3, 2), 1);
  EXPECT_EQ(pace.held(0.001, 3, 2), 2);
  EXPECT_EQ(pace.held(0.001, 0, 2), 2);
}

// rank 0 sleeps a quarter of the work queued behind each worker's current creature
TEST(Scheduler, RankZeroSleepsAQuarterOfTheQueuedWork) {
  const DispatchPace pace;
  EXPECT_EQ(pace.relaxedMicros(0.010, 2), 2500);
  EXPECT_EQ(pace.relaxedMicros(0.0001, 41), 1000);
  EXPECT_EQ(pace.relaxedMicros(0.0001, 3), DispatchPace::kMinRelaxedMicros);
  EXPECT_EQ(pace.relaxedMicros(10, 2), DispatchPace::kMaxRelaxedMicros);
  // nothing queued or nothing known: no relaxed sleep (rank 0 answers within a quarter of an
  // evaluation)
  EXPECT_EQ(pace.relaxedMicros(0.010, 1), 0);
  EXPECT_EQ(pace.relaxedMicros(0, 5), 0);
  EXPECT_EQ(Backoff::quarterOf(0.001), 250);
  EXPECT_EQ(Backoff::quarterOf(0.0001), Backoff::kMin);
  EXPECT_EQ(Backoff::quarterOf(1), Backoff::kMax);
  EXPECT_EQ(Backoff::quarterOf(0), Backoff::kMax);
}

TEST(Scheduler, LargestFirstIsTheDefault) {
  Population p = smallPopulation();
  EXPECT_EQ(DispatchSettings{}.order, DispatchOrder::largest_first);
  EXPECT_EQ(schedulingOrder(p, DispatchSettings{}, 7), schedulingOrder(p));
}

TEST(Scheduler, SmallestFirstTiesById) {
  Population p = smallPopulation();
  p.individuals[5].evaluated = true;
  std::vector<std::size_t> order =
      schedulingOrder(p, DispatchSettings{DispatchOrder::smallest_first, 0}, 1);
  EXPECT_EQ(order.size(), 11u);
  for (std::size_t k = 1; k < order.size(); ++k) {
    EXPECT_TRUE(sizeOf(p, order[k - 1]) < sizeOf(p, order[k]) ||
                (sizeOf(p, order[k - 1]) == sizeOf(p, order[k]) && order[k - 1] < order[k]));
  }
  // the same creatures as largest first, and (genomes of different sizes) not in its order
  EXPECT_EQ(sorted(order), sorted(schedulingOrder(p)));
  EXPECT_NE(order, schedulingOrder(p));
}

TEST(Scheduler, ShuffledIsASeededPermutationPerGeneration) {
  Population p = smallPopulation();
  p.individuals[2].evaluated = true;
  DispatchSettings shuffled{DispatchOrder::shuffled, 0};
  std::vector<std::size_t> order = schedulingOrder(p, shuffled, 5);
  // every pending individual once
  EXPECT_EQ(sorted(order), sorted(schedulingOrder(p)));
  // a pure function of seed and generation
  EXPECT_EQ(order, schedulingOrder(p, shuffled, 5));
  EXPECT_NE(order, schedulingOrder(p, shuffled, 6));
  // run.dispatch_seed, when given, instead of the run seed
  EXPECT_EQ(schedulingOrder(p, DispatchSettings{DispatchOrder::shuffled, 6}, 5),
            schedulingOrder(p, shuffled, 6));
  Population later = p;
  later.generation = 1;
  EXPECT_NE(order, schedulingOrder(later, shuffled, 5));
  // and not just the size order or the id order
  EXPECT_NE(order, schedulingOrder(p));
  EXPECT_NE(order, sorted(order));
}

TEST(Scheduler, ShuffledIsIndependentOfTheResults) {
  Population a = smallPopulation(), b = smallPopulation();
  // outcomes of evaluated individuals do not enter the order
  a.individuals[0].evaluated = b.individuals[0].evaluated = true;
  a.individuals[0].outcome.fitness = 1;
  b.individuals[0].outcome.fitness = 99;
  DispatchSettings shuffled{DispatchOrder::shuffled, 3};
  EXPECT_EQ(schedulingOrder(a, shuffled, 1), schedulingOrder(b, shuffled, 1));
}

TEST(Scheduler, DispatchOrderNamesAreRunOnlySettings) {
  DispatchSettings dispatch;
  SettingsSchema schema;
  dispatch.declareSettings(schema);
  schema.set("run.dispatch_order", "shuffled");
  EXPECT_EQ(dispatch.order, DispatchOrder::shuffled);
  schema.set("run.dispatch_order", "smallest_first");
  EXPECT_EQ(dispatch.order, DispatchOrder::smallest_first);
  schema.set("run.dispatch_seed", "12");
  EXPECT_EQ(dispatch.seed, 12u);
  EXPECT_EQ(schema.runOnlyKeys(),
            (std::set<std::string>{"run.dispatch_order", "run.dispatch_seed"}));
  try {
    schema.set("run.dispatch_order", "random");
    ADD_FAILURE() << "no ConfigError for 'random'";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("run.dispatch_order = random"), std::string::npos)
        << e.what();
  }
}

TEST(Scheduler, InProcessResultsDoNotDependOnTheDispatchOrder) {
  WorkerSettings settings;
  settings.creature.set("task.name", "synthetic");
  settings.creature.set("task.synthetic_cost_us", "20");
  settings.creature.set("task.synthetic_noise", "0.5");
  // the same outcomes, by id, whichever order evaluates them
  std::vector<Population> done;
  for (DispatchOrder order :
       {DispatchOrder::largest_first, DispatchOrder::shuffled, DispatchOrder::smallest_first}) {
    InProcessEvaluator evaluator(settings, DispatchSettings{order, 0});
    Population p = smallPopulation();
    evaluator.evaluate(p, 4);
    done.push_back(std::move(p));
  }
  for (const Population& p : done) {
    for (std::size_t i = 0; i < p.individuals.size(); ++i) {
      EXPECT_EQ(p.individuals[i].outcome.fitness, done[0].individuals[i].outcome.fitness);
      EXPECT_EQ(p.individuals[i].outcome.measures, done[0].individuals[i].outcome.measures);
    }
  }
}

TEST(Scheduler, InProcessEvaluatorFillsOnlyTheMissingOutcomes) {
  WorkerSettings settings;
  settings.creature.set("task.name", "synthetic");
  settings.creature.set("task.synthetic_cost_us", "50");
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

TEST(Scheduler, InProcessStreamAnswersInTheOrderSubmittedAsEvaluateWould) {
  WorkerSettings settings;
  settings.creature.set("task.name", "synthetic");
  settings.creature.set("task.synthetic_cost_us", "20");
  settings.creature.set("task.synthetic_noise", "0.5");
  InProcessEvaluator evaluator(settings);
  Population batch = smallPopulation();
  evaluator.evaluate(batch, 4);
  Population streamed = smallPopulation();
  EXPECT_EQ(evaluator.streamDepth(), 1u);
  for (std::size_t i : {3u, 1u, 7u})
    evaluator.submit(streamed.individuals[i], 4);
  EXPECT_EQ(evaluator.streaming(), 3u);
  for (std::size_t i : {3u, 1u, 7u}) {
    StreamedResult result = evaluator.take();
    EXPECT_EQ(result.id, streamed.individuals[i].id);
    EXPECT_EQ(result.rank, 0);
    EXPECT_EQ(result.outcome.fitness, batch.individuals[i].outcome.fitness);
    EXPECT_EQ(result.outcome.measures, batch.individuals[i].outcome.measures);
  }
  EXPECT_EQ(evaluator.streaming(), 0u);
  EXPECT_THROW(evaluator.take(), std::logic_error);
  evaluator.submit(streamed.individuals[0], 4);
  evaluator.discardStream();
  EXPECT_EQ(evaluator.streaming(), 0u);
}

}  // namespace
}  // namespace cambrian
