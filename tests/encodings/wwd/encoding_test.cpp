// The wwd encoding behind the Encoding interface: registered by name and tag, its settings,
// random genomes, validation, sizes, the operators and the byte and text forms with their refusals.
#include "encodings/wwd/encoding.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "brain/layered_network.hpp"
#include "core/settings.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace cambrian::wwd {
namespace {

// two boxes (as in grammar_test.cpp): a 10 x 0.05 x 3.37 m root with a pressure sensor, one joint,
// a 0.05 x 10 x 0.05 m box on it
const Dna kTwoBoxes = {999, 0, 333, 7,   7, 215, 0,   4,   999, 6,  21, 12,  3,   0,   999, 300,
                       1,   0, 17,  500, 2, 5,   998, 250, 999, 0,  8,  333, 666, 3,   999, 0,
                       333, 0, 999, 0,   2, 6,   114, 525, 3,   39, 1,  2,   3,   999, 0,   999};

// the registered encoding's copy, configured by `settings` (key, value pairs)
std::unique_ptr<Encoding> configured(
    const std::vector<std::pair<std::string, std::string>>& settings) {
  std::unique_ptr<Encoding> encoding = findEncoding(WwdEncoding::kName).clone();
  SettingsSchema schema;
  encoding->declareSettings(schema);
  for (const auto& [key, value] : settings)
    schema.set(key, value);
  schema.check();
  return encoding;
}

// the message of the InputError that reading `bytes` throws, or "" if they read
std::string byteFailure(const std::vector<std::uint8_t>& bytes) {
  try {
    findEncoding(WwdEncoding::kName).fromBytes(bytes.data(), bytes.size());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// the message of the InputError that reading `text` throws, or "" if it reads
std::string textFailure(const std::string& text, const Encoding& encoding) {
  try {
    encoding.fromText(text, "dino.genome");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
std::string textFailure(const std::string& text) {
  return textFailure(text, findEncoding(WwdEncoding::kName));
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(WwdEncoding, IsRegisteredByNameAndTag) {
  const Encoding& encoding = findEncoding("wwd");
  EXPECT_EQ(encoding.name(), "wwd");
  EXPECT_EQ(encoding.tag(), (std::array<char, 4>{'C', 'M', 'B', 'W'}));
  EXPECT_EQ(encodingForTag({'C', 'M', 'B', 'W'}), &encoding);
  EXPECT_EQ(encoding.textHeader(), "cambrian-wwd");
  EXPECT_NE(dynamic_cast<const WwdEncoding*>(&encoding), nullptr);
}

// random genomes: a pure function of (seed, generation, individual), valid, read exactly
TEST(WwdEncoding, RandomGenomesAreAPureFunctionOfTheirKey) {
  auto encoding = configured({});
  const Genotype a = encoding->random(7, 0, 3);
  EXPECT_EQ(a, encoding->random(7, 0, 3));
  EXPECT_EQ(a.bytes(), encoding->random(7, 0, 3).bytes());
  EXPECT_NE(a, encoding->random(7, 0, 4));
  EXPECT_NE(a, encoding->random(7, 1, 3));
  EXPECT_NE(a, encoding->random(8, 0, 3));
  for (std::uint64_t i = 0; i < 50; ++i) {
    const Genotype g = encoding->random(7, 0, i);
    ASSERT_NO_THROW(encoding->validate(g));
    const auto& wwd = dynamic_cast<const WwdEncoding&>(*encoding);
    EXPECT_EQ(readCreature(dnaOf(g), wwd.grammar).genes_read, dnaOf(g).size());
  }
  // the box limit reaches the random genomes
  auto small = configured({{"wwd.max_boxes", "2"}});
  for (std::uint64_t i = 0; i < 50; ++i)
    ASSERT_LE(small->size(small->random(7, 0, i)).genes, 2u);
}

// the byte form: the tag, version 1, the gene count and each gene, all little-endian; read back
// exactly, by the encoding and by the registry
TEST(WwdEncoding, BytesRoundTrip) {
  const Encoding& encoding = findEncoding("wwd");
  const Genotype small = makeGenotype({1, 999, 0});
  const std::vector<std::uint8_t> expected = {'C', 'M', 'B', 'W', 1, 0,    0, 0, 3,
                                              0,   0,   0,   1,   0, 0xe7, 3, 0, 0};
  EXPECT_EQ(small.bytes(), expected);
  EXPECT_EQ(encoding.toBytes(small.data()), expected);
  for (std::uint64_t i = 0; i < 20; ++i) {
    const Genotype g = encoding.random(5, 0, i);
    const std::vector<std::uint8_t>& bytes = g.bytes();
    const Genotype back = encoding.fromBytes(bytes.data(), bytes.size());
    EXPECT_EQ(dnaOf(back), dnaOf(g));
    EXPECT_EQ(back, g);
    const Genotype decoded = decodeGenome(bytes);
    EXPECT_EQ(decoded, g);
    EXPECT_EQ(decoded.encoding().name(), "wwd");
    EXPECT_EQ(dnaOf(decoded), dnaOf(g));
  }
  const Genotype empty = makeGenotype({});
  EXPECT_EQ(dnaOf(decodeGenome(empty.bytes())), Dna{});
}

// what the byte reader refuses, each an InputError naming the problem
TEST(WwdEncoding, BytesRefuseWhatIsNotWwdDna) {
  const std::vector<std::uint8_t> good = makeGenotype({1, 999, 0}).bytes();
  ASSERT_EQ(byteFailure(good), "");

  std::vector<std::uint8_t> magic = good;
  magic[3] = 'S';
  EXPECT_TRUE(contains(byteFailure(magic), "bad magic")) << byteFailure(magic);
  EXPECT_TRUE(contains(byteFailure({'C', 'M'}), "bad magic")) << byteFailure({'C', 'M'});

  std::vector<std::uint8_t> version = good;
  version[4] = 2;
  EXPECT_TRUE(contains(byteFailure(version), "version 2")) << byteFailure(version);

  std::vector<std::uint8_t> gene = good;
  gene[14] = 0xe8;  // gene 1: 1000
  EXPECT_TRUE(contains(byteFailure(gene), "gene 1 is 1000")) << byteFailure(gene);
  gene[14] = 0xff;
  gene[15] = 0xff;
  EXPECT_TRUE(contains(byteFailure(gene), "gene 1 is 65535")) << byteFailure(gene);

  const std::vector<std::uint8_t> cut(good.begin(), good.end() - 1);
  EXPECT_TRUE(contains(byteFailure(cut), "truncated")) << byteFailure(cut);
  const std::vector<std::uint8_t> header(good.begin(), good.begin() + 6);
  EXPECT_TRUE(contains(byteFailure(header), "truncated")) << byteFailure(header);
  std::vector<std::uint8_t> count = good;
  count[8] = 4;  // four genes, three there
  EXPECT_TRUE(contains(byteFailure(count), "truncated")) << byteFailure(count);

  std::vector<std::uint8_t> trailing = good;
  trailing.push_back(0);
  EXPECT_TRUE(contains(byteFailure(trailing), "1 unexpected bytes after the end"))
      << byteFailure(trailing);
  for (const auto& bad : {magic, version, gene, cut, trailing})
    EXPECT_TRUE(contains(byteFailure(bad), "wwd DNA bytes")) << byteFailure(bad);
}

// the text form: exact round trip, a header, 20 genes a `dna` line, `end`
TEST(WwdEncoding, TextRoundTrip) {
  const Encoding& encoding = findEncoding("wwd");
  for (std::uint64_t i = 0; i < 20; ++i) {
    const Genotype g = encoding.random(5, 0, i);
    const std::string text = encoding.toText(g);
    EXPECT_EQ(text.rfind("cambrian-wwd 1\n", 0), 0u) << text;
    EXPECT_EQ(encoding.fromText(text, "test"), g);
  }
  const Genotype small = makeGenotype(kTwoBoxes);
  const std::string text = encoding.toText(small);
  EXPECT_TRUE(contains(text, "\ndna 999 0 333 7 7 215 0 4 999 6 21 12 3 0 999 300 1 0 17 500\n"))
      << text;
  EXPECT_TRUE(contains(text, "\ndna 3 39 1 2 3 999 0 999\nend\n")) << text;
  EXPECT_EQ(encoding.fromText(text, "test"), small);
  // an empty DNA: no `dna` line
  EXPECT_EQ(dnaOf(encoding.fromText(encoding.toText(makeGenotype({})), "test")), Dna{});
}

// hand-written text: comments, blank lines, genes spread over any number of `dna` lines
TEST(WwdEncoding, TextWithCommentsAndSeveralDnaLinesReads) {
  const std::string text =
      "# a block\n"
      "cambrian-wwd 1   # the header\n"
      "\n"
      "dna 95 95 95 1   # the box\n"
      "dna 0\n"
      "   dna 0 525 # the main net\n"
      "dna\n"
      "dna 0 500\n"
      "end\n"
      "# after the end, comments only\n";
  const Genotype g = findEncoding("wwd").fromText(text, "block.genome");
  EXPECT_EQ(dnaOf(g), (Dna{95, 95, 95, 1, 0, 0, 525, 0, 500}));
}

// what the text reader refuses: each an InputError naming the source and, where there is one, the
// line
TEST(WwdEncoding, TextRefusesWhatIsNotWwdDna) {
  // no header: the first statement is not it
  std::string failure = textFailure("dna 1 2\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:1:")) << failure;
  EXPECT_TRUE(contains(failure, "cambrian-wwd")) << failure;
  // nothing at all
  failure = textFailure("# only a comment\n\n");
  EXPECT_TRUE(contains(failure, "dino.genome")) << failure;
  EXPECT_TRUE(contains(failure, "empty")) << failure;
  // another encoding's header, or another version
  failure = textFailure("# x\ncambrian-graph 1\ndna 1\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:2:")) << failure;
  EXPECT_TRUE(contains(failure, "cambrian-graph")) << failure;
  failure = textFailure("cambrian-wwd 2\ndna 1\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:1:")) << failure;
  failure = textFailure("cambrian-wwd\ndna 1\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:1:")) << failure;
  failure = textFailure("cambrian-wwd 1 extra\ndna 1\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:1:")) << failure;
  // a gene out of range, or not a number
  failure = textFailure("cambrian-wwd 1\ndna 1 2\n\ndna 3 1000\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:4:")) << failure;
  EXPECT_TRUE(contains(failure, "gene 3")) << failure;
  EXPECT_TRUE(contains(failure, "1000")) << failure;
  failure = textFailure("cambrian-wwd 1\ndna 1 -1\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:2:")) << failure;
  failure = textFailure("cambrian-wwd 1\ndna 1 2.5\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:2:")) << failure;
  // no `end`: cut short
  failure = textFailure("cambrian-wwd 1\ndna 1 2\n");
  EXPECT_TRUE(contains(failure, "dino.genome")) << failure;
  EXPECT_TRUE(contains(failure, "end")) << failure;
  // an unknown statement
  failure = textFailure("cambrian-wwd 1\ndna 1\ngenes 2\nend\n");
  EXPECT_TRUE(contains(failure, "dino.genome:3:")) << failure;
  EXPECT_TRUE(contains(failure, "genes")) << failure;
  // anything after `end`, or after it on its line
  failure = textFailure("cambrian-wwd 1\nend\ndna 1\n");
  EXPECT_TRUE(contains(failure, "dino.genome:3:")) << failure;
  failure = textFailure("cambrian-wwd 1\nend 1\n");
  EXPECT_TRUE(contains(failure, "dino.genome:2:")) << failure;
  // more genes than wwd.max_genes
  auto short_dna = configured({{"wwd.max_genes", "3"}});
  EXPECT_EQ(textFailure("cambrian-wwd 1\ndna 1 2 3\nend\n", *short_dna), "");
  failure = textFailure("cambrian-wwd 1\ndna 1 2\ndna 3 4\nend\n", *short_dna);
  EXPECT_TRUE(contains(failure, "dino.genome:3:")) << failure;
  EXPECT_TRUE(contains(failure, "wwd.max_genes")) << failure;
}

// validate: a DNA no longer than wwd.max_genes, every gene below 1000, a wwd genome
TEST(WwdEncoding, ValidateRefusesADnaLongerThanTheLimit) {
  auto encoding = configured({{"wwd.max_genes", "10"}});
  EXPECT_NO_THROW(encoding->validate(makeGenotype(Dna(10, 999))));
  EXPECT_NO_THROW(encoding->validate(makeGenotype({})));
  try {
    encoding->validate(makeGenotype(Dna(11, 0)));
    FAIL() << "11 genes passed wwd.max_genes = 10";
  } catch (const GenomeError& e) {
    EXPECT_TRUE(contains(e.what(), "wwd.max_genes")) << e.what();
  }
  EXPECT_THROW(encoding->validate(makeGenotype({1, 1000})), GenomeError);
  EXPECT_THROW(encoding->validate(Genotype()), GenomeError);
  const Genotype springy = findEncoding("springy").random(1, 0, 0);
  EXPECT_THROW(encoding->validate(springy), GenomeError);
  EXPECT_THROW(dnaOf(springy), GenomeError);
}

// the settings' rules: each refused value a ConfigError naming its key
TEST(WwdEncoding, SettingsRefuseValuesOutOfRange) {
  EXPECT_NO_THROW(configured({{"wwd.min_side", "0.5"}, {"wwd.max_side", "0.5"}}));
  try {
    configured({{"wwd.min_side", "0.5"}, {"wwd.max_side", "0.4"}});
    FAIL() << "wwd.max_side below wwd.min_side passed";
  } catch (const ConfigError& e) {
    EXPECT_TRUE(contains(e.what(), "wwd.max_side")) << e.what();
  }
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"wwd.max_boxes", "0"},       {"wwd.min_side", "0"},     {"wwd.max_joint_limit", "91"},
      {"wwd.main_net_size", "0"},   {"wwd.subnet_size", "31"}, {"wwd.max_weight", "-1"},
      {"wwd.density", "0"},         {"wwd.friction", "-0.1"},  {"wwd.strength_per_area", "-1"},
      {"wwd.mutation_rate", "1.5"}, {"wwd.max_genes", "0"}};
  for (const auto& setting : refused) {
    try {
      configured({setting});
      ADD_FAILURE() << setting.first << " = " << setting.second << " passed";
    } catch (const ConfigError& e) {
      EXPECT_TRUE(contains(e.what(), setting.first)) << e.what();
    }
  }
}

// the settings reach the grammar, the body and the operators
TEST(WwdEncoding, SettingsReachTheGrammarAndTheBody) {
  auto encoding = configured({{"wwd.min_side", "1"},
                              {"wwd.max_side", "2"},
                              {"wwd.density", "500"},
                              {"wwd.strength_per_area", "100"}});
  const Creature creature = encoding->develop(makeGenotype(kTwoBoxes));
  ASSERT_EQ(creature.body.parts.size(), 2u);
  const Vec3 root = creature.body.parts[0].size;
  EXPECT_EQ(root.x, 2.0);
  EXPECT_EQ(root.y, 1.0);
  EXPECT_DOUBLE_EQ(creature.body.parts[0].mass, 500 * root.x * root.y * root.z);
  const PartPlan& child = creature.body.parts[1];
  EXPECT_DOUBLE_EQ(child.strength, 100 * child.cross_section);
  const auto network = std::dynamic_pointer_cast<const LayeredNetworkPlan>(creature.controller);
  ASSERT_TRUE(network);
  EXPECT_NO_THROW(
      network->build(0.01, creature.body.sensors.size(), creature.body.effectors.size()));

  // wwd.mutation_rate: 1 draws every gene anew, 0 about one gene; mutate's rate multiplies it
  // (Encoding::scalesOwnMutation), 0 leaves the parent as it is
  Rng genes(3, RngPurpose::test);
  Dna dna(200);
  for (Gene& g : dna)
    g = static_cast<Gene>(genes.below(kGeneValues));
  const Genotype parent = makeGenotype(dna);
  auto every = configured({{"wwd.mutation_rate", "1"}});
  auto seed = configured({});
  EXPECT_TRUE(seed->scalesOwnMutation());
  Rng rng(4, RngPurpose::test);
  int all = 0, few = 0, more = 0, none = 0;
  for (int t = 0; t < 10; ++t) {
    const Dna a = dnaOf(every->mutate(parent, 1, rng));
    const Dna b = dnaOf(seed->mutate(parent, 1, rng));
    const Dna c = dnaOf(seed->mutate(parent, 4, rng));
    const Dna d = dnaOf(seed->mutate(parent, 0, rng));
    for (std::size_t i = 0; i < dna.size(); ++i) {
      all += a[i] != dna[i] ? 1 : 0;
      few += b[i] != dna[i] ? 1 : 0;
      more += c[i] != dna[i] ? 1 : 0;
      none += d[i] != dna[i] ? 1 : 0;
    }
  }
  EXPECT_GT(all, 1950);  // 2,000 genes, each drawn anew (one in a thousand the same)
  EXPECT_LT(few, 40);    // about 10
  EXPECT_GT(more, few);  // about 40
  EXPECT_EQ(none, 0);
}

// mutation and crossover give valid genomes; graft is not WWD's
TEST(WwdEncoding, MutationAndCrossoverGoThroughGraftDoesNot) {
  auto encoding = configured({});
  EXPECT_TRUE(encoding->supports(Variation::mutation));
  EXPECT_TRUE(encoding->supports(Variation::crossover));
  EXPECT_FALSE(encoding->supports(Variation::graft));
  Rng rng(5, RngPurpose::test);
  Genotype child = encoding->random(5, 0, 0);
  for (std::uint64_t k = 0; k < 40; ++k) {
    child = k % 2 == 0
                ? encoding->mutate(child, 1, rng)
                : encoding->combine(Variation::crossover, child, encoding->random(5, 1, k), rng);
    ASSERT_NO_THROW(encoding->validate(child));
    const Creature creature = encoding->develop(child);
    ASSERT_NO_THROW(creature.controller->build(0.01, creature.body.sensors.size(),
                                               creature.body.effectors.size()));
  }
  const Genotype a = encoding->random(5, 0, 1);
  EXPECT_THROW(encoding->combine(Variation::graft, a, a, rng), GenomeError);
  EXPECT_THROW(encoding->combine(Variation::mutation, a, a, rng), GenomeError);
}

// a crossover child longer than wwd.max_genes is not made: the first parent instead
TEST(WwdEncoding, CrossoverKeepsTheGeneLimit) {
  auto encoding = configured({{"wwd.max_genes", "48"}});
  const Genotype a = makeGenotype(kTwoBoxes);
  Rng rng(6, RngPurpose::test);
  int parent = 0;
  for (std::uint64_t k = 0; k < 40; ++k) {
    const Genotype child =
        encoding->combine(Variation::crossover, a, findEncoding("wwd").random(6, 0, k), rng);
    ASSERT_LE(dnaOf(child).size(), 48u);
    ASSERT_NO_THROW(encoding->validate(child));
    parent += child == a ? 1 : 0;
  }
  EXPECT_GT(parent, 0);
}

// size: a gene per box, a link per joint, the boxes' mean sides summed
TEST(WwdEncoding, SizeCountsBoxesAndJoints) {
  const Encoding& encoding = findEncoding("wwd");
  const GenomeSize two = encoding.size(makeGenotype(kTwoBoxes));
  EXPECT_EQ(two.genes, 2u);
  EXPECT_EQ(two.links, 1u);
  EXPECT_DOUBLE_EQ(two.total_part_size, (10 + 0.05 + (0.05 + 9.95 / 3)) / 3 + 10.1 / 3);
  const GenomeSize one = encoding.size(makeGenotype({}));
  EXPECT_EQ(one.genes, 1u);
  EXPECT_EQ(one.links, 0u);
  EXPECT_DOUBLE_EQ(one.total_part_size, 0.05);
  // and as many as development makes
  for (std::uint64_t i = 0; i < 20; ++i) {
    const Genotype g = encoding.random(9, 0, i);
    const Creature creature = encoding.develop(g);
    EXPECT_EQ(encoding.size(g).genes, creature.body.parts.size());
    EXPECT_EQ(encoding.size(g).links, creature.body.parts.size() - 1);
  }
}

}  // namespace
}  // namespace cambrian::wwd
