// cambrian: Walking with Dinosaurs' mutation and Mtree crossover.
#include "encodings/wwd/operators.hpp"

#include "cambrian/rng.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace cambrian::wwd {

namespace {

// the Mtree's points of a creature by kind (CrossoverPoint::Kind joint, subnet, main_net), and
// the joints' screw genes
struct Mtree {
  std::array<std::vector<GeneSpan>, 4> points;
  std::vector<std::size_t> screws;
};

Mtree mtreeOf(const CreatureGenes& genes) {
  using Kind = CrossoverPoint::Kind;
  Mtree tree;
  for (const JointGenes& joint : genes.joints) {
    tree.points[static_cast<std::size_t>(Kind::joint)].push_back(joint.span);
    tree.screws.push_back(joint.screw_gene);
    tree.points[static_cast<std::size_t>(Kind::subnet)].push_back(joint.subnet.span);
  }
  tree.points[static_cast<std::size_t>(Kind::main_net)].push_back(genes.main.span);
  return tree;
}

}  // namespace

Gene halfTurn(Gene screw) {
  return static_cast<Gene>((screw + kGeneValues / 2) % kGeneValues);
}

Dna mutateDna(const Dna& dna, double rate, Rng& rng) {
  Dna child = dna;
  if (child.empty())
    return child;
  const double chance = rate > 0 ? rate : 1.0 / static_cast<double>(child.size());
  for (Gene& gene : child) {
    if (rng.bernoulli(chance))
      gene = static_cast<Gene>(rng.below(kGeneValues));
  }
  return child;
}

Dna crossDna(const Dna& receiver, const Dna& donor, const GrammarSettings& settings, Rng& rng,
             CrossoverPoint* point) {
  using Kind = CrossoverPoint::Kind;
  const Mtree to = mtreeOf(readCreature(receiver, settings));
  const Mtree from = mtreeOf(readCreature(donor, settings));
  // a point of the receiver, drawn uniformly over all its points, and its kind
  std::size_t pick = rng.below(to.points[1].size() + to.points[2].size() + to.points[3].size());
  std::size_t kind = 1;
  while (pick >= to.points[kind].size()) {
    pick -= to.points[kind].size();
    ++kind;
  }
  const std::vector<GeneSpan>& donors = from.points[kind];
  if (donors.empty()) {
    if (point)
      *point = {};
    return receiver;
  }
  const GeneSpan target = to.points[kind][pick];
  const std::size_t chosen = rng.below(donors.size());
  const GeneSpan source = donors[chosen];
  const bool joint = kind == static_cast<std::size_t>(Kind::joint);

  // the donor's genes, zeros where it reads past its end
  std::vector<Gene> copied(source.size(), 0);
  for (std::size_t i = source.begin; i < source.end && i < donor.size(); ++i)
    copied[i - source.begin] = donor[i];
  if (joint) {
    Gene& screw = copied[from.screws[chosen] - source.begin];
    screw = halfTurn(screw);
  }

  Dna child(receiver.begin(), receiver.begin() + static_cast<std::ptrdiff_t>(
                                                     std::min(target.begin, receiver.size())));
  child.resize(target.begin, 0);
  child.insert(child.end(), copied.begin(), copied.end());
  if (target.end < receiver.size())
    child.insert(child.end(), receiver.begin() + static_cast<std::ptrdiff_t>(target.end),
                 receiver.end());
  if (point)
    *point = {static_cast<Kind>(kind), target, source};
  return child;
}

}  // namespace cambrian::wwd
