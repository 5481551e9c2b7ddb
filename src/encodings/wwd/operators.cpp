// cambrian: Walking with Dinosaurs' mutation and Mtree crossover.
#include "encodings/wwd/operators.hpp"

#include "cambrian/rng.hpp"

#include <algorithm>
#include <vector>

namespace cambrian::wwd {

namespace {

// the Mtree's points of a creature: its joints' spans (with their screw genes) and its nets'
struct Mtree {
  std::vector<GeneSpan> joints, nets;
  std::vector<std::size_t> screws;
};

Mtree mtreeOf(const CreatureGenes& genes) {
  Mtree tree;
  for (const JointGenes& joint : genes.joints) {
    tree.joints.push_back(joint.span);
    tree.screws.push_back(joint.screw_gene);
    tree.nets.push_back(joint.subnet.span);
  }
  tree.nets.push_back(genes.main.span);
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
  const Mtree to = mtreeOf(readCreature(receiver, settings));
  const Mtree from = mtreeOf(readCreature(donor, settings));
  const std::size_t points = to.joints.size() + to.nets.size();
  const std::size_t pick = rng.below(points);
  const bool joint = pick < to.joints.size();
  const std::vector<GeneSpan>& donors = joint ? from.joints : from.nets;
  if (donors.empty()) {
    if (point)
      *point = {};
    return receiver;
  }
  const GeneSpan target = joint ? to.joints[pick] : to.nets[pick - to.joints.size()];
  const std::size_t chosen = rng.below(donors.size());
  const GeneSpan source = donors[chosen];

  // the donor's genes, zeros where it reads past its end
  std::vector<Gene> copied(source.size(), 0);
  for (std::size_t i = source.begin; i < source.end && i < donor.size(); ++i)
    copied[i - source.begin] = donor[i];
  if (joint) {
    Gene& screw = copied[from.screws[chosen] - source.begin];
    screw = halfTurn(screw);
  }

  Dna child(receiver.begin(),
            receiver.begin() + static_cast<std::ptrdiff_t>(std::min(target.begin, receiver.size())));
  child.resize(target.begin, 0);
  child.insert(child.end(), copied.begin(), copied.end());
  if (target.end < receiver.size())
    child.insert(child.end(), receiver.begin() + static_cast<std::ptrdiff_t>(target.end),
                 receiver.end());
  if (point)
    *point = {joint ? CrossoverPoint::Kind::joint : CrossoverPoint::Kind::net, target, source};
  return child;
}

}  // namespace cambrian::wwd
