#include "evolution/generation_record.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace cambrian {
namespace {

// an individual with a one-node genome of `density`
Individual someone(std::uint64_t id, double fitness, double density = 1000) {
  Individual individual;
  individual.id = id;
  graph::Genome genome;
  genome.nodes.resize(1);
  genome.nodes[0].density = density;
  individual.genome = graph::makeGenotype(genome);
  individual.outcome.fitness = fitness;
  individual.evaluated = true;
  return individual;
}

TEST(RunDigest, DependsOnIdsGenomesAndFitnessButNotTimings) {
  RunDigest a, b, c, d;
  Individual x = someone(1, 0.5);
  a.add(x);
  x.eval_seconds = 3;
  x.worker_rank = 4;
  b.add(x);
  EXPECT_EQ(a.value(), b.value());
  c.add(someone(1, 0.5000000001));
  EXPECT_NE(a.value(), c.value());
  d.add(someone(1, 0.5, 900));
  EXPECT_NE(a.value(), d.value());
  EXPECT_EQ(a.hex().size(), 16u);
}

TEST(GenerationRecord, Utilisation) {
  GenerationRecord r;
  r.workers = 2;
  r.evaluations = 10;
  r.evaluation_span_seconds = 1;
  r.worker_busy_seconds = 1.5;
  EXPECT_DOUBLE_EQ(r.utilisation(), 0.75);
  EXPECT_DOUBLE_EQ(r.evaluationsPerSecond(), 10);
  r.evaluation_span_seconds = 0;
  EXPECT_EQ(r.utilisation(), 0.0);
  EXPECT_EQ(r.evaluationsPerSecond(), 0.0);
}

// the digest is FNV-1a over (id, genome size, genome bytes, fitness bits) per individual
TEST(RunDigest, IsTheDocumentedHash) {
  Individual x = someone(3, 0.25);
  RunDigest digest;
  digest.add(x);
  Fnv1a expected;
  expected.addWord(3);
  expected.addWord(x.genomeBytes().size());
  expected.add(x.genomeBytes().data(), x.genomeBytes().size());
  double fitness = 0.25;
  std::uint64_t bits;
  std::memcpy(&bits, &fitness, sizeof bits);
  expected.addWord(bits);
  EXPECT_EQ(digest.value(), expected.value());
  // continuing from a saved value is the same as adding in one go
  RunDigest resumed(digest.value());
  resumed.add(someone(4, 1.5));
  digest.add(someone(4, 1.5));
  EXPECT_EQ(resumed.value(), digest.value());
}

TEST(GenerationRecord, DistinctGenomesCountsByteStrings) {
  Population p;
  p.individuals = {someone(1, 0), someone(2, 0), someone(3, 0, 900)};
  EXPECT_EQ(distinctGenomes(p), 2u);
}

}  // namespace
}  // namespace cambrian
