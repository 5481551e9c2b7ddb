// cambrian: graph edits on a genome (reachability from the root, node removal with renumbering).
#pragma once

#include "encodings/directed_graph/genome.hpp"

#include <vector>

namespace cambrian::graph {

/// reachable[i] is true when node i can be reached from node 0 along connections (node 0
/// itself included when the genome has nodes). Connections with out-of-range ends are ignored.
std::vector<bool> reachableNodes(const Genome& genome);

/// Keeps the nodes with keep[i] true (in order), renumbers connections and drops every
/// connection whose `from` or `to` is removed or out of range. keep.size() must equal the
/// node count.
void removeNodes(Genome& genome, const std::vector<bool>& keep);

/// Whether removeNodes(genome, keep) would leave the genome as it is: every node kept and every
/// connection's ends in range.
bool removesNothing(const Genome& genome, const std::vector<bool>& keep);

}  // namespace cambrian::graph
