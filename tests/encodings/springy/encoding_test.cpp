// The springy encoding behind the Encoding interface: registered by name and tag, settings that
// read the organism file, random genomes of its morphology, frozen frequencies, the operators,
// the written forms and development.
#include "encodings/springy/encoding.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "core/settings.hpp"
#include "encodings/springy/organism_forms.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian::springy {
namespace {

const std::string kSnake =
    std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/springy/snake.organism";

// the registered encoding's copy, configured by `settings` (key, value pairs)
std::unique_ptr<Encoding> configured(
    const std::vector<std::pair<std::string, std::string>>& settings) {
  std::unique_ptr<Encoding> encoding = findEncoding(SpringyEncoding::kName).clone();
  SettingsSchema schema;
  encoding->declareSettings(schema);
  for (const auto& [key, value] : settings)
    schema.set(key, value);
  schema.check();
  return encoding;
}

TEST(SpringyEncoding, IsRegisteredByNameAndTag) {
  const Encoding& encoding = findEncoding("springy");
  EXPECT_EQ(encoding.name(), "springy");
  EXPECT_EQ(encodingForTag(kOrganismTag), &encoding);
}

// springy.organism is read when the settings are checked; a missing file names the key; no
// file is the Pyramid
TEST(SpringyEncoding, TheOrganismFileIsReadWithTheSettingsElseTheBuiltInPyramid) {
  auto encoding = configured({{"springy.organism", kSnake}});
  const auto& springy = dynamic_cast<const SpringyEncoding&>(*encoding);
  EXPECT_EQ(springy.organism_template.nodes.size(), 7u);
  try {
    configured({{"springy.organism", "/nonexistent/snake.organism"}});
    FAIL() << "a missing organism file was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("springy.organism = /nonexistent/snake.organism"),
              std::string::npos)
        << e.what();
  }
  // without a file, the built-in Pyramid: the same organism as its file
  auto bare = configured({});
  const std::string pyramid =
      std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/springy/pyramid.organism";
  auto from_file = configured({{"springy.organism", pyramid}});
  EXPECT_EQ(dynamic_cast<const SpringyEncoding&>(*bare).organism_template,
            dynamic_cast<const SpringyEncoding&>(*from_file).organism_template);
  EXPECT_EQ(bare->random(1, 0, 0), from_file->random(1, 0, 0));
}

// random genomes: the template's morphology, valid, a pure function of (seed, generation,
// individual); with frozen frequency every moving muscle has it, through mutation and crossover
TEST(SpringyEncoding, RandomGenomesKeepTheMorphologyAndFrozenFrequencyHolds) {
  auto encoding = configured({{"springy.organism", kSnake},
                              {"springy.evolve_frequency", "false"},
                              {"springy.frozen_frequency", "1"}});
  const auto& springy = dynamic_cast<const SpringyEncoding&>(*encoding);
  const Genotype a = encoding->random(7, 0, 3);
  EXPECT_EQ(a, encoding->random(7, 0, 3));
  EXPECT_NE(a, encoding->random(7, 0, 4));
  EXPECT_TRUE(sameMorphology(organismOf(a), springy.organism_template));
  EXPECT_NO_THROW(encoding->validate(a));
  Rng rng(7, RngPurpose::test);
  Genotype child = a;
  for (int k = 0; k < 50; ++k) {
    child = k % 2 == 0
                ? encoding->mutate(child, 0.1, rng)
                : encoding->combine(Variation::crossover, child,
                                    encoding->random(7, 1, static_cast<std::uint64_t>(k)), rng);
    ASSERT_NO_THROW(encoding->validate(child));
    for (const Tube& tube : organismOf(child).tubes) {
      if (tube.kind == TubeKind::muscle) {
        EXPECT_EQ(tube.muscle.frequency, 1.0);
      }
    }
  }
  EXPECT_TRUE(sameMorphology(organismOf(child), springy.organism_template));
  // a muscle at another frequency breaks the frozen rule
  Organism other = organismOf(child);
  for (Tube& tube : other.tubes) {
    if (tube.kind == TubeKind::muscle && tube.muscle.amplitude > 0)
      tube.muscle.frequency = 0.5;
  }
  EXPECT_THROW(encoding->validate(makeGenotype(other)), GenomeError);
  // the springy organisms have mutation and crossover only
  EXPECT_TRUE(encoding->supports(Variation::crossover));
  EXPECT_FALSE(encoding->supports(Variation::graft));
  EXPECT_THROW(encoding->combine(Variation::graft, a, a, rng), GenomeError);
}

// both written forms give the genome back; the bytes start with the encoding's tag
TEST(SpringyEncoding, WrittenFormsRoundTrip) {
  auto encoding = configured({{"springy.organism", kSnake}});
  const Genotype genome = encoding->random(3, 0, 0);
  EXPECT_EQ(encoding->fromText(encoding->toText(genome), "test"), genome);
  const std::vector<std::uint8_t>& bytes = genome.bytes();
  EXPECT_EQ(decodeGenome(bytes.data(), bytes.size()), genome);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "CMBS");
}

// development: a part per body, an effector and a sinusoid per muscle
TEST(SpringyEncoding, DevelopsOneEffectorPerMuscle) {
  auto encoding = configured({{"springy.organism", kSnake}});
  const Genotype genome = encoding->random(3, 0, 0);
  const Creature creature = encoding->develop(genome);
  EXPECT_EQ(creature.body.effectors.size(), 6u);
  ASSERT_TRUE(creature.controller);
  EXPECT_EQ(creature.controller->kind(), "lengths");
  EXPECT_NO_THROW(creature.controller->build(0.01, 0, 6));
  EXPECT_THROW(creature.controller->build(0.01, 0, 5), Error);
  EXPECT_EQ(encoding->size(genome).genes, 7u);
  EXPECT_EQ(encoding->size(genome).links, 6u);
}

}  // namespace
}  // namespace cambrian::springy
