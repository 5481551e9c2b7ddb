// cambrian: bringing any genome within GenomeLimits (the last step of every operator).
#pragma once

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::graph {

/// Makes `genome` pass validateGenome(genome, limits) while changing as little as possible:
/// adds a default root if there are no nodes; truncates nodes, connections, brain neurons,
/// neurons per node, inputs per neuron and effectors per node to their limits; drops
/// connections with out-of-range ends; clamps every number into its range (NaN to the low end);
/// maps out-of-range enumeration values and reflection bits into range. A valid genome is
/// left unchanged.
void fitToLimits(Genome& genome, const GenomeLimits& limits);

}  // namespace cambrian::graph
