// cambrian: the neuron sets of the directed-graph encoding (genome.neuron_set).
#include "encodings/directed_graph/gene_ranges.hpp"

#include <algorithm>
#include <array>

namespace cambrian::graph {

namespace {

// every function cambrian had before the chaumont set: the enumeration up to oscillate_saw
constexpr std::size_t kSimsCount = static_cast<std::size_t>(NeuronFunction::oscillate_saw) + 1;
constexpr std::array<NeuronFunction, kSimsCount> kSimsSet = [] {
  std::array<NeuronFunction, kSimsCount> set{};
  for (std::size_t i = 0; i < kSimsCount; ++i)
    set[i] = static_cast<NeuronFunction>(i);
  return set;
}();

// Chaumont et al. 2007, Table I: cst, sum, mul, sumT, div, mem, wav (sen and eff are the
// sensors and effectors)
constexpr std::array<NeuronFunction, 7> kChaumontSet = {
    NeuronFunction::constant,  NeuronFunction::sum,           NeuronFunction::product,
    NeuronFunction::sum_above, NeuronFunction::divide_or_one, NeuronFunction::delay,
    NeuronFunction::wave};

}  // namespace

std::span<const NeuronFunction> neuronSet(const GenomeLimits& limits) {
  if (limits.neuron_set == NeuronSet::chaumont)
    return kChaumontSet;
  return kSimsSet;
}

bool neuronFunctionAllowed(const GenomeLimits& limits, NeuronFunction function) {
  const std::span<const NeuronFunction> set = neuronSet(limits);
  return std::find(set.begin(), set.end(), function) != set.end();
}

const char* neuronSetName(NeuronSet set) {
  return set == NeuronSet::chaumont ? "chaumont" : "sims";
}

}  // namespace cambrian::graph
