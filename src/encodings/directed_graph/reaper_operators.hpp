// cambrian: Minemonics' variation operators on the directed graph — the reaper's gene
// specification, gene split, gene purge, branch specification and grow-stub mutations and its
// feature graft (a morphogene is a node, a morphogene branch a connection).
#pragma once

#include "cambrian/rng.hpp"

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::graph {

/// The operators' chances and sizes ([evolution] keys; Minemonics' numbers by default).
struct ReaperOperatorSettings {
  double gene_specification_chance = 0.2;    ///< per node: re-drawn
  double gene_split_chance = 0.2;            ///< per node: split in two
  double branch_specification_chance = 0.2;  ///< per node: one of its connections re-drawn
  double grow_stub_chance = 0.6;             ///< per node: gets 0..grow_stub_max connections
  int grow_stub_max = 2;
  int graft_depth_min = 5;  ///< a feature graft copies 5..10 levels of genes
  int graft_depth_max = 10;
  int segment_branch_redraws = 10;  ///< a segment crossover re-draws 10 random connections
};

/// Gene specification: each node, with gene_specification_chance, is replaced by a random node
/// (its body, local neurons and effectors); connections are kept.
Genome specifyGenes(const Genome& parent, const GenomeLimits& limits,
                    const ReaperOperatorSettings& settings, Rng& rng);

/// Gene split: each node, with gene_split_chance, is halved along x, y or z, and the other half
/// becomes a new node joined to it on that face by a joint that cannot move (rigid where
/// genome.joint_types allows it, else a joint of limit 0), without neurons or effectors. The two
/// halves have the node's volume; a node whose half would be below genome.min_part_size, or a
/// genome at its node or connection limit, is not split.
Genome splitGenes(const Genome& parent, const GenomeLimits& limits,
                  const ReaperOperatorSettings& settings, Rng& rng);

/// Gene purge: one node other than the root is re-drawn (as by gene specification) and every
/// connection from another node into it is removed, so it no longer develops unless other
/// connections lead to it again. A one-node genome is returned unchanged.
Genome purgeGene(const Genome& parent, const GenomeLimits& limits, Rng& rng);

/// Branch specification: each node with connections, with branch_specification_chance, has one
/// of them (drawn uniformly) re-drawn with the same ends.
Genome specifyBranches(const Genome& parent, const GenomeLimits& limits,
                       const ReaperOperatorSettings& settings, Rng& rng);

/// Grow stub: each node, with grow_stub_chance, gets 0..grow_stub_max new random connections to
/// nodes drawn uniformly (itself included), within genome.max_connections.
Genome growStubs(const Genome& parent, const GenomeLimits& limits,
                 const ReaperOperatorSettings& settings, Rng& rng);

/// The genes of `donor` from `first` on, `depth` levels deep: `first` and every node reached from
/// it along at most depth - 1 connections, in breadth-first order (`first` becomes node 0), with
/// the connections between them. No brain neurons, no projectile.
Genome featureOf(const Genome& donor, std::uint16_t first, int depth);

/// Feature graft: a random node of `donor` and graft_depth_min..graft_depth_max levels below it
/// (featureOf) copied into `receiver`, which one of its connections (or a new one) leads into.
Genome graftFeature(const Genome& receiver, const Genome& donor, const GenomeLimits& limits,
                    const ReaperOperatorSettings& settings, Rng& rng);

/// Minemonics' crossover: a run of `mother`'s genes (first..last, drawn uniformly, at least one)
/// followed by a run of `father`'s (first up to an end drawn from first..its last gene, possibly
/// none), each gene with the connections leaving it. A connection whose end lies in its segment
/// keeps it; one whose end does not is led into a child gene drawn uniformly (the repair that
/// joins the segments); then segment_branch_redraws connections drawn uniformly are re-drawn
/// with the same ends. The mother's first gene is the child's root; the brain and projectile are
/// the mother's.
Genome crossSegments(const Genome& mother, const Genome& father, const GenomeLimits& limits,
                     const ReaperOperatorSettings& settings, Rng& rng);

}  // namespace cambrian::graph
