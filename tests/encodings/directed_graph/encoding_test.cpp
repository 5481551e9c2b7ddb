// Tests of the directed-graph encoding behind the Encoding interface: each operation is the
// graph function it wraps, under the encoding's settings; the byte form keeps today's files;
// every genome.* key a validation message names is a declared setting.
#include "encodings/directed_graph/encoding.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "core/settings.hpp"
#include "encodings/directed_graph/graph.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace cambrian::graph {
namespace {

const std::string kCreatures = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";

TEST(DirectedGraphEncoding, OperationsAreTheGraphFunctions) {
  DirectedGraphEncoding encoding;
  encoding.limits.max_parts = 12;
  encoding.mutation.add_node_rate = 0.5;
  for (std::uint64_t i = 0; i < 30; ++i) {
    Genotype genome = encoding.random(9, 1, i);
    EXPECT_EQ(graphGenome(genome), randomGenome(encoding.limits, 9, 1, i));
    EXPECT_NO_THROW(encoding.validate(genome));

    // development under the encoding's limits
    Creature creature = encoding.develop(genome);
    Creature direct = develop(graphGenome(genome), encoding.limits);
    EXPECT_EQ(creature.body.parts.size(), direct.body.parts.size());
    EXPECT_LE(creature.body.parts.size(), 12u);
    ASSERT_TRUE(creature.controller);

    // mutation with the given parameter rate and the encoding's structural rates
    Rng a(4, RngPurpose::test, 0, i), b(4, RngPurpose::test, 0, i);
    MutationSettings settings = encoding.mutation;
    settings.parameter_rate = 0.3;
    EXPECT_EQ(graphGenome(encoding.mutate(genome, 0.3, a)),
              mutate(graphGenome(genome), encoding.limits, settings, b));

    // crossover and grafting
    Genotype other = encoding.random(9, 2, i);
    Rng c(5, RngPurpose::test, 0, i), d(5, RngPurpose::test, 0, i);
    EXPECT_EQ(graphGenome(encoding.combine(Variation::crossover, genome, other, c)),
              crossover(graphGenome(genome), graphGenome(other), encoding.limits, d));
    EXPECT_EQ(graphGenome(encoding.combine(Variation::graft, genome, other, c)),
              graft(graphGenome(genome), graphGenome(other), encoding.limits, d));
  }
  EXPECT_TRUE(encoding.supports(Variation::mutation));
  EXPECT_TRUE(encoding.supports(Variation::graft));
}

TEST(DirectedGraphEncoding, TidyCollectsUnreachableNodesUnlessKept) {
  Genome genome;
  genome.nodes.resize(3);
  genome.connections.push_back(ConnectionGene{});
  genome.connections[0].from = 0;
  genome.connections[0].to = 1;
  DirectedGraphEncoding encoding;
  EXPECT_EQ(graphGenome(encoding.tidy(makeGenotype(genome))).nodes.size(), 3u);
  encoding.mutation.keep_unconnected = false;
  EXPECT_EQ(graphGenome(encoding.tidy(makeGenotype(genome))).nodes.size(), 2u);

  // with nothing to collect the genome comes back as it is (the same genotype, not a copy); a
  // connection to no node is collected
  Genome tidy = genome;
  tidy.nodes.resize(2);
  Genotype kept = makeGenotype(tidy);
  EXPECT_EQ(&encoding.tidy(kept).data(), &kept.data());
  Genome dangling = tidy;
  dangling.connections.push_back(ConnectionGene{});
  dangling.connections[1].to = 9;
  Genotype collected = encoding.tidy(makeGenotype(dangling));
  EXPECT_EQ(graphGenome(collected), tidy);
}

TEST(DirectedGraphEncoding, SizeCountsGenesLinksAndPartSides) {
  DirectedGraphEncoding encoding;
  Genome genome;
  genome.nodes.resize(2);
  genome.nodes[0].dimensions = {0.3, 0.6, 0.9};
  genome.nodes[1].dimensions = {0.1, 0.1, 0.1};
  genome.connections.resize(3);
  GenomeSize size = encoding.size(makeGenotype(genome));
  EXPECT_EQ(size.genes, 2u);
  EXPECT_EQ(size.links, 3u);
  EXPECT_NEAR(size.total_part_size, 0.6 + 0.1, 1e-15);
}

// the byte form is today's: tag "CMBG", version 1; a file written before the renovation reads
TEST(DirectedGraphEncoding, ByteFormIsTaggedAndVersioned) {
  Genotype walker = readGenomeFile(kCreatures + "walker4.genome");
  const std::vector<std::uint8_t>& bytes = walker.bytes();
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "CMBG");
  EXPECT_EQ(bytes[4], 1);
  EXPECT_EQ(bytes, serializeGenome(graphGenome(walker)));
  DirectedGraphEncoding encoding;
  Genotype back = encoding.fromBytes(bytes.data(), bytes.size());
  EXPECT_EQ(graphGenome(back), graphGenome(walker));
  EXPECT_EQ(encoding.fromText(encoding.toText(walker), "walker"), walker);
}

TEST(DirectedGraphEncoding, RefusesGenomesOfAnotherKindOrBeyondItsLimits) {
  DirectedGraphEncoding encoding;
  EXPECT_THROW(encoding.validate(Genotype()), GenomeError);
  encoding.limits.max_nodes = 1;
  Genome two;
  two.nodes.resize(2);
  EXPECT_THROW(encoding.validate(makeGenotype(two)), GenomeError);
}

TEST(DirectedGraphEncoding, DeclaresItsSettingsWithTheirRanges) {
  DirectedGraphEncoding encoding;
  SettingsSchema schema;
  encoding.declareSettings(schema);
  EXPECT_NO_THROW(schema.check());
  schema.set("genome.max_weight", "-1");
  EXPECT_THROW(schema.check(), ConfigError);
  schema.set("genome.max_weight", "2.5");
  schema.set("genome.max_scale", "0.1");  // below min_scale 0.5
  EXPECT_THROW(schema.check(), ConfigError);
  schema.set("genome.max_scale", "3");
  schema.set("evolution.add_node_rate", "0.2");
  EXPECT_NO_THROW(schema.check());
  EXPECT_EQ(encoding.limits.max_weight, 2.5);
  EXPECT_EQ(encoding.limits.max_scale, 3.0);
  EXPECT_EQ(encoding.mutation.add_node_rate, 0.2);
}

// every "genome.<key>" a validation message can name is a key users can set
TEST(DirectedGraphEncoding, EveryKeyAValidationMessageNamesExists) {
  std::ifstream source(std::string(CAMBRIAN_SOURCE_DIR) +
                       "/src/encodings/directed_graph/validate.cpp");
  std::stringstream text;
  text << source.rdbuf();
  const std::string code = text.str();
  ASSERT_FALSE(code.empty());
  DirectedGraphEncoding encoding;
  SettingsSchema schema;
  encoding.declareSettings(schema);
  std::set<std::string> named;
  const std::regex key("\"-?(genome\\.[a-z_]+)\"");
  for (auto it = std::sregex_iterator(code.begin(), code.end(), key); it != std::sregex_iterator();
       ++it)
    named.insert((*it)[1]);
  EXPECT_GE(named.size(), 10u);
  for (const std::string& name : named)
    EXPECT_NE(schema.find(name), nullptr) << name << " is named by validate.cpp but not declared";
}

// genome.joint_types: names known, each once, at least one; the mask follows them
TEST(DirectedGraphEncoding, JointTypesAreASetOfNames) {
  DirectedGraphEncoding encoding;
  SettingsSchema schema;
  encoding.declareSettings(schema);
  EXPECT_EQ(encoding.limits.joint_types, 0xF);
  schema.set("genome.joint_types", "rigid revolute");
  EXPECT_NO_THROW(schema.check());
  EXPECT_EQ(encoding.limits.joint_types, 0x3);
  for (const char* bad : {"revolute wheel", "", "revolute revolute"}) {
    schema.set("genome.joint_types", bad);
    EXPECT_THROW(schema.check(), ConfigError) << bad;
  }
}

// Chaumont et al.'s one-degree-of-freedom joints: random genomes, every operator and every
// developed body keep to them, and a genome with a universal joint is refused by name
TEST(DirectedGraphEncoding, OneDegreeOfFreedomJointsOnlyHoldUnderEveryOperator) {
  DirectedGraphEncoding encoding;
  SettingsSchema schema;
  encoding.declareSettings(schema);
  schema.set("genome.joint_types", "rigid revolute");
  schema.set("evolution.add_node_rate", "0.5");
  schema.check();
  auto expectOneDof = [&](const Genotype& genome, const char* what, std::uint64_t i) {
    for (const PartGene& node : graphGenome(genome).nodes)
      EXPECT_LE(degreesOfFreedom(node.joint_type), 1) << what << " " << i;
    EXPECT_NO_THROW(encoding.validate(genome)) << what << " " << i;
    for (const PartPlan& part : encoding.develop(genome).body.parts)
      EXPECT_LE(degreesOfFreedom(part.joint), 1) << what << " " << i;
  };
  std::set<JointType> seen;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Genotype genome = encoding.random(3, 0, i);
    expectOneDof(genome, "random", i);
    for (const PartGene& node : graphGenome(genome).nodes)
      seen.insert(node.joint_type);
    Rng rng(6, RngPurpose::test, 0, i);
    Genotype mutant = encoding.tidy(encoding.mutate(genome, 1.0, rng));
    expectOneDof(mutant, "mutation", i);
    for (const PartGene& node : graphGenome(mutant).nodes)
      seen.insert(node.joint_type);
    Genotype other = encoding.random(3, 1, i);
    expectOneDof(encoding.tidy(encoding.combine(Variation::crossover, genome, other, rng)),
                 "crossover", i);
    expectOneDof(encoding.tidy(encoding.combine(Variation::graft, genome, other, rng)), "graft", i);
  }
  EXPECT_EQ(seen, (std::set<JointType>{JointType::fixed, JointType::revolute}));

  try {
    encoding.validate(readGenomeFile(kCreatures + "walker4.genome"));
    ADD_FAILURE() << "a universal joint passed genome.joint_types = rigid revolute";
  } catch (const GenomeError& error) {
    EXPECT_NE(std::string(error.what()).find("joint universal is not among genome.joint_types"),
              std::string::npos)
        << error.what();
  }
}

// genome.neuron_set = chaumont: random genomes and mutants use only Chaumont et al.'s functions
// (each of them), their networks are bounded to +-1, and a Sims function is refused by name
TEST(DirectedGraphEncoding, ChaumontNeuronSetHoldsUnderEveryOperator) {
  DirectedGraphEncoding encoding;
  SettingsSchema schema;
  encoding.declareSettings(schema);
  schema.set("genome.neuron_set", "chaumont");
  schema.check();
  const std::set<NeuronFunction> chaumont{NeuronFunction::constant,      NeuronFunction::sum,
                                          NeuronFunction::product,       NeuronFunction::sum_above,
                                          NeuronFunction::divide_or_one, NeuronFunction::delay,
                                          NeuronFunction::wave};
  std::set<NeuronFunction> seen;
  auto collect = [&](const Genotype& genome, std::uint64_t i) {
    EXPECT_NO_THROW(encoding.validate(genome)) << i;
    for (const PartGene& node : graphGenome(genome).nodes)
      for (const NeuronGene& neuron : node.neurons)
        seen.insert(neuron.function);
    for (const NeuronGene& neuron : graphGenome(genome).brain)
      seen.insert(neuron.function);
  };
  for (std::uint64_t i = 0; i < 200; ++i) {
    Genotype genome = encoding.random(4, 0, i);
    collect(genome, i);
    Rng rng(7, RngPurpose::test, 0, i);
    collect(encoding.tidy(encoding.mutate(genome, 1.0, rng)), i);
    Creature creature = encoding.develop(genome);
    const auto* network = dynamic_cast<const NeuralNetworkPlan*>(creature.controller.get());
    if (network) {
      EXPECT_EQ(network->signal_bound, 1.0);
    }
  }
  EXPECT_EQ(seen, chaumont);

  Genome sims;
  sims.nodes.resize(1);
  NeuronGene sine;
  sine.function = NeuronFunction::sin;
  sims.nodes[0].neurons.push_back(sine);
  try {
    encoding.validate(makeGenotype(sims));
    ADD_FAILURE() << "sin passed genome.neuron_set = chaumont";
  } catch (const GenomeError& error) {
    EXPECT_NE(std::string(error.what()).find("function sin is not in genome.neuron_set chaumont"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace cambrian::graph
