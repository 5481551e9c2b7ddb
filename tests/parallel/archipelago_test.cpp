// Tests of the islands' migrations over MPI, at every rank count CTest gives them
// (archipelago_np_N; one island per rank, each on a communicator of its own per test): batches
// travel along the ring and arrive one interval later, a target's checkpoint trims the sender's
// outbox, a resume sends the outbox again and a batch that arrives twice is taken in once, an
// island whose migrants a neighbour no longer holds is refused, bad checkpoint bytes are an
// error.
#include "parallel/archipelago.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "core/bytes.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace cambrian {

extern MpiContext* world;  // the job's context (mpi_test_main.cpp)

namespace {

// island `island`'s generation g: three individuals, ids 1000 island + 10 g + k, fitness k (so
// its best is k = 2)
Population generationOf(int island, std::uint64_t g) {
  Population population;
  population.generation = g;
  for (std::uint64_t k = 0; k < 3; ++k) {
    Individual individual;
    individual.id = 1000 * static_cast<std::uint64_t>(island) + 10 * g + k;
    individual.generation = g;
    individual.genome = decodeGenome(graph::serializeGenome(
        graph::randomGenome(graph::GenomeLimits{}, individual.id + 1, g, k)));
    individual.outcome.fitness = static_cast<double>(k);
    individual.evaluated = true;
    population.individuals.push_back(std::move(individual));
  }
  return population;
}

std::uint64_t bestId(int island, std::uint64_t g) {
  return 1000 * static_cast<std::uint64_t>(island) + 10 * g + 2;
}

// every island trading its best one every `interval` generations along a ring
MigrationSettings ring(int islands, int interval) {
  MigrationSettings settings;
  settings.islands = islands;
  settings.interval = interval;
  settings.migrants = 1;
  settings.topology = MigrationTopology::ring;
  return settings;
}

// the (event, target) pairs an outbox holds (Archipelago::checkpointState's layout)
std::vector<std::pair<std::uint64_t, int>> outboxOf(const std::vector<std::uint8_t>& state) {
  std::vector<std::pair<std::uint64_t, int>> entries;
  ByteReader r(state.data(), state.size(), "state");
  EXPECT_EQ(r.u64(), 1u);
  const std::uint64_t count = r.u64();
  for (std::uint64_t k = 0; k < count; ++k) {
    const int target = static_cast<int>(r.u64());
    std::uint64_t event = 0;
    int source = -1;
    decodeMigrants(r.blob(), event, source);
    EXPECT_EQ(source, world->rank());
    entries.emplace_back(event, target);
  }
  return entries;
}

TEST(Archipelago, MigrantsRoundTripAndBadBytesAreRefused) {
  Population population = generationOf(3, 4);
  std::vector<std::uint8_t> bytes =
      encodeMigrants(4, 3, {&population.individuals[2], &population.individuals[0]});
  std::uint64_t event = 0;
  int source = -1;
  std::vector<Individual> back = decodeMigrants(bytes, event, source);
  EXPECT_EQ(event, 4u);
  EXPECT_EQ(source, 3);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].id, population.individuals[2].id);
  EXPECT_EQ(back[0].genomeBytes(), population.individuals[2].genomeBytes());
  EXPECT_EQ(back[0].outcome.fitness, 2.0);
  EXPECT_TRUE(back[1].evaluated);
  bytes.resize(bytes.size() - 3);
  EXPECT_THROW(decodeMigrants(bytes, event, source), InputError);
}

TEST(Archipelago, BatchesArriveOneIntervalLaterFromTheIslandBefore) {
  std::unique_ptr<MpiContext> breeders = world->split(0);
  const int islands = breeders->size(), island = breeders->rank();
  Archipelago archipelago(*breeders, ring(islands, 1), 7);
  for (std::uint64_t g = 0; g < 4; ++g) {
    std::optional<std::vector<Individual>> immigrants =
        archipelago.exchange(generationOf(island, g));
    ASSERT_TRUE(immigrants);
    if (islands == 1 || g == 0) {
      EXPECT_TRUE(immigrants->empty());
      continue;
    }
    // the best of the island before, from the generation before
    ASSERT_EQ(immigrants->size(), 1u);
    EXPECT_EQ(immigrants->front().id, bestId((island + islands - 1) % islands, g - 1));
  }
  archipelago.close();
}

TEST(Archipelago, ATargetsCheckpointTrimsTheSendersOutbox) {
  if (world->size() < 2)
    GTEST_SKIP() << "needs two islands";
  std::unique_ptr<MpiContext> breeders = world->split(0);
  const int islands = breeders->size(), island = breeders->rank();
  Archipelago archipelago(*breeders, ring(islands, 1), 7);
  for (std::uint64_t g = 0; g < 4; ++g)
    ASSERT_TRUE(archipelago.exchange(generationOf(island, g)));
  // every batch sent is kept: events 0..3 to the next island
  std::vector<std::pair<std::uint64_t, int>> kept = outboxOf(archipelago.checkpointState());
  EXPECT_EQ(kept.size(), 4u);
  EXPECT_EQ(kept.front(), std::make_pair(std::uint64_t{0}, (island + 1) % islands));
  // (every island has looked before any says it no longer needs them)
  breeders->allReduceMax(0);
  // a checkpoint of generations 0..3: a resume from it takes in event 2 first (after generation
  // 3, interval 1); the others learn it at the next exchange and drop events 0 and 1
  archipelago.checkpointed(4);
  ASSERT_TRUE(archipelago.exchange(generationOf(island, 4)));
  archipelago.close();
  kept = outboxOf(archipelago.checkpointState());
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept.front().first, 2u);
  EXPECT_EQ(kept.back().first, 4u);
}

TEST(Archipelago, AResumeSendsTheOutboxAgainAndARepeatedBatchIsTakenInOnce) {
  if (world->size() < 2)
    GTEST_SKIP() << "needs two islands";
  const int islands = world->size(), island = world->rank();
  std::vector<std::uint8_t> state;
  std::vector<Individual> first;
  {
    // the run before: generations 0..2, its job ending with every batch sent here drained and
    // none taken in after generation 2
    std::unique_ptr<MpiContext> breeders = world->split(0);
    Archipelago before(*breeders, ring(islands, 1), 7);
    for (std::uint64_t g = 0; g < 3; ++g) {
      std::optional<std::vector<Individual>> immigrants = before.exchange(generationOf(island, g));
      ASSERT_TRUE(immigrants);
      if (g == 2)
        first = std::move(*immigrants);
    }
    before.close();
    state = before.checkpointState();
  }
  // the resumed run, from the checkpoint after generation 1: the outbox goes out again (events
  // 0..2), generation 1's exchange again takes in event 0, generation 2's event 1
  std::unique_ptr<MpiContext> breeders = world->split(0);
  Archipelago after(*breeders, ring(islands, 1), 7);
  after.resume(state);
  std::optional<std::vector<Individual>> again = after.exchange(generationOf(island, 1));
  ASSERT_TRUE(again);
  ASSERT_EQ(again->size(), 1u);
  EXPECT_EQ(again->front().id, bestId((island + islands - 1) % islands, 0));
  again = after.exchange(generationOf(island, 2));
  ASSERT_TRUE(again);
  ASSERT_EQ(again->size(), 1u);
  EXPECT_EQ(again->front().id, first.front().id);
  EXPECT_EQ(again->front().genomeBytes(), first.front().genomeBytes());
  // generation 2's batch went out once: the outbox held it already
  after.close();
  EXPECT_EQ(outboxOf(after.checkpointState()).size(), 3u);
}

TEST(Archipelago, AnIslandWhoseMigrantsAreGoneIsRefused) {
  if (world->size() < 2)
    GTEST_SKIP() << "needs two islands";
  const int islands = world->size(), island = world->rank();
  std::vector<std::uint8_t> state;
  {
    // generations 0..4; after a checkpoint of 0..3 every island drops events 0 and 1
    std::unique_ptr<MpiContext> breeders = world->split(0);
    Archipelago before(*breeders, ring(islands, 1), 7);
    for (std::uint64_t g = 0; g < 4; ++g)
      ASSERT_TRUE(before.exchange(generationOf(island, g)));
    before.checkpointed(4);
    ASSERT_TRUE(before.exchange(generationOf(island, 4)));
    before.close();
    state = before.checkpointState();
  }
  std::unique_ptr<MpiContext> breeders = world->split(0);
  Archipelago after(*breeders, ring(islands, 1), 7);
  after.resume(state);
  // every island from its newest checkpoint (generation 5)
  EXPECT_NO_THROW(after.start(5, "out"));
  // island 1 put back to an older checkpoint: only island 0, its source, misses what it would
  // take in first (from generation 2, event 0; afresh, event 0; from 4, event 2: kept)
  const std::string here = "out/island_" + std::to_string(island);
  std::vector<std::uint64_t> starts(static_cast<std::size_t>(islands), 5);
  starts[1] = 2;
  std::string message = after.missingFor(starts, here);
  EXPECT_EQ(message.empty(), island != 0) << message;
  if (island == 0) {
    EXPECT_NE(message.find("island 1 continues from generation 2"), std::string::npos) << message;
    EXPECT_NE(message.find("island 0 (out/island_0"), std::string::npos) << message;
    EXPECT_NE(message.find("after generation 0"), std::string::npos) << message;
  }
  starts[1] = 0;
  EXPECT_EQ(after.missingFor(starts, here).empty(), island != 0);
  starts[1] = 4;
  EXPECT_TRUE(after.missingFor(starts, here).empty());
  after.close();
}

TEST(Archipelago, BadCheckpointBytesAreACheckpointError) {
  std::unique_ptr<MpiContext> breeders = world->split(0);
  Archipelago archipelago(*breeders, ring(breeders->size(), 1), 7);
  auto codeOf = [&](const std::vector<std::uint8_t>& state) {
    try {
      archipelago.resume(state);
    } catch (const Error& e) {
      return e.code();
    }
    return ExitCode::ok;
  };
  EXPECT_EQ(codeOf({1, 2, 3}), ExitCode::checkpoint);
  // a batch for this island itself
  std::vector<std::uint8_t> state;
  ByteWriter w(state);
  w.u64(1);
  w.u64(1);
  w.u64(static_cast<std::uint64_t>(breeders->rank()));
  Population population = generationOf(0, 0);
  const std::vector<std::uint8_t> batch = encodeMigrants(0, 0, {&population.individuals[0]});
  w.blob(batch.data(), batch.size());
  EXPECT_EQ(codeOf(state), ExitCode::checkpoint);
  // nothing: a checkpoint written without islands
  EXPECT_EQ(codeOf({}), ExitCode::ok);
}

}  // namespace
}  // namespace cambrian
