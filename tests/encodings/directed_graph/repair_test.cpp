#include "encodings/directed_graph/repair.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/rng.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cambrian::graph {
namespace {

// a valid genome is left exactly as it is
TEST(FitToLimits, ValidGenomeUnchanged) {
  GenomeLimits limits;
  for (std::uint64_t i = 0; i < 500; ++i) {
    Genome genome = randomGenome(limits, 21, 0, i);
    Genome fitted = genome;
    fitToLimits(fitted, limits);
    EXPECT_EQ(fitted, genome);
  }
}

// garbage of every kind becomes valid
TEST(FitToLimits, GarbageBecomesValid) {
  GenomeLimits limits;
  Rng rng(5, RngPurpose::test);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {nan, -1e300, 1e300, -3.5,
                           0,   0.01,   7,     std::numeric_limits<double>::infinity()};
  auto any = [&]() { return values[rng.below(8)]; };
  for (int trial = 0; trial < 300; ++trial) {
    Genome g;
    g.nodes.resize(rng.below(30));
    for (PartGene& node : g.nodes) {
      node.shape = static_cast<PartShape>(rng.below(256));
      node.dimensions = {any(), any(), any()};
      node.density = any();
      node.joint_type = static_cast<JointType>(rng.below(256));
      node.joint_limit = {any(), any(), any()};
      node.recursive_limit = static_cast<std::uint8_t>(rng.below(256));
      node.neurons.resize(rng.below(10));
      for (NeuronGene& n : node.neurons) {
        n.function = static_cast<NeuronFunction>(rng.below(256));
        n.parameter = any();
        n.inputs.resize(rng.below(6));
        for (NeuronInput& in : n.inputs) {
          in.source = static_cast<SignalSource>(rng.below(256));
          in.weight = any();
        }
      }
      node.effectors.resize(rng.below(6));
      for (EffectorGene& e : node.effectors)
        e.input.weight = any();
    }
    g.connections.resize(rng.below(50));
    for (ConnectionGene& c : g.connections) {
      c.from = static_cast<std::uint16_t>(rng.below(40));
      c.to = static_cast<std::uint16_t>(rng.below(40));
      c.position = {any(), any(), any()};
      c.orientation = {any(), any(), any()};
      c.scale = any();
      c.reflection = static_cast<std::uint8_t>(rng.below(256));
      c.controller = {true, any(), any(), any(), any()};
    }
    g.brain.resize(rng.below(12));
    fitToLimits(g, limits);
    ASSERT_NO_THROW(validateGenome(g, limits)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace cambrian::graph
