// Tests of genotypes: empty ones, shared data and bytes, equality by byte form, checked casts.
#include "cambrian/encoding.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

TEST(Genotype, EmptyHoldsNothing) {
  Genotype empty;
  EXPECT_FALSE(empty);
  EXPECT_THROW(empty.encoding(), Error);
  EXPECT_THROW(empty.data(), Error);
  EXPECT_TRUE(empty == Genotype());
}

TEST(Genotype, CopiesShareTheGenomeAndItsBytes) {
  Genotype a = graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 1));
  const std::vector<std::uint8_t>& bytes = a.bytes();
  Genotype b = a;
  EXPECT_EQ(&b.bytes(), &bytes);  // made once, kept
  EXPECT_EQ(&b.data(), &a.data());
  EXPECT_TRUE(a == b);
  // an equal genome made separately compares equal by its bytes
  Genotype c = graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 1));
  EXPECT_TRUE(a == c);
  Genotype d = graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 2));
  EXPECT_FALSE(a == d);
  EXPECT_FALSE(a == Genotype());
}

// a deferred genome: made by its recipe once, when first read, and shared by every copy
TEST(Genotype, ADeferredGenomeIsMadeOnceWhenFirstReadAndSharedByItsCopies) {
  static const graph::DirectedGraphEncoding encoding;
  int made = 0;
  Genotype deferred = Genotype::deferred(encoding, [&made] {
    ++made;
    return graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 1));
  });
  Genotype copy = deferred;
  EXPECT_TRUE(deferred);
  EXPECT_FALSE(deferred.made());
  EXPECT_EQ(&deferred.encoding(), &encoding);  // known before it is made
  EXPECT_EQ(made, 0);
  const std::vector<std::uint8_t>& bytes = copy.bytes();
  EXPECT_EQ(made, 1);
  EXPECT_TRUE(deferred.made());
  EXPECT_EQ(&deferred.bytes(), &bytes);
  EXPECT_EQ(&deferred.data(), &copy.data());
  EXPECT_EQ(made, 1);
  EXPECT_TRUE(deferred == graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 1)));
}

// a genome sent for evaluation is kept in its byte form alone and decoded again, the same, when
// next read (rank 0's memory for large populations)
TEST(Genotype, ADroppedDecodedGenomeIsDecodedAgainTheSame) {
  Genotype genome = graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 3, 0, 2));
  genome.dropDecoded();  // no byte form yet: the decoded genome stays (else data() would throw)
  const GenomeData* before = &genome.data();
  EXPECT_EQ(&genome.data(), before);
  const std::vector<std::uint8_t> bytes = genome.bytes();
  const graph::Genome decoded = genome.as<graph::GraphGenomeData>().genome;
  Genotype copy = genome;
  genome.dropDecoded();
  EXPECT_EQ(genome.bytes(), bytes);
  EXPECT_EQ(copy.as<graph::GraphGenomeData>().genome, decoded);  // the same genome
  EXPECT_EQ(&copy.data(), &genome.data());                       // copies share the decoding
  EXPECT_EQ(genome.encoding().toBytes(genome.data()), bytes);
}

// a recipe that makes a genome of another encoding is an error, said when it is read
TEST(Genotype, ADeferredGenomeOfAnotherEncodingIsRefused) {
  struct OtherEncoding : graph::DirectedGraphEncoding {
    std::array<char, 4> tag() const override { return {'o', 't', 'h', 'r'}; }
  };
  static const OtherEncoding other;
  Genotype deferred = Genotype::deferred(other, [] {
    return graph::makeGenotype(graph::randomGenome(graph::GenomeLimits{}, 2, 0, 1));
  });
  EXPECT_THROW(deferred.data(), Error);
}

TEST(Genotype, CastsAreChecked) {
  struct Other : GenomeData {};
  Genotype a = graph::makeGenotype(graph::Genome{});
  EXPECT_NO_THROW(a.as<graph::GraphGenomeData>());
  EXPECT_THROW(a.as<Other>(), GenomeError);
}

}  // namespace
}  // namespace cambrian
