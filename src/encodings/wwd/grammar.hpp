// cambrian: Walking with Dinosaurs' DNA and its grammar (the seed's appendix B): a string of
// genes read left to right, chooser genes picking each rule's case, zeros read past the end. The
// reading gives the creature's genes and its Mtree: where each joint's and each net's genes lie.
#pragma once

#include "cambrian/math.hpp"

#include "brain/layered_network.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cambrian {
class Rng;
}

namespace cambrian::wwd {

/// A gene: an integer in [0, kGeneValues).
using Gene = std::uint16_t;
/// Genes take kGeneValues values (the seed's largest chooser reads 0..999).
constexpr int kGeneValues = 1000;

/// The DNA string.
using Dna = std::vector<Gene>;

/// The grammar's limits and the numbers its genes are read into (the wwd.* settings).
struct GrammarSettings {
  int max_boxes = 15;           ///< "we are limited to 15 boxes each world"
  double min_side = 0.05;       ///< m, "within bullets specifications 0.05 to 10"
  double max_side = 10;         ///< m
  double max_joint_limit = 85;  ///< degrees, "in the range of +-85 in each direction"
  int main_net_size = 5;        ///< the most probable nodes per layer of the main net
  int subnet_size = 3;          ///< the same for a joint's subnet
  /// weights and constant values: max_weight (g - 500) / 500, 0 at g = 500
  double max_weight = 5;
  friend bool operator==(const GrammarSettings&, const GrammarSettings&) = default;
};

/// A run of genes [begin, end); end may pass the DNA's end (zeros read there).
struct GeneSpan {
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
};

/// A point on a box face: face `side` (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z) at (u, v) in [-1, 1)
/// (a gene g reads (g - 500) / 500) in units of the half-sides of its two other axes (the next axis
/// after the face's, then the one after).
struct FacePoint {
  int side = 0;
  double u = 0, v = 0;
};

/// Bi ::= h w d Se. Box sides, and whether it has a pressure sensor.
struct BoxGenes {
  Vec3 size;
  bool pressure_sensor = false;
};

/// Ni: a node as read, its input genes not yet resolved (its previous layer is known only
/// after the whole DNA is read: the seed's "subnets are buffered").
struct NodeGenes {
  LayeredFunction function = LayeredFunction::constant;
  double value = 0;  ///< constant nodes
  int input_count = 0;
  std::array<Gene, 3> inputs{};  ///< index genes, taken modulo the previous layer's size
  std::array<double, 3> weights{};
};

/// NN: layers of nodes, and where its genes lie.
struct NetGenes {
  std::vector<std::vector<NodeGenes>> layers;
  GeneSpan span;
};

/// J ::= NN E screw PRE POST DOF Bi B: the joint that makes box `child` on box `parent`.
struct JointGenes {
  int parent = 0, child = 1;
  NetGenes subnet;
  std::array<Gene, 3> effector{};  ///< node index genes into the subnet's last layer
  double screw = 0;                ///< radians about the joint's normal
  std::size_t screw_gene = 0;      ///< the screw gene's position in the DNA
  FacePoint pre, post;             ///< on the parent box, on the child box
  Vec3 limit;                      ///< radians per axis
  GeneSpan span;                   ///< the joint and everything built on its child box
};

/// A creature as the grammar reads it: boxes in reading order (box 0 the root), joint j makes
/// box j + 1, the main net read last.
struct CreatureGenes {
  std::vector<BoxGenes> boxes;
  std::vector<JointGenes> joints;
  NetGenes main;
  std::size_t genes_read = 0;  ///< past the DNA's end when zeros were read
  bool truncated = false;      ///< some box count was cut to the box limit
};

/// Reads `dna` by the grammar.
CreatureGenes readCreature(const Dna& dna, const GrammarSettings& settings);
/// The DNA the grammar reads as `genes` (its spans and counters not used): each chooser the
/// smallest gene of its case, each number the nearest gene. Exact for what readCreature gives:
/// readCreature(writeCreature(g)) == g but for spans, genes_read and truncated. Throws GenomeError
/// naming the box, joint or net when `genes` cannot be written (a joint on a later box, a layer
/// size no chooser gives, more boxes than the limit).
Dna writeCreature(const CreatureGenes& genes, const GrammarSettings& settings);
/// A random creature's DNA: the grammar read over genes drawn uniformly as it needs them.
Dna randomDna(const GrammarSettings& settings, Rng& rng);

/// How many nodes a layer gets for chooser gene `chooser` when `most_probable` is the most
/// probable count: most_probable -+ i with chance 300 / 2^i per mille each, i = 1 .. until
/// most_probable - i reaches 0, the rest most_probable (the seed's section 3.2).
int layerSize(Gene chooser, int most_probable);
/// How many layers a net gets for chooser gene `chooser` (its value mod 100: 0-14 one layer,
/// 15-39 two, 40-84 three, 85-99 four).
int layerCount(Gene chooser);

}  // namespace cambrian::wwd
