#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "encodings/directed_graph/catapult_limits.hpp"
#include "encodings/directed_graph/chaotic_limits.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <string>
#include <vector>

namespace cambrian::graph {
namespace {

// the message of the InputError that deserializing `bytes` throws, or "" if it succeeds
std::string failure(const std::vector<std::uint8_t>& bytes) {
  try {
    deserializeGenome(bytes.data(), bytes.size());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// bit-exact round trip on thousands of random genomes
TEST(SerializeGenome, RoundTripRandomGenomes) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 3000; ++i) {
    Genome genome = randomGenome(limits, 31, 0, i);
    std::vector<std::uint8_t> bytes = serializeGenome(genome);
    Genome back = deserializeGenome(bytes.data(), bytes.size());
    ASSERT_EQ(back, genome) << "individual " << i;
    EXPECT_EQ(serializeGenome(back), bytes);
  }
}

// lists longer than a gene holds inside itself (more than 3 inputs or effectors) round-trip too,
// and a genome of 6 inputs per neuron as a random one
TEST(SerializeGenome, LongListsRoundTrip) {
  GenomeLimits limits;
  limits.max_inputs = 6;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Genome genome = randomGenome(limits, 32, 0, i);
    std::vector<std::uint8_t> bytes = serializeGenome(genome);
    ASSERT_EQ(deserializeGenome(bytes.data(), bytes.size()), genome) << "individual " << i;
  }
  Genome g;
  g.nodes.resize(1);
  for (int k = 0; k < 7; ++k) {
    NeuronInput input;
    input.index = static_cast<std::uint16_t>(k);
    input.weight = 0.5 * k;
    g.nodes[0].effectors.push_back({input});
  }
  g.nodes[0].neurons.resize(1);
  g.nodes[0].neurons[0].inputs.assign(g.nodes[0].effectors.size(), NeuronInput{});
  g.nodes[0].neurons[0].inputs[6].weight = -1;
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  Genome back = deserializeGenome(bytes.data(), bytes.size());
  EXPECT_EQ(back, g);
  EXPECT_EQ(back.nodes[0].effectors[6].input.weight, 3.0);
  EXPECT_EQ(back.nodes[0].neurons[0].inputs.size(), 7u);
}

// doubles travel as their IEEE-754 bits, including the awkward ones
TEST(SerializeGenome, DoublesAreBitExact) {
  Genome g;
  g.nodes.resize(1);
  g.nodes[0].dimensions = {0.1, 1.0 / 3.0, -0.0};
  g.nodes[0].density = 5e-324;
  g.nodes[0].joint_limit = {std::numeric_limits<double>::infinity(), 1e308, -2.5};
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  Genome back = deserializeGenome(bytes.data(), bytes.size());
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back.nodes[0].dimensions[k]),
              std::bit_cast<std::uint64_t>(g.nodes[0].dimensions[k]));
  }
  EXPECT_EQ(back, g);
}

// the layout starts with the magic and the version, little-endian
TEST(SerializeGenome, HeaderLayout) {
  std::vector<std::uint8_t> bytes = serializeGenome(Genome{});
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(std::memcmp(bytes.data(), "CMBG", 4), 0);
  EXPECT_EQ(bytes[4], 1);  // no projectile: the oldest version that carries it
  EXPECT_EQ(bytes[5], 0);
  EXPECT_EQ(bytes[6], 0);
  EXPECT_EQ(bytes[7], 0);
  // an empty genome: header and three zero counts
  EXPECT_EQ(bytes.size(), 8u + 4 + 4 + 4);
}

// every truncation of a serialized genome throws InputError naming where it stopped
TEST(SerializeGenome, EveryPrefixThrows) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 20; ++i) {
    std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(limits, 41, 0, i));
    for (std::size_t size = 0; size < bytes.size(); ++size) {
      std::vector<std::uint8_t> prefix(bytes.begin(), bytes.begin() + static_cast<long>(size));
      std::string message = failure(prefix);
      ASSERT_NE(message, "") << "prefix " << size << " of " << bytes.size();
      EXPECT_NE(message.find("genome bytes"), std::string::npos) << message;
      if (size >= 8) {
        EXPECT_NE(message.find("truncated in"), std::string::npos) << message;
        EXPECT_NE(message.find("of " + std::to_string(size)), std::string::npos) << message;
      }
    }
  }
}

// the exact shape of the truncation messages: inside a field, and a count too large
TEST(SerializeGenome, TruncationMessageNamesFieldAndOffset) {
  Genome g;
  g.nodes.resize(3);
  for (int n = 0; n < 2; ++n)
    g.nodes[n].neurons.push_back({NeuronFunction::sum, {{}, {}, {}}, 0});
  g.nodes[2].neurons.resize(1);
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  const std::size_t node_bytes = 1 + 24 + 8 + 1 + 24 + 1 + 4 + 4;
  const std::size_t neuron_bytes = 1 + 8 + 4 + 3 * 13;

  // cut inside node 2's density (three of its eight bytes present)
  std::size_t density = 8 + 4 + 2 * (node_bytes + neuron_bytes) + 1 + 24;
  std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<long>(density + 3));
  EXPECT_EQ(failure(cut), "genome bytes: truncated in node 2 (offset " + std::to_string(density) +
                              " of " + std::to_string(density + 3) + ")");

  // cut inside node 2's only neuron: its count no longer fits
  std::size_t count = density + 8 + 1 + 24 + 1;
  cut.assign(bytes.begin(), bytes.begin() + static_cast<long>(count + 4 + 4));
  EXPECT_EQ(failure(cut), "genome bytes: truncated in node 2 neurons (offset " +
                              std::to_string(count) + " of " + std::to_string(count + 8) +
                              ": count 1 needs at least 13 more bytes, 4 left)");
}

// random byte flips never crash: the result is a genome or an InputError
TEST(SerializeGenome, RandomByteFlipsNeverCrash) {
  GenomeLimits limits;
  Rng rng(3, RngPurpose::test);
  int failures = 0, successes = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(limits, 43, 0, i));
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::uint8_t> damaged = bytes;
      int flips = 1 + static_cast<int>(rng.below(4));
      for (int f = 0; f < flips; ++f) {
        damaged[rng.below(damaged.size())] ^= static_cast<std::uint8_t>(1 + rng.below(255));
      }
      (failure(damaged).empty() ? successes : failures)++;
    }
  }
  // both outcomes happen (doubles absorb most flips, counts and flags reject many)
  EXPECT_GT(failures, 0);
  EXPECT_GT(successes, 0);
}

// random garbage of any length is rejected, never read out of bounds
TEST(SerializeGenome, GarbageThrows) {
  Rng rng(4, RngPurpose::test);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::uint8_t> bytes(rng.below(200));
    for (std::uint8_t& b : bytes)
      b = static_cast<std::uint8_t>(rng.below(256));
    // half of them get a valid header so the body is exercised
    if (trial % 2 == 0 && bytes.size() >= 8) {
      std::memcpy(bytes.data(), "CMBG\x01\x00\x00\x00", 8);
    }
    std::string message = failure(bytes);
    if (!message.empty()) {
      EXPECT_NE(message.find("genome bytes"), std::string::npos);
    }
  }
}

TEST(SerializeGenome, BadMagic) {
  std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(GenomeLimits{}, 1));
  bytes[0] = 'X';
  EXPECT_EQ(failure(bytes), "genome bytes: not a cambrian genome (bad magic)");
  EXPECT_EQ(failure({}), "genome bytes: not a cambrian genome (bad magic)");
  EXPECT_THROW(deserializeGenome(nullptr, 0), InputError);
}

TEST(SerializeGenome, NewerVersion) {
  std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(GenomeLimits{}, 1));
  bytes[4] = 9;
  EXPECT_EQ(failure(bytes), "genome bytes: format version 9 is newer than this cambrian (5)");
  bytes[4] = 0;
  EXPECT_NE(failure(bytes).find("version 0"), std::string::npos);
}

// absurd counts are rejected before anything is allocated
TEST(SerializeGenome, HugeCountsRejected) {
  std::vector<std::uint8_t> bytes = serializeGenome(Genome{});
  bytes[8] = bytes[9] = bytes[10] = bytes[11] = 0xff;
  std::string message = failure(bytes);
  EXPECT_NE(message.find("truncated in node count (offset 8 of 20: count 4294967295 needs"),
            std::string::npos)
      << message;
}

TEST(SerializeGenome, TrailingBytesRejected) {
  std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(GenomeLimits{}, 2));
  bytes.push_back(0);
  EXPECT_NE(failure(bytes).find("1 unexpected bytes after the end"), std::string::npos);
}

// booleans are 0 or 1 on the wire
TEST(SerializeGenome, BadFlagRejected) {
  Genome g;
  g.nodes.resize(1);
  g.connections.resize(1);
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  std::size_t node_bytes = 1 + 24 + 8 + 1 + 24 + 1 + 4 + 4;
  std::size_t terminal = 8 + 4 + node_bytes + 4 + 2 + 2 + 24 + 24 + 8 + 1;
  bytes[terminal] = 2;
  EXPECT_NE(failure(bytes).find("connection 0 terminal_only is 2"), std::string::npos)
      << failure(bytes);
}

using test::catapultLimits;

// a catapult's genome round-trips through version 2 bytes; every other genome is still written
// as version 1, byte for byte what it was
TEST(Serialize, TheProjectileTravelsInVersion2) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Genome catapult = randomGenome(catapultLimits(true), seed);
    ASSERT_TRUE(catapult.projectile.has_value());
    const std::vector<std::uint8_t> bytes = serializeGenome(catapult);
    EXPECT_EQ(bytes[4], 2);
    EXPECT_EQ(deserializeGenome(bytes.data(), bytes.size()), catapult);
    const Genome walker = randomGenome(GenomeLimits{}, seed);
    EXPECT_EQ(serializeGenome(walker)[4], 1);
  }
  // cut inside the projectile: refused, naming it
  const std::vector<std::uint8_t> bytes = serializeGenome(randomGenome(catapultLimits(), 3));
  const std::vector<std::uint8_t> cut(bytes.begin(), bytes.end() - 9);
  EXPECT_NE(failure(cut).find("projectile"), std::string::npos) << failure(cut);
}

// chaotic joint controllers travel in version 3 bytes (their start and speed after the sine's
// fields); before version 3 the controller byte is 0 or 1, after it 0 to 3
TEST(Serialize, ChaoticControllersTravelInVersion3) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Genome chaotic = randomGenome(test::chaoticLimits(), seed);
    const std::vector<std::uint8_t> bytes = serializeGenome(chaotic);
    if (chaotic.connections.empty()) {
      EXPECT_EQ(bytes[4], 1);
      continue;
    }
    EXPECT_EQ(bytes[4], 3);
    EXPECT_EQ(deserializeGenome(bytes.data(), bytes.size()), chaotic);
  }
  Genome g;
  g.nodes.resize(1);
  g.connections.resize(1);
  const std::size_t node_bytes = 1 + 24 + 8 + 1 + 24 + 1 + 4 + 4;
  const std::size_t controller = 8 + 4 + node_bytes + 4 + 2 + 2 + 24 + 24 + 8 + 1 + 1;
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  bytes[controller] = 2;
  EXPECT_NE(failure(bytes).find("connection 0 controller.enabled is 2, expected 0 or 1"),
            std::string::npos)
      << failure(bytes);
  g.connections[0].controller.kind = JointControllerKind::chaotic;
  bytes = serializeGenome(g);
  ASSERT_EQ(bytes[4], 3);
  ASSERT_EQ(bytes[controller], 2);
  bytes[controller] = 4;
  EXPECT_NE(failure(bytes).find("connection 0 controller.enabled is 4, expected 0 to 3"),
            std::string::npos)
      << failure(bytes);
}

// one genome, one byte string: the reader accepts only the version the writer picks (the oldest
// that carries the genome), so a genome read is written again to the same bytes
TEST(Serialize, OnlyTheOldestVersionThatCarriesAGenomeIsRead) {
  Genome g;
  g.nodes.resize(1);
  g.connections.resize(1);
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  ASSERT_EQ(bytes[4], 1);
  // a capsule in version 1 bytes: its version cannot carry it
  const std::size_t shape = 8 + 4;
  bytes[shape] = static_cast<std::uint8_t>(PartShape::capsule);
  EXPECT_NE(failure(bytes).find("format version 1, but this genome is written as version 4"),
            std::string::npos)
      << failure(bytes);
  // version 4 bytes whose morphogene fields are all defaults: nothing needs version 4
  Genome defaults = g;
  defaults.connections[0].flip = true;
  bytes = serializeGenome(defaults);
  ASSERT_EQ(bytes[4], 4);
  bytes.back() = 0;  // the connection's flip and mirror byte
  EXPECT_NE(failure(bytes).find("format version 4, but this genome is written as version 1"),
            std::string::npos)
      << failure(bytes);
  // version 2 bytes without a projectile
  Genome catapult = randomGenome(catapultLimits(), 3);
  ASSERT_TRUE(catapult.projectile.has_value());
  catapult.projectile.reset();
  bytes = serializeGenome(catapult);
  ASSERT_EQ(bytes[4], 1);
  bytes[4] = 2;
  bytes.push_back(0);  // "no projectile"
  EXPECT_NE(failure(bytes).find("nothing in it needs a later version"), std::string::npos)
      << failure(bytes);
}

// a photosensitive node needs version 5; version 5 bytes without one are refused, and the
// flag's byte is 0 or 1
TEST(Serialize, PhotosensitivePartsNeedVersionFive) {
  GenomeLimits limits;
  limits.photosensors = Photosensors::chosen;
  Genome g = randomGenome(limits, 5, 0, 1);
  g.nodes[0].photosensitive = true;
  std::vector<std::uint8_t> bytes = serializeGenome(g);
  ASSERT_EQ(bytes[4], 5);
  EXPECT_EQ(deserializeGenome(bytes.data(), bytes.size()), g);
  std::vector<std::uint8_t> two = bytes;
  two[two.size() - g.nodes.size()] = 2;  // node 0's flag
  EXPECT_NE(failure(two).find("photosensitive"), std::string::npos) << failure(two);
  for (PartGene& node : g.nodes)
    node.photosensitive = false;
  bytes = serializeGenome(g);
  ASSERT_LT(bytes[4], 5);
  // the same genome in version 5 bytes (version 4's fields and every flag 0)
  GenomeLimits morphogenes;
  morphogenes.morphogenes = true;
  Genome m = randomGenome(morphogenes, 5, 0, 2);
  m.nodes[0].photosensitive = true;
  bytes = serializeGenome(m);
  ASSERT_EQ(bytes[4], 5);
  bytes[bytes.size() - m.nodes.size()] = 0;
  EXPECT_NE(failure(bytes).find("format version 5, but this genome is written as version 4"),
            std::string::npos)
      << failure(bytes);
}

}  // namespace
}  // namespace cambrian::graph
