// cambrian: reading Walking with Dinosaurs' DNA by its grammar.
#include "encodings/wwd/grammar.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cambrian::wwd {

namespace {

// the largest gene value, the denominator of every fraction a gene is read into
constexpr double kTopGene = kGeneValues - 1;
// B ::= count J^count: the count's cases (0..5 joints on a box)
constexpr int kJointCases = 6;
// Ni: its chooser's cases (a value node, or a function of 1, 2 or 3 inputs)
constexpr int kNodeCases = 4;
// f: the seed's functions -1 (sensor) .. 18 (saw)
constexpr int kFunctionCases = 20;

// Reads genes in order: the DNA's own, then zeros ("padding with zeros"), or, when growing a
// random DNA, genes drawn as they are needed and appended.
class GeneReader {
 public:
  GeneReader(const Dna& dna, Dna* grown, Rng* rng) : dna_(dna), grown_(grown), rng_(rng) {}
  Gene next() {
    const std::size_t at = position_++;
    if (at < dna_.size())
      return dna_[at];
    if (!grown_)
      return 0;
    grown_->push_back(static_cast<Gene>(rng_->below(kGeneValues)));
    return grown_->back();
  }
  std::size_t position() const { return position_; }

 private:
  const Dna& dna_;
  Dna* grown_;
  Rng* rng_;
  std::size_t position_ = 0;
};

// a gene as a fraction in [0, 1]
double fraction(Gene gene) {
  return gene / kTopGene;
}
// a gene as a number in [-1, 1): (g - 500) / 500, 0 at the middle gene exactly
double signedFraction(Gene gene) {
  constexpr double kMiddle = kGeneValues / 2;
  return (gene - kMiddle) / kMiddle;
}

class CreatureReader {
 public:
  CreatureReader(GeneReader& genes, const GrammarSettings& settings, CreatureGenes& out)
      : genes_(genes), settings_(settings), out_(out) {}

  // S ::= Bi B NN
  void creature() {
    out_.boxes.push_back(box());
    joints(0);
    out_.main = net(settings_.main_net_size);
    out_.genes_read = genes_.position();
  }

 private:
  // Bi ::= h w d Se
  BoxGenes box() {
    BoxGenes b;
    for (int axis = 0; axis < 3; ++axis)
      b.size[axis] =
          settings_.min_side + fraction(genes_.next()) * (settings_.max_side - settings_.min_side);
    b.pressure_sensor = genes_.next() % 2 == 1;
    return b;
  }

  // B ::= count J^count, no joint read once the creature has its most boxes
  void joints(int parent) {
    const int count = genes_.next() % kJointCases;
    for (int j = 0; j < count; ++j) {
      if (static_cast<int>(out_.boxes.size()) >= settings_.max_boxes) {
        out_.truncated = true;
        return;
      }
      joint(parent);
    }
  }

  // J ::= NN E screw PRE POST DOF Bi B
  void joint(int parent) {
    const std::size_t begin = genes_.position();
    const std::size_t index = out_.joints.size();
    out_.joints.emplace_back();
    JointGenes j;
    j.parent = parent;
    j.child = static_cast<int>(out_.boxes.size());
    j.subnet = net(settings_.subnet_size);
    for (Gene& e : j.effector)
      e = genes_.next();
    j.screw_gene = genes_.position();
    j.screw = genes_.next() * (2 * kPi / kGeneValues);
    j.pre = facePoint();
    j.post = facePoint();
    const double max_limit = settings_.max_joint_limit * kPi / 180;
    for (int axis = 0; axis < 3; ++axis)
      j.limit[axis] = fraction(genes_.next()) * max_limit;
    out_.boxes.push_back(box());
    out_.joints[index] = j;
    joints(j.child);
    out_.joints[index].span = {begin, genes_.position()};
  }

  // PRE, POST ::= x y side
  FacePoint facePoint() {
    FacePoint p;
    p.u = signedFraction(genes_.next());
    p.v = signedFraction(genes_.next());
    p.side = genes_.next() % 6;
    return p;
  }

  // NN ::= cv NNL^(1..4); NNL ::= lcv Ni^(1..2 most_probable - 1)
  NetGenes net(int most_probable) {
    NetGenes n;
    n.span.begin = genes_.position();
    n.layers.resize(static_cast<std::size_t>(layerCount(genes_.next())));
    for (auto& layer : n.layers) {
      layer.resize(static_cast<std::size_t>(layerSize(genes_.next(), most_probable)));
      for (NodeGenes& node : layer)
        node = this->node();
    }
    n.span.end = genes_.position();
    return n;
  }

  // Ni ::= ncv value | ncv f in1 w1 | ncv f in1 in2 w1 w2 | ncv f in1 in2 in3 w1 w2 w3
  NodeGenes node() {
    NodeGenes n;
    n.input_count = genes_.next() % kNodeCases;
    if (n.input_count == 0) {
      n.function = LayeredFunction::constant;
      n.value = settings_.max_weight * signedFraction(genes_.next());
      return n;
    }
    n.function = static_cast<LayeredFunction>(static_cast<int>(genes_.next() % kFunctionCases) - 1);
    for (int i = 0; i < n.input_count; ++i)
      n.inputs[static_cast<std::size_t>(i)] = genes_.next();
    for (int i = 0; i < n.input_count; ++i)
      n.weights[static_cast<std::size_t>(i)] = settings_.max_weight * signedFraction(genes_.next());
    return n;
  }

  GeneReader& genes_;
  const GrammarSettings& settings_;
  CreatureGenes& out_;
};

}  // namespace

int layerCount(Gene chooser) {
  const int value = chooser % 100;
  return value < 15 ? 1 : value < 40 ? 2 : value < 85 ? 3 : 4;
}

int layerSize(Gene chooser, int most_probable) {
  double used = 0;
  for (int i = 1; most_probable - i > 0; ++i) {
    const double chance = 300.0 / static_cast<double>(1 << std::min(i, 30));
    used += chance;
    if (chooser < used)
      return most_probable - i;
    used += chance;
    if (chooser < used)
      return most_probable + i;
  }
  return most_probable;
}

CreatureGenes readCreature(const Dna& dna, const GrammarSettings& settings) {
  CreatureGenes out;
  GeneReader genes(dna, nullptr, nullptr);
  CreatureReader(genes, settings, out).creature();
  return out;
}

Dna randomDna(const GrammarSettings& settings, Rng& rng) {
  Dna grown;
  const Dna none;
  GeneReader genes(none, &grown, &rng);
  CreatureGenes out;
  CreatureReader(genes, settings, out).creature();
  return grown;
}

}  // namespace cambrian::wwd

namespace cambrian::wwd {

namespace {

// the nearest gene to fraction `f` in [0, 1] of the gene range
Gene geneOf(double f) {
  const double g = std::round(std::clamp(f, 0.0, 1.0) * kTopGene);
  return static_cast<Gene>(g);
}
// the nearest gene to `x` in [-1, 1) read as a signed fraction
Gene signedGeneOf(double x) {
  constexpr double kMiddle = kGeneValues / 2;
  return static_cast<Gene>(std::clamp(std::round(kMiddle + x * kMiddle), 0.0, kTopGene));
}

class CreatureWriter {
 public:
  CreatureWriter(const CreatureGenes& genes, const GrammarSettings& settings, Dna& out)
      : genes_(genes), settings_(settings), out_(out) {}

  void creature() {
    if (genes_.boxes.empty())
      throw GenomeError("wwd creature: no boxes");
    if (static_cast<int>(genes_.boxes.size()) > settings_.max_boxes)
      throw GenomeError("wwd creature: " + std::to_string(genes_.boxes.size()) +
                        " boxes, more than wwd.max_boxes");
    if (genes_.joints.size() + 1 != genes_.boxes.size())
      throw GenomeError("wwd creature: " + std::to_string(genes_.boxes.size()) + " boxes and " +
                        std::to_string(genes_.joints.size()) +
                        " joints (joint j makes box j + 1: one box more than joints)");
    for (std::size_t j = 0; j < genes_.joints.size(); ++j) {
      const JointGenes& joint = genes_.joints[j];
      if (joint.child != static_cast<int>(j) + 1 || joint.parent < 0 ||
          joint.parent > joint.child - 1)
        throw GenomeError("wwd creature: joint " + std::to_string(j) + " must make box " +
                          std::to_string(j + 1) + " on an earlier box");
    }
    box(0);
    joints(0);
    net(genes_.main, settings_.main_net_size, "the main net");
  }

 private:
  void box(int index) {
    const BoxGenes& b = genes_.boxes[static_cast<std::size_t>(index)];
    const double range = settings_.max_side - settings_.min_side;
    for (int axis = 0; axis < 3; ++axis)
      out_.push_back(geneOf(range > 0 ? (b.size[axis] - settings_.min_side) / range : 0));
    out_.push_back(b.pressure_sensor ? 1 : 0);
  }

  // the joints on box `parent`, in their order, each followed by what is built on its box
  void joints(int parent) {
    std::vector<std::size_t> children;
    for (std::size_t j = 0; j < genes_.joints.size(); ++j) {
      if (genes_.joints[j].parent == parent)
        children.push_back(j);
    }
    if (children.size() >= static_cast<std::size_t>(kJointCases))
      throw GenomeError("wwd creature: box " + std::to_string(parent) + " has " +
                        std::to_string(children.size()) + " joints (at most " +
                        std::to_string(kJointCases - 1) + ")");
    out_.push_back(static_cast<Gene>(children.size()));
    for (std::size_t j : children) {
      // preorder: joint j must be the next one read
      if (j != next_joint_)
        throw GenomeError("wwd creature: joint " + std::to_string(j) +
                          " is out of reading order (boxes are numbered as the grammar reads "
                          "them: depth first)");
      ++next_joint_;
      const JointGenes& joint = genes_.joints[j];
      net(joint.subnet, settings_.subnet_size, "joint " + std::to_string(j) + "'s subnet");
      for (Gene e : joint.effector)
        out_.push_back(e);
      double turns = joint.screw / (2 * kPi);
      turns -= std::floor(turns);
      out_.push_back(
          static_cast<Gene>(static_cast<int>(std::round(turns * kGeneValues)) % kGeneValues));
      facePoint(joint.pre);
      facePoint(joint.post);
      const double max_limit = settings_.max_joint_limit * kPi / 180;
      for (int axis = 0; axis < 3; ++axis)
        out_.push_back(geneOf(max_limit > 0 ? joint.limit[axis] / max_limit : 0));
      box(joint.child);
      joints(joint.child);
    }
  }

  void facePoint(const FacePoint& p) {
    out_.push_back(signedGeneOf(p.u));
    out_.push_back(signedGeneOf(p.v));
    out_.push_back(static_cast<Gene>(((p.side % 6) + 6) % 6));
  }

  void net(const NetGenes& n, int most_probable, const std::string& what) {
    static const Gene kLayerChoosers[] = {0, 15, 40, 85};
    if (n.layers.empty() || n.layers.size() > 4)
      throw GenomeError("wwd creature: " + what + " has " + std::to_string(n.layers.size()) +
                        " layers (1..4)");
    out_.push_back(kLayerChoosers[n.layers.size() - 1]);
    for (std::size_t l = 0; l < n.layers.size(); ++l) {
      const auto& layer = n.layers[l];
      Gene chooser = 0;
      while (chooser < kGeneValues &&
             layerSize(chooser, most_probable) != static_cast<int>(layer.size()))
        ++chooser;
      if (chooser == kGeneValues)
        throw GenomeError("wwd creature: " + what + "'s layer " + std::to_string(l) + " has " +
                          std::to_string(layer.size()) + " nodes, which no chooser gives (1.." +
                          std::to_string(2 * most_probable - 1) + ")");
      out_.push_back(chooser);
      for (const NodeGenes& node : layer)
        this->node(node);
    }
  }

  void node(const NodeGenes& n) {
    const double w = settings_.max_weight;
    const auto weightGene = [w](double x) { return signedGeneOf(w > 0 ? x / w : 0); };
    if (n.function == LayeredFunction::constant) {
      out_.push_back(0);
      out_.push_back(weightGene(n.value));
      return;
    }
    const int count = std::clamp(n.input_count, 1, 3);
    out_.push_back(static_cast<Gene>(count));
    out_.push_back(static_cast<Gene>(static_cast<int>(n.function) + 1));
    for (int i = 0; i < count; ++i)
      out_.push_back(n.inputs[static_cast<std::size_t>(i)]);
    for (int i = 0; i < count; ++i)
      out_.push_back(weightGene(n.weights[static_cast<std::size_t>(i)]));
  }

  const CreatureGenes& genes_;
  const GrammarSettings& settings_;
  Dna& out_;
  std::size_t next_joint_ = 0;
};

}  // namespace

Dna writeCreature(const CreatureGenes& genes, const GrammarSettings& settings) {
  Dna dna;
  CreatureWriter(genes, settings, dna).creature();
  return dna;
}

}  // namespace cambrian::wwd
