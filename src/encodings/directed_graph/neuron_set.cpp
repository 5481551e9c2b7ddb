// cambrian: the neuron sets of the directed-graph encoding (genome.neuron_set).
#include "encodings/directed_graph/gene_ranges.hpp"

#include <algorithm>
#include <array>

namespace cambrian::graph {

namespace {

// every function cambrian had before the chaumont set, in enumeration order
constexpr std::array<NeuronFunction, 24> kSimsSet = {NeuronFunction::constant,
                                                     NeuronFunction::sum,
                                                     NeuronFunction::product,
                                                     NeuronFunction::divide,
                                                     NeuronFunction::sum_threshold,
                                                     NeuronFunction::greater_than,
                                                     NeuronFunction::sign_of,
                                                     NeuronFunction::min,
                                                     NeuronFunction::max,
                                                     NeuronFunction::abs,
                                                     NeuronFunction::if_positive,
                                                     NeuronFunction::interpolate,
                                                     NeuronFunction::sin,
                                                     NeuronFunction::cos,
                                                     NeuronFunction::atan,
                                                     NeuronFunction::log,
                                                     NeuronFunction::expt,
                                                     NeuronFunction::sigmoid,
                                                     NeuronFunction::integrate,
                                                     NeuronFunction::differentiate,
                                                     NeuronFunction::smooth,
                                                     NeuronFunction::memory,
                                                     NeuronFunction::oscillate_wave,
                                                     NeuronFunction::oscillate_saw};
static_assert(static_cast<int>(NeuronFunction::oscillate_saw) == 23);

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
