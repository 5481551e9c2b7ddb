// cambrian: genetic operators on the directed-graph genome (Sims 1994, Chaumont et al. 2007).
#pragma once

#include "cambrian/rng.hpp"

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::graph {

/// How mutation behaves. Rates are per mutable parameter or per structural opportunity.
struct MutationSettings {
  double parameter_rate = 0.10;  ///< chance each parameter is perturbed (Chaumont: 10 %)
  double perturbation = 0.25;    ///< perturbation scale, as a fraction of the parameter's range
  double add_node_rate = 0.05;   ///< chance to add a random node (and a connection to it)
  double remove_node_rate = 0.03;
  double add_connection_rate = 0.05;
  double remove_connection_rate = 0.03;
  double repoint_rate = 0.05;  ///< chance each connection is re-pointed to another node
  double add_neuron_rate = 0.05;
  double remove_neuron_rate = 0.03;
  bool keep_unconnected =
      true;  ///< keep nodes unreachable from the root (Chaumont) or collect them
};

/// Sims' mutation: parameter perturbation scaled to each parameter's range, node and connection
/// insertion and removal, re-pointing, neuron insertion and removal. Result is valid under limits.
Genome mutate(const Genome& parent, const GenomeLimits& limits, const MutationSettings& settings,
              Rng& rng);

/// Sims' crossover: nodes of both parents aligned by index, copied from one parent and then the
/// other at crossover points; a catapult's arm (node 0) and projectile come from `a`. Result is
/// valid under limits.
Genome crossover(const Genome& a, const Genome& b, const GenomeLimits& limits, Rng& rng);

/// Which node of the second parent grafting leads into.
enum class GraftInto : std::uint8_t {
  root,      ///< its root, so that its whole body comes along
  any_node,  ///< a node drawn uniformly (Sims' grafting)
};

/// Sims' grafting: a copy of `a` with one of its connections re-pointed into a copy of `b`'s
/// graph appended to it, at `b`'s root or at a random node of it; `b`'s nodes that then cannot
/// be reached are dropped (a catapult's arm and projectile stay `a`'s). Result is valid under
/// limits.
Genome graft(const Genome& a, const Genome& b, const GenomeLimits& limits, Rng& rng,
             GraftInto into = GraftInto::root);

/// Removes nodes unreachable from the root, renumbering connections (pass an rvalue to collect in
/// place, without a copy).
Genome removeUnreachableNodes(Genome genome);

}  // namespace cambrian::graph
