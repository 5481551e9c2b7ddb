#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/catapult_limits.hpp"
#include "encodings/directed_graph/chaotic_limits.hpp"
#include "encodings/directed_graph/cuts.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

namespace cambrian::graph {
namespace {

// the message of the InputError that parsing `text` throws, or "" if it parses
std::string failure(const std::string& text) {
  try {
    parseGenomeText(text, "walker.genome");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// exact round trip on thousands of random genomes
TEST(GenomeText, RoundTripRandomGenomes) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 3000; ++i) {
    Genome genome = randomGenome(limits, 51, 0, i);
    std::string text = genomeToText(genome);
    Genome back = parseGenomeText(text);
    ASSERT_EQ(back, genome) << text;
    EXPECT_EQ(genomeToText(back), text);
  }
}

// awkward values survive: shortest exact decimals, out-of-range enums and bits, disabled
// controllers with settings, terminal-only
TEST(GenomeText, RoundTripUnusualValues) {
  Genome g;
  g.nodes.resize(2);
  g.nodes[0].dimensions = {0.1, 1.0 / 3.0, 1e-300};
  g.nodes[0].density = -0.0;
  g.nodes[1].joint_type = static_cast<JointType>(9);
  g.nodes[1].shape = static_cast<PartShape>(2);
  g.nodes[1].neurons.push_back(
      {static_cast<NeuronFunction>(77), {{static_cast<SignalSource>(12), 65535, 7, -1e-9}}, 3});
  g.nodes[1].neurons.push_back({NeuronFunction::if_positive, {}, 0});
  g.nodes[1].effectors.push_back({});
  ConnectionGene c;
  c.from = 1;
  c.to = 300;
  c.reflection = 0x85;
  c.terminal_only = true;
  c.controller = {false, 0.25, 2, -1, 0.5};
  g.connections.push_back(c);
  c.reflection = 5;
  c.controller = {true, 0, 1, 0, 0};
  g.connections.push_back(c);
  g.brain.push_back({NeuronFunction::constant, {}, 1.5});
  EXPECT_EQ(parseGenomeText(genomeToText(g)), g) << genomeToText(g);
}

// a controller that differs from the default only in a zero's sign is written, so that the text
// reads back to the same bytes (found by fuzzing: an off controller with offset -0 was left out)
TEST(GenomeText, RoundTripNegativeZeroController) {
  Genome g;
  g.nodes.resize(1);
  ConnectionGene c;
  c.controller = {false, 0, 1, 0, -0.0};
  g.connections.push_back(c);
  c.controller = {false, -0.0, 1, 0, 0};
  g.connections.push_back(c);
  std::string text = genomeToText(g);
  EXPECT_EQ(serializeGenome(parseGenomeText(text)), serializeGenome(g)) << text;
}

// a hand-written genome: comments, defaults, continuation lines, brain
TEST(GenomeText, HandWrittenWithDefaults) {
  const std::string text = R"(# a comment before the header
cambrian-genome 1
node 0 size 0.6 0.3 0.15 joint rigid   # density stays at its default
  neuron oscillate_wave parameter 1.5 input constant 0 0 0.8
  effector input local_neuron 0 0 1.0
node 1
  density 500
  limit 0.5 0.5 0.5 recursion 2
  neuron sum
    input local_sensor 0 1 0.5
    input brain_sensor 0 2 -1
  effector brain_neuron 1 2 0.25
connection 0 -> 1 position 0.5 1 0 orientation 0 0 1.5708 scale 1 reflect xy
  controller amplitude 0.5 frequency 1 phase 0 offset 0
connection 1 -> 1 terminal_only
  reflect z
brain
  neuron if input local_sensor 0 0 1
)";
  Genome g = parseGenomeText(text);
  ASSERT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(g.nodes[0].dimensions, (Vec3{0.6, 0.3, 0.15}));
  EXPECT_EQ(g.nodes[0].density, PartGene{}.density);
  EXPECT_EQ(g.nodes[0].joint_type, JointType::fixed);
  ASSERT_EQ(g.nodes[0].neurons.size(), 1u);
  EXPECT_EQ(g.nodes[0].neurons[0].function, NeuronFunction::oscillate_wave);
  EXPECT_EQ(g.nodes[0].neurons[0].parameter, 1.5);
  EXPECT_EQ(g.nodes[0].neurons[0].inputs[0], (NeuronInput{SignalSource::constant, 0, 0, 0.8}));
  EXPECT_EQ(g.nodes[0].effectors[0].input, (NeuronInput{SignalSource::local_neuron, 0, 0, 1}));
  EXPECT_EQ(g.nodes[1].dimensions, PartGene{}.dimensions);
  EXPECT_EQ(g.nodes[1].density, 500);
  EXPECT_EQ(g.nodes[1].joint_type, JointType::revolute);
  EXPECT_EQ(g.nodes[1].recursive_limit, 2);
  ASSERT_EQ(g.nodes[1].neurons[0].inputs.size(), 2u);
  EXPECT_EQ(g.nodes[1].neurons[0].inputs[1], (NeuronInput{SignalSource::brain_sensor, 0, 2, -1}));
  EXPECT_EQ(g.nodes[1].effectors[0].input, (NeuronInput{SignalSource::brain_neuron, 1, 2, 0.25}));
  ASSERT_EQ(g.connections.size(), 2u);
  EXPECT_EQ(g.connections[0].position, (Vec3{0.5, 1, 0}));
  EXPECT_EQ(g.connections[0].orientation, (Vec3{0, 0, 1.5708}));
  EXPECT_EQ(g.connections[0].reflection, 3);
  EXPECT_TRUE(g.connections[0].controller.enabled);
  EXPECT_EQ(g.connections[0].controller.amplitude, 0.5);
  EXPECT_EQ(g.connections[1].from, 1);
  EXPECT_TRUE(g.connections[1].terminal_only);
  EXPECT_EQ(g.connections[1].reflection, 4);
  EXPECT_EQ(g.connections[1].position, ConnectionGene{}.position);
  EXPECT_FALSE(g.connections[1].controller.enabled);
  ASSERT_EQ(g.brain.size(), 1u);
  EXPECT_EQ(g.brain[0].function, NeuronFunction::if_positive);
  EXPECT_NO_THROW(validateGenome(g, GenomeLimits{}));
}

// parse errors name the source, the line and the field
TEST(GenomeText, ErrorsNameLineAndField) {
  const std::string head = "cambrian-genome 1\nnode 0\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {head + "\n\n\n\nnode 1 density heavy\n",
       "walker.genome:7: node 1: expected a number for 'density', got 'heavy'"},
      {head + "node 1 size 1 2\n",
       "walker.genome:3: node 1: expected a number for 'size', got end of line"},
      {head + "node 2\n", "walker.genome:3: node: expected node 1 next, got node 2"},
      {head + "node 1 colour red\n", "walker.genome:3: node 1: unknown node field 'colour'"},
      {head + "node 1 joint hinge\n", "walker.genome:3: node 1: unknown value 'hinge' for 'joint'"},
      {head + "node 1 recursion 300\n",
       "walker.genome:3: node 1: expected an integer 0..255 for 'recursion', got '300'"},
      {head + "  neuron frobnicate\n",
       "walker.genome:3: node 0: neuron 0: unknown value 'frobnicate' for 'function'"},
      {head + "  neuron sum input local_sensor 0 x 1\n",
       "walker.genome:3: node 0: neuron 0: expected an integer 0..65535 for 'input index', got "
       "'x'"},
      {head + "  neuron sum input wrong 0 0 1\n",
       "walker.genome:3: node 0: neuron 0: unknown value 'wrong' for 'input source'"},
      {head + "  neuron sum speed 3\n",
       "walker.genome:3: node 0: neuron 0: unknown neuron field 'speed'"},
      {head + "  effector input local_neuron 0 0 1 extra\n",
       "walker.genome:3: node 0: effector 0: unexpected 'extra'"},
      {head + "connection 0 1\n",
       "walker.genome:3: connection 0: expected '->' in 'connection', got '1'"},
      {head + "connection 0 -> 0 reflect w\n",
       "walker.genome:3: connection 0: expected x, y, z, a combination such as xy, or none for "
       "'reflect', got 'w'"},
      {head + "connection 0 -> 0 reflect xx\n", "for 'reflect', got 'xx'"},
      {head + "connection 0 -> 0\n  controller amplitude loud\n",
       "walker.genome:4: connection 0: controller: expected a number for 'amplitude', got 'loud'"},
      {head + "connection 0 -> 0\n  neuron sum\n",
       "walker.genome:4: connection 0: a neuron line must follow a node or the brain line"},
      {head + "connection 0 -> 0\n  effector constant 0 0 1\n",
       "walker.genome:4: connection 0: an effector line must follow a node line"},
      {head + "  controller\n",
       "walker.genome:3: node 0: a controller line must follow a connection"},
      {head + "  input constant 0 0 1\n",
       "walker.genome:3: node 0: 'input' must follow a neuron line"},
      {head + "brain extra\n", "walker.genome:3: brain: unexpected 'extra' after 'brain'"},
      {"cambrian-genome 1\nwibble\n", "walker.genome:2: genome: unknown statement 'wibble'"},
      {"node 0\n", "walker.genome:1: expected the header 'cambrian-genome 2', got 'node'"},
      {"cambrian-genome 9\n", "walker.genome:1: format version 9 is newer than this cambrian (2)"},
      {"# only a comment\n", "walker.genome: empty genome text"},
      {"cambrian-genome 1\ncambrian-genome 1\n",
       "walker.genome:2: the header may appear only once"},
  };
  for (const Case& c : cases) {
    std::string message = failure(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "text:\n"
        << c.text << "expected: " << c.expected << "\ngot: " << message;
  }
}

// genomeToText writes the current version: its header, and `end` as the last line
TEST(GenomeText, WritesVersionTwoWithEnd) {
  std::string text = genomeToText(randomGenome(GenomeLimits{}, 3));
  EXPECT_EQ(text.rfind("cambrian-genome " + std::to_string(kGenomeTextVersion) + "\n", 0), 0u)
      << text;
  ASSERT_GE(text.size(), 5u);
  EXPECT_EQ(text.substr(text.size() - 5), "\nend\n") << text;
}

// version 2 needs `end` as its last statement; comments and blank lines may follow it
TEST(GenomeText, VersionTwoEndsWithEnd) {
  const std::string body = "cambrian-genome 2\nnode 0 size 0.3 0.3 0.3\nnode 1\n";
  Genome g = parseGenomeText(body + "end\n\n# a trailing comment\n   \n");
  ASSERT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(g.nodes[0].dimensions, (Vec3{0.3, 0.3, 0.3}));
  EXPECT_EQ(parseGenomeText(body + "end"), g);  // no newline after `end`
  EXPECT_EQ(parseGenomeText(body + "end # done\n"), g);

  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {body, "walker.genome:3: missing `end`: the file may be truncated"},
      {body + "\n# a comment is not an end\n",
       "walker.genome:3: missing `end`: the file may be truncated"},
      {body + "end\nnode 2\n",
       "walker.genome:5: unexpected 'node' after `end` (line 4): `end` must be the last statement"},
      {body + "end\n\nend\n", "walker.genome:6: unexpected 'end' after `end` (line 4)"},
      {body + "end now\n", "walker.genome:4: unexpected 'now' after `end`"},
      {"cambrian-genome 2\n", "walker.genome:1: missing `end`: the file may be truncated"},
      {"cambrian-genome 1\nnode 0\nend\n",
       "walker.genome:3: `end` is a statement of format version 2; this file's header says "
       "version 1"},
  };
  for (const Case& c : cases) {
    std::string message = failure(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "text:\n"
        << c.text << "expected: " << c.expected << "\ngot: " << message;
  }
}

// version 1 files (no `end`) still read, and mean the same as in version 2
TEST(GenomeText, ReadsVersionOne) {
  const std::string nodes = "node 0 size 0.3 0.2 0.1 joint rigid\nnode 1 density 500\n";
  Genome one = parseGenomeText("cambrian-genome 1\n" + nodes);
  ASSERT_EQ(one.nodes.size(), 2u);
  EXPECT_EQ(one.nodes[1].density, 500);
  EXPECT_EQ(parseGenomeText("cambrian-genome 2\n" + nodes + "end\n"), one);
}

// a version-2 file cut short anywhere is refused, naming the file; the cuts are every line
// boundary and every 37th byte of walker4.genome (the whole file parses)
TEST(GenomeText, TruncatedFilesAreRefused) {
  const std::string source = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/walker4.genome";
  std::ifstream in(source, std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(whole.size(), 1000u);
  ASSERT_NO_THROW(readGenomeFile(source));

  // every cut that loses at least the `d` of the final `end` (the last byte is its newline)
  std::set<std::size_t> cuts = test::truncationPoints(whole);
  ASSERT_GT(cuts.size(), 60u);

  const std::filesystem::path path =
      std::filesystem::path(CAMBRIAN_BINARY_DIR) / "text_test_truncated.genome";
  for (std::size_t cut : cuts) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << whole.substr(0, cut);
    try {
      readGenomeFile(path.string());
      ADD_FAILURE() << "a cut at byte " << cut << " of " << whole.size() << " parsed";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ":", 0), 0u)
          << "cut at byte " << cut << ": " << e.what();
    }
  }
  std::filesystem::remove(path);
}

// the source name defaults to <text>
TEST(GenomeText, DefaultSourceName) {
  try {
    parseGenomeText("cambrian-genome 1\nnode 0 density x\n");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("<text>:2: node 0:", 0), 0u) << e.what();
  }
}

using test::catapultLimits;

// a catapult's projectile is one line of the text form, read back exactly; a second one is an
// error naming its line
TEST(Text, TheProjectileIsOneLine) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Genome g = randomGenome(catapultLimits(true), seed);
    const std::string text = genomeToText(g);
    EXPECT_NE(text.find("\nprojectile size "), std::string::npos);
    EXPECT_EQ(parseGenomeText(text), g);
  }
  const std::string text =
      "cambrian-genome 2\nnode 0 size 0.5 0.5 0.5\nprojectile size 0.2 0.2 0.2 density 900 "
      "position 0 0 1 trigger constant 0 0 1\nprojectile size 0.1 0.1 0.1\nend\n";
  EXPECT_NE(failure(text).find(":4"), std::string::npos) << failure(text);
  EXPECT_NE(failure(text).find("one projectile"), std::string::npos) << failure(text);
  const Genome g = parseGenomeText(
      "cambrian-genome 2\nnode 0 size 0.5 0.5 0.5\nprojectile size 0.2 0.3 0.4 density 900 "
      "position 0 0 1 trigger constant 0 0 1\nend\n");
  ASSERT_TRUE(g.projectile.has_value());
  EXPECT_EQ(g.projectile->dimensions, (Vec3{0.2, 0.3, 0.4}));
  EXPECT_EQ(g.projectile->density, 900);
  EXPECT_EQ(g.projectile->trigger.weight, 1);
}

// chaotic joint controllers round-trip through the text, and read as written by hand
TEST(Text, AChaoticControllerIsOneLine) {
  for (std::uint64_t i = 0; i < 300; ++i) {
    const Genome genome = randomGenome(test::chaoticLimits(0.5), 52, 0, i);
    const std::string text = genomeToText(genome);
    ASSERT_EQ(parseGenomeText(text), genome) << text;
  }
  const Genome g = parseGenomeText(
      "cambrian-genome 2\nnode 0 size 0.2 0.2 0.2 density 1000 joint revolute limit 1 1 1 "
      "recursion 1\nnode 1 size 0.2 0.2 0.2 density 1000 joint revolute limit 1 1 1 "
      "recursion 1\nconnection 0 -> 1 position 1 0 0 orientation 0 0 0 scale 1\n"
      "  controller chaotic amplitude 0.25 offset 0.1 start 0.1 -0.2 0.3 speed 4\nend\n");
  const JointControllerGene& c = g.connections.at(0).controller;
  EXPECT_TRUE(c.enabled);
  EXPECT_EQ(c.kind, JointControllerKind::chaotic);
  EXPECT_EQ(c.amplitude, 0.25);
  EXPECT_EQ(c.offset, 0.1);
  EXPECT_EQ(c.chua_start, (ChuaState{0.1, -0.2, 0.3}));
  EXPECT_EQ(c.chua_speed, 4);
}

// a photosensitive node is one word on its line, and round-trips
TEST(Text, APhotosensitivePartIsOneWord) {
  GenomeLimits limits;
  limits.photosensors = Photosensors::chosen;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const Genome genome = randomGenome(limits, 52, 0, i);
    const std::string text = genomeToText(genome);
    ASSERT_EQ(parseGenomeText(text), genome) << text;
  }
  const Genome g = parseGenomeText(
      "cambrian-genome 2\nnode 0 size 0.4 0.4 0.2 photosensitive\nnode 1 size 0.3 0.1 0.1\n"
      "connection 0 -> 1\nend\n");
  EXPECT_TRUE(g.nodes[0].photosensitive);
  EXPECT_FALSE(g.nodes[1].photosensitive);
  EXPECT_NE(genomeToText(g).find("photosensitive"), std::string::npos);
}

}  // namespace
}  // namespace cambrian::graph
