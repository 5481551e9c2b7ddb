// cambrian: reachability, node removal and garbage collection of the genome graph.
#include "encodings/directed_graph/graph.hpp"

#include "encodings/directed_graph/operators.hpp"

#include <cstdint>

namespace cambrian::graph {

std::vector<bool> reachableNodes(const Genome& genome) {
  std::size_t n = genome.nodes.size();
  std::vector<bool> reached(n, false);
  if (n == 0)
    return reached;

  // depth-first search from the root over valid connections
  std::vector<std::size_t> stack{0};
  reached[0] = true;
  while (!stack.empty()) {
    std::size_t node = stack.back();
    stack.pop_back();
    for (const ConnectionGene& c : genome.connections) {
      if (c.from != node || c.to >= n || reached[c.to])
        continue;
      reached[c.to] = true;
      stack.push_back(c.to);
    }
  }
  return reached;
}

void removeNodes(Genome& genome, const std::vector<bool>& keep) {
  std::size_t n = genome.nodes.size();

  // new index of every kept node
  std::vector<int> renumber(n, -1);
  std::vector<PartGene> nodes;
  for (std::size_t i = 0; i < n; ++i) {
    if (i < keep.size() && keep[i]) {
      renumber[i] = static_cast<int>(nodes.size());
      nodes.push_back(std::move(genome.nodes[i]));
    }
  }
  genome.nodes = std::move(nodes);

  // connections between kept nodes survive, renumbered
  std::vector<ConnectionGene> connections;
  for (ConnectionGene& c : genome.connections) {
    if (c.from >= n || c.to >= n || renumber[c.from] < 0 || renumber[c.to] < 0)
      continue;
    c.from = static_cast<std::uint16_t>(renumber[c.from]);
    c.to = static_cast<std::uint16_t>(renumber[c.to]);
    connections.push_back(c);
  }
  genome.connections = std::move(connections);
}

bool removesNothing(const Genome& genome, const std::vector<bool>& keep) {
  const std::size_t n = genome.nodes.size();
  if (keep.size() < n)
    return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i])
      return false;
  }
  for (const ConnectionGene& c : genome.connections) {
    if (c.from >= n || c.to >= n)
      return false;
  }
  return true;
}

Genome removeUnreachableNodes(Genome genome) {
  const std::vector<bool> reachable = reachableNodes(genome);
  removeNodes(genome, reachable);
  return genome;
}

}  // namespace cambrian::graph
