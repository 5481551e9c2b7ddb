#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/catapult_limits.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cambrian::graph {
namespace {

// a small valid genome touching every kind of gene
Genome sampleGenome() {
  Genome g;
  g.nodes.resize(2);
  g.nodes[0].joint_type = JointType::fixed;
  g.nodes[1].neurons.push_back({NeuronFunction::sum, {{SignalSource::local_sensor, 0, 1, 0.5}}, 1});
  g.nodes[1].effectors.push_back({{SignalSource::local_neuron, 0, 0, 1}});
  ConnectionGene c;
  c.from = 0;
  c.to = 1;
  c.controller.enabled = true;
  c.controller.amplitude = 0.5;
  g.connections.push_back(c);
  g.brain.push_back({NeuronFunction::oscillate_wave, {{SignalSource::constant, 0, 0, 1}}, 1});
  return g;
}

// the limits the expected messages quote, set explicitly (independent of the defaults)
GenomeLimits quotedLimits() {
  GenomeLimits limits;
  limits.max_nodes = 20;
  limits.max_connections = 40;
  limits.max_recursive_limit = 4;
  limits.max_neurons_per_node = 6;
  limits.max_brain_neurons = 8;
  limits.max_inputs = 3;
  limits.min_part_size = 0.05;
  limits.max_part_size = 1.5;
  limits.min_density = 200;
  limits.max_density = 3000;
  limits.max_weight = 5;
  limits.min_scale = 0.5;
  limits.max_scale = 2;
  limits.max_frequency = 4;
  return limits;
}

// the validation message of a genome, or "" when it is valid
std::string failure(const Genome& genome, const GenomeLimits& limits = quotedLimits()) {
  try {
    validateGenome(genome, limits);
  } catch (const GenomeError& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateGenome, SampleIsValid) {
  EXPECT_EQ(failure(sampleGenome()), "");
}

// one case per rule: a change that breaks it and the text the message must contain
struct Case {
  std::function<void(Genome&)> breakIt;
  std::string expected;
};

TEST(ValidateGenome, EachOutOfRangeFieldIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Case> cases = {
      {[](Genome& g) { g.nodes.clear(); }, "no nodes"},
      {[](Genome& g) { g.nodes.resize(21); }, "21 nodes exceed genome.max_nodes 20"},
      {[](Genome& g) { g.connections.resize(41); }, "41 connections exceed genome.max_connections"},
      {[](Genome& g) { g.brain.resize(9); }, "9 brain neurons exceed genome.max_brain_neurons"},
      {[](Genome& g) { g.nodes[1].shape = static_cast<PartShape>(3); }, "node 1: shape = 3"},
      {[](Genome& g) { g.nodes[1].dimensions.y = 0.01; },
       "node 1: dimensions.y = 0.01 is below genome.min_part_size 0.05"},
      {[](Genome& g) { g.nodes[0].dimensions.z = 2; },
       "node 0: dimensions.z = 2 is above genome.max_part_size 1.5"},
      {[nan](Genome& g) { g.nodes[0].dimensions.x = nan; },
       "node 0: dimensions.x = nan is not a number"},
      {[](Genome& g) { g.nodes[1].density = 100; },
       "node 1: density = 100 is below genome.min_density"},
      {[](Genome& g) { g.nodes[1].density = 4000; },
       "node 1: density = 4000 is above genome.max_density"},
      {[](Genome& g) { g.nodes[1].joint_type = static_cast<JointType>(4); },
       "node 1: joint_type = 4"},
      {[](Genome& g) { g.nodes[1].joint_limit.x = -0.1; }, "node 1: joint_limit.x = -0.1 is below"},
      {[](Genome& g) { g.nodes[1].joint_limit.z = 4; }, "node 1: joint_limit.z = 4 is above"},
      {[](Genome& g) { g.nodes[1].recursive_limit = 0; }, "node 1: recursive_limit = 0 is below"},
      {[](Genome& g) { g.nodes[1].recursive_limit = 5; },
       "node 1: recursive_limit = 5 is above genome.max_recursive_limit 4"},
      {[](Genome& g) { g.nodes[1].neurons.resize(7); },
       "node 1: 7 neurons exceed genome.max_neurons_per_node"},
      {[](Genome& g) { g.nodes[1].neurons[0].function = NeuronFunction::count_; },
       "node 1: neuron 0: function = 28"},
      {[](Genome& g) { g.nodes[1].neurons[0].parameter = 11; },
       "node 1: neuron 0: parameter = 11 is above"},
      {[](Genome& g) { g.nodes[1].neurons[0].inputs.resize(4); },
       "node 1: neuron 0: 4 inputs exceed genome.max_inputs 3"},
      {[](Genome& g) { g.nodes[1].neurons[0].inputs[0].weight = -6; },
       "node 1: neuron 0: input 0: weight = -6 is below -genome.max_weight"},
      {[](Genome& g) { g.nodes[1].neurons[0].inputs[0].source = static_cast<SignalSource>(7); },
       "node 1: neuron 0: input 0: source = 7"},
      {[](Genome& g) { g.nodes[1].effectors.resize(4); },
       "node 1: 4 effectors exceed the maximum 3"},
      {[](Genome& g) { g.nodes[1].effectors[0].input.weight = 5.5; },
       "node 1: effector 0: weight = 5.5 is above genome.max_weight 5"},
      {[](Genome& g) { g.connections[0].from = 2; },
       "connection 0: from = 2 but the genome has 2 nodes"},
      {[](Genome& g) { g.connections[0].to = 7; },
       "connection 0: to = 7 but the genome has 2 nodes"},
      {[](Genome& g) { g.connections[0].position.y = 1.5; },
       "connection 0: position.y = 1.5 is above"},
      {[](Genome& g) { g.connections[0].orientation.z = -4; },
       "connection 0: orientation.z = -4 is below"},
      {[](Genome& g) { g.connections[0].scale = 0.1; },
       "connection 0: scale = 0.1 is below genome.min_scale"},
      {[](Genome& g) { g.connections[0].reflection = 8; }, "connection 0: reflection = 8"},
      {[](Genome& g) { g.connections[0].controller.amplitude = 2; },
       "connection 0: controller.amplitude = 2 is above"},
      {[](Genome& g) { g.connections[0].controller.frequency = 5; },
       "connection 0: controller.frequency = 5 is above genome.max_frequency 4"},
      {[](Genome& g) { g.connections[0].controller.phase = 4; },
       "connection 0: controller.phase = 4"},
      {[](Genome& g) { g.connections[0].controller.offset = -1.5; },
       "connection 0: controller.offset = -1.5"},
      {[](Genome& g) { g.brain[0].parameter = -11; }, "brain: neuron 0: parameter = -11 is below"},
      {[](Genome& g) { g.brain[0].inputs[0].weight = 9; }, "brain: neuron 0: input 0: weight = 9"},
  };
  for (const Case& c : cases) {
    Genome g = sampleGenome();
    c.breakIt(g);
    std::string message = failure(g);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected '" << c.expected << "' in '" << message << "'";
  }
}

// limits are honoured, not hard-coded: a larger limit accepts what the default rejects
TEST(ValidateGenome, LimitsAreConfigurable) {
  Genome g = sampleGenome();
  g.nodes[1].recursive_limit = 6;
  EXPECT_NE(failure(g), "");
  GenomeLimits limits = quotedLimits();
  limits.max_recursive_limit = 6;
  EXPECT_EQ(failure(g, limits), "");
}

// boundaries are inclusive
TEST(ValidateGenome, BoundariesAreInclusive) {
  Genome g = sampleGenome();
  GenomeLimits limits;
  g.nodes[1].dimensions = {limits.min_part_size, limits.max_part_size, limits.min_part_size};
  g.nodes[1].joint_limit = {0, kPi, 0};
  g.connections[0].position = {-1, 1, 1};
  g.connections[0].orientation = {-kPi, kPi, 0};
  g.connections[0].scale = limits.max_scale;
  g.connections[0].reflection = 7;
  g.connections[0].controller.frequency = limits.max_frequency;
  g.nodes[1].neurons[0].parameter = 10;
  g.nodes[1].neurons[0].inputs[0].weight = -limits.max_weight;
  g.nodes[1].effectors.resize(3);
  EXPECT_EQ(failure(g), "");
}

// GenomeError carries the input-file exit code
TEST(ValidateGenome, ErrorExitCode) {
  Genome g;
  try {
    validateGenome(g, GenomeLimits{});
    FAIL() << "expected GenomeError";
  } catch (const GenomeError& e) {
    EXPECT_EQ(e.code(), ExitCode::input_file);
  }
}

using test::catapultLimits;

// a projectile in every catapult genome and in no other; its fields within their ranges
TEST(Validate, AProjectileExactlyInCatapults) {
  Genome catapult = randomGenome(catapultLimits(), 5);
  EXPECT_NO_THROW(validateGenome(catapult, catapultLimits()));
  auto message = [](const Genome& g, const GenomeLimits& limits) {
    try {
      validateGenome(g, limits);
    } catch (const GenomeError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(catapult, GenomeLimits{}).find("genome.catapult = false"), std::string::npos);
  Genome walker = randomGenome(GenomeLimits{}, 5);
  EXPECT_NE(message(walker, catapultLimits()).find("has no projectile"), std::string::npos);
  catapult.projectile->dimensions.y = 9;
  EXPECT_NE(message(catapult, catapultLimits()).find("projectile"), std::string::npos);
  EXPECT_NE(message(catapult, catapultLimits()).find("size.y"), std::string::npos);
  // the projectile's own size range, not the parts'
  catapult.projectile->dimensions.y = 0.5;
  GenomeLimits small = catapultLimits();
  small.projectile_max_side = 0.4;
  EXPECT_NE(message(catapult, small).find("genome.projectile_max_side"), std::string::npos);
  catapult.projectile->dimensions.y = 1.6;  // above genome.max_part_size, 1.5
  GenomeLimits large = catapultLimits();
  large.projectile_max_side = 2;
  EXPECT_NO_THROW(validateGenome(catapult, large));
}
}  // namespace
}  // namespace cambrian::graph
