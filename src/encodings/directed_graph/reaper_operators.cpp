#include "encodings/directed_graph/reaper_operators.hpp"

#include "encodings/directed_graph/graph.hpp"
#include "encodings/directed_graph/operators.hpp"
#include "encodings/directed_graph/random.hpp"
#include "encodings/directed_graph/repair.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace cambrian::graph {

namespace {

// the joint of a split's second half: rigid, or a joint of the first allowed type held at 0
void holdStill(PartGene& node, const GenomeLimits& limits) {
  node.joint_limit = {0, 0, 0};
  if (limits.joint_types & 1u) {
    node.joint_type = JointType::fixed;
    return;
  }
  for (int t = 0; t < kJointTypeKinds; ++t) {
    if (limits.joint_types >> t & 1u) {
      node.joint_type = static_cast<JointType>(t);
      return;
    }
  }
}

// a position, or a mirror's axes, on the node split along `axis`, seen from its second half:
// development turns a child on face `axis` so that the child's x points along that axis
// (faceRotation: +90 degrees about z for y, -90 degrees about y for z)
Vec3 intoSecondHalf(Vec3 p, int axis) {
  if (axis == 1)
    return {p.y, -p.x, p.z};
  if (axis == 2)
    return {p.z, p.y, -p.x};
  return p;
}
std::uint8_t mirrorsIntoSecondHalf(std::uint8_t bits, int axis) {
  if (axis == 0)
    return bits;
  const auto first = static_cast<std::uint8_t>(bits & 1u);
  const auto other = static_cast<std::uint8_t>(bits >> axis & 1u);
  bits = static_cast<std::uint8_t>(bits & ~(1u | 1u << axis));
  return static_cast<std::uint8_t>(bits | other | first << axis);
}

}  // namespace

Genome specifyGenes(const Genome& parent, const GenomeLimits& limits,
                    const ReaperOperatorSettings& settings, Rng& rng) {
  Genome g = parent;
  for (PartGene& node : g.nodes) {
    if (rng.bernoulli(settings.gene_specification_chance))
      node = randomPartGene(limits, rng);
  }
  fitToLimits(g, limits);
  return g;
}

Genome splitGenes(const Genome& parent, const GenomeLimits& limits,
                  const ReaperOperatorSettings& settings, Rng& rng) {
  Genome g = parent;
  const std::size_t nodes = g.nodes.size();
  for (std::size_t i = 0; i < nodes; ++i) {
    if (!rng.bernoulli(settings.gene_split_chance))
      continue;
    const int axis = static_cast<int>(rng.below(3));
    const bool room = static_cast<int>(g.nodes.size()) < limits.max_nodes &&
                      static_cast<int>(g.connections.size()) < limits.max_connections;
    const double half = 0.5 * g.nodes[i].dimensions[axis];
    if (!room || half < limits.min_part_size)
      continue;

    // the first half keeps the gene; the second, turned onto the face, is a new node
    PartGene& first = g.nodes[i];
    first.dimensions[axis] = half;
    PartGene second = first;
    const Vec3 size = intoSecondHalf(first.dimensions, axis);
    second.dimensions = {half, std::abs(size.y), std::abs(size.z)};
    second.recursive_limit = 1;
    second.neurons.clear();
    second.effectors.clear();
    holdStill(second, limits);
    const auto index = static_cast<std::uint16_t>(g.nodes.size());
    g.nodes.push_back(std::move(second));

    // what hung on the face the second half now covers hangs on the second half's far face
    for (ConnectionGene& c : g.connections) {
      if (c.from == i && dominantAxis(c.position) == axis && c.position[axis] > 0) {
        c.from = index;
        c.position = intoSecondHalf(c.position, axis);
        c.reflection = mirrorsIntoSecondHalf(c.reflection, axis);
      }
    }

    // the halves' joint: face to face, aligned, never driven
    ConnectionGene joint;
    joint.from = static_cast<std::uint16_t>(i);
    joint.to = index;
    joint.position = {0, 0, 0};
    joint.position[axis] = 1;
    joint.controller.enabled = false;
    g.connections.push_back(joint);
  }
  fitToLimits(g, limits);
  return g;
}

Genome purgeGene(const Genome& parent, const GenomeLimits& limits, Rng& rng) {
  Genome g = parent;
  if (g.nodes.size() < 2)
    return g;
  const auto purged = static_cast<std::uint16_t>(1 + rng.below(g.nodes.size() - 1));
  g.nodes[purged] = randomPartGene(limits, rng);
  std::erase_if(g.connections,
                [purged](const ConnectionGene& c) { return c.to == purged && c.from != purged; });
  fitToLimits(g, limits);
  return g;
}

Genome specifyBranches(const Genome& parent, const GenomeLimits& limits,
                       const ReaperOperatorSettings& settings, Rng& rng) {
  Genome g = parent;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (!rng.bernoulli(settings.branch_specification_chance))
      continue;
    std::vector<std::size_t> own;
    for (std::size_t c = 0; c < g.connections.size(); ++c) {
      if (g.connections[c].from == i)
        own.push_back(c);
    }
    if (own.empty())
      continue;
    ConnectionGene& chosen = g.connections[own[rng.below(own.size())]];
    chosen = randomConnectionGene(chosen.from, chosen.to, limits, rng);
  }
  fitToLimits(g, limits);
  return g;
}

Genome growStubs(const Genome& parent, const GenomeLimits& limits,
                 const ReaperOperatorSettings& settings, Rng& rng) {
  Genome g = parent;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (!rng.bernoulli(settings.grow_stub_chance))
      continue;
    const int count = rng.between(0, settings.grow_stub_max);
    for (int k = 0; k < count; ++k) {
      if (static_cast<int>(g.connections.size()) >= limits.max_connections)
        break;
      const auto to = static_cast<std::uint16_t>(rng.below(g.nodes.size()));
      g.connections.push_back(randomConnectionGene(static_cast<std::uint16_t>(i), to, limits, rng));
    }
  }
  fitToLimits(g, limits);
  return g;
}

Genome featureOf(const Genome& donor, std::uint16_t first, int depth) {
  // breadth first from `first`, depth levels of nodes
  const std::size_t n = donor.nodes.size();
  std::vector<int> level(n, -1);
  std::vector<std::uint16_t> order;
  std::deque<std::uint16_t> queue;
  if (first < n && depth > 0) {
    level[first] = 0;
    queue.push_back(first);
  }
  while (!queue.empty()) {
    const std::uint16_t node = queue.front();
    queue.pop_front();
    order.push_back(node);
    for (const ConnectionGene& c : donor.connections) {
      if (c.from == node && c.to < n && level[c.to] < 0 && level[node] + 1 < depth) {
        level[c.to] = level[node] + 1;
        queue.push_back(c.to);
      }
    }
  }

  // the copied nodes in that order, and the connections between them
  std::vector<int> index(n, -1);
  Genome feature;
  for (std::uint16_t node : order) {
    index[node] = static_cast<int>(feature.nodes.size());
    feature.nodes.push_back(donor.nodes[node]);
  }
  for (ConnectionGene c : donor.connections) {
    if (c.from < n && c.to < n && index[c.from] >= 0 && index[c.to] >= 0) {
      c.from = static_cast<std::uint16_t>(index[c.from]);
      c.to = static_cast<std::uint16_t>(index[c.to]);
      feature.connections.push_back(c);
    }
  }
  return feature;
}

Genome graftFeature(const Genome& receiver, const Genome& donor, const GenomeLimits& limits,
                    const ReaperOperatorSettings& settings, Rng& rng) {
  if (donor.nodes.empty())
    return receiver;
  const auto first = static_cast<std::uint16_t>(rng.below(donor.nodes.size()));
  const int depth = rng.between(settings.graft_depth_min, settings.graft_depth_max);
  return graft(receiver, featureOf(donor, first, depth), limits, rng, GraftInto::root);
}

Genome crossSegments(const Genome& mother, const Genome& father, const GenomeLimits& limits,
                     const ReaperOperatorSettings& settings, Rng& rng) {
  // the segments: mother's first..last (inclusive), father's first..end (exclusive)
  const std::size_t mother_first = rng.below(mother.nodes.size());
  const std::size_t mother_last = mother_first + rng.below(mother.nodes.size() - mother_first);
  const std::size_t father_first = rng.below(father.nodes.size());
  const std::size_t father_end = father_first + rng.below(father.nodes.size() - father_first);

  Genome child;
  child.brain = mother.brain;
  child.projectile = mother.projectile;
  const std::size_t mother_count = mother_last - mother_first + 1;
  child.nodes.assign(mother.nodes.begin() + static_cast<std::ptrdiff_t>(mother_first),
                     mother.nodes.begin() + static_cast<std::ptrdiff_t>(mother_last + 1));
  child.nodes.insert(child.nodes.end(),
                     father.nodes.begin() + static_cast<std::ptrdiff_t>(father_first),
                     father.nodes.begin() + static_cast<std::ptrdiff_t>(father_end));
  const std::size_t nodes = child.nodes.size();

  // each segment's connections, their ends inside it kept, the others repaired into the child
  std::vector<std::size_t> repaired;
  auto carry = [&](const Genome& parent, std::size_t first, std::size_t end, std::size_t offset) {
    for (const ConnectionGene& c : parent.connections) {
      if (c.from < first || c.from >= end)
        continue;
      ConnectionGene copy = c;
      copy.from = static_cast<std::uint16_t>(offset + (c.from - first));
      if (c.to >= first && c.to < end) {
        copy.to = static_cast<std::uint16_t>(offset + (c.to - first));
      } else {
        repaired.push_back(child.connections.size());
      }
      child.connections.push_back(copy);
    }
  };
  carry(mother, mother_first, mother_last + 1, 0);
  carry(father, father_first, father_end, mother_count);
  for (std::size_t c : repaired)
    child.connections[c].to = static_cast<std::uint16_t>(rng.below(nodes));

  // re-drawn connections
  for (int n = 0; n < settings.segment_branch_redraws && !child.connections.empty(); ++n) {
    ConnectionGene& chosen = child.connections[rng.below(child.connections.size())];
    chosen = randomConnectionGene(chosen.from, chosen.to, limits, rng);
  }
  fitToLimits(child, limits);
  return child;
}

}  // namespace cambrian::graph
