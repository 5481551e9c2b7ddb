// cambrian: the versioned little-endian byte form of a genome ("CMBG", version, counts, fields).
#include "cambrian/error.hpp"

#include "core/bytes.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

namespace cambrian::graph {
namespace {

// smallest encoded sizes, used to reject counts the remaining bytes cannot hold
constexpr std::size_t kInputBytes = 1 + 2 + 2 + 8;
constexpr std::size_t kNeuronBytes = 1 + 8 + 4;
constexpr std::size_t kEffectorBytes = kInputBytes;
constexpr std::size_t kNodeBytes = 1 + 24 + 8 + 1 + 24 + 1 + 4 + 4;
constexpr std::size_t kConnectionBytes = 2 + 2 + 24 + 24 + 8 + 1 + 1 + 1 + 32;

using Writer = ByteWriter;
using Reader = ByteReader;

// writers for each gene
void writeInput(Writer& w, const NeuronInput& input) {
  w.u8(static_cast<std::uint8_t>(input.source));
  w.u16(input.slot);
  w.u16(input.index);
  w.f64(input.weight);
}

void writeNeurons(Writer& w, const std::vector<NeuronGene>& neurons) {
  w.u32(static_cast<std::uint32_t>(neurons.size()));
  for (const NeuronGene& neuron : neurons) {
    w.u8(static_cast<std::uint8_t>(neuron.function));
    w.f64(neuron.parameter);
    w.u32(static_cast<std::uint32_t>(neuron.inputs.size()));
    for (const NeuronInput& input : neuron.inputs)
      writeInput(w, input);
  }
}

// readers for each gene, mirroring the writers
NeuronInput readInput(Reader& r) {
  NeuronInput input;
  input.source = static_cast<SignalSource>(r.u8());
  input.slot = r.u16();
  input.index = r.u16();
  input.weight = r.f64();
  return input;
}

std::vector<NeuronGene> readNeurons(Reader& r, const std::string& where) {
  r.context(where + " neurons");
  std::vector<NeuronGene> neurons(r.count(kNeuronBytes));
  for (std::size_t i = 0; i < neurons.size(); ++i) {
    r.context(where + " neuron " + std::to_string(i));
    neurons[i].function = static_cast<NeuronFunction>(r.u8());
    neurons[i].parameter = r.f64();
    neurons[i].inputs.resize(r.count(kInputBytes));
    for (NeuronInput& input : neurons[i].inputs)
      input = readInput(r);
  }
  return neurons;
}

// The oldest version that carries the genome (1 without a projectile, so that every other
// genome keeps its bytes): the writer's choice, and the only version the reader accepts for it
std::uint32_t oldestVersionCarrying(const Genome& genome) {
  const bool chaotic = std::any_of(
      genome.connections.begin(), genome.connections.end(),
      [](const ConnectionGene& c) { return c.controller.kind == JointControllerKind::chaotic; });
  const bool photosensitive = std::any_of(genome.nodes.begin(), genome.nodes.end(),
                                          [](const PartGene& node) { return node.photosensitive; });
  return photosensitive                ? 5
         : hasMorphogeneFields(genome) ? 4
         : chaotic                     ? 3
         : genome.projectile           ? 2
                                       : 1;
}

}  // namespace

std::vector<std::uint8_t> serializeGenome(const Genome& genome) {
  std::vector<std::uint8_t> out;
  out.reserve(4096);  // most genomes: no growing on the way
  Writer w(out);

  // header: tag and version
  w.raw(kGenomeTag.data(), kGenomeTag.size());
  const std::uint32_t version = oldestVersionCarrying(genome);
  w.u32(version);

  // nodes
  w.u32(static_cast<std::uint32_t>(genome.nodes.size()));
  for (const PartGene& node : genome.nodes) {
    w.u8(static_cast<std::uint8_t>(node.shape));
    w.vec3(node.dimensions);
    w.f64(node.density);
    w.u8(static_cast<std::uint8_t>(node.joint_type));
    w.vec3(node.joint_limit);
    w.u8(node.recursive_limit);
    writeNeurons(w, node.neurons);
    w.u32(static_cast<std::uint32_t>(node.effectors.size()));
    for (const EffectorGene& effector : node.effectors)
      writeInput(w, effector.input);
  }

  // connections
  w.u32(static_cast<std::uint32_t>(genome.connections.size()));
  for (const ConnectionGene& c : genome.connections) {
    w.u16(c.from);
    w.u16(c.to);
    w.vec3(c.position);
    w.vec3(c.orientation);
    w.f64(c.scale);
    w.u8(c.reflection);
    w.u8(c.terminal_only ? 1 : 0);
    // bit 0: on; bit 1 (version 3): chaotic, its circuit's start and speed after the sine's
    const bool chua = c.controller.kind == JointControllerKind::chaotic;
    w.u8(static_cast<std::uint8_t>((c.controller.enabled ? 1 : 0) | (chua ? 2 : 0)));
    w.f64(c.controller.amplitude);
    w.f64(c.controller.frequency);
    w.f64(c.controller.phase);
    w.f64(c.controller.offset);
    if (chua) {
      for (double v : c.controller.chua_start)
        w.f64(v);
      w.f64(c.controller.chua_speed);
    }
  }

  // brain, then (from version 2) whether a projectile follows, and it
  writeNeurons(w, genome.brain);
  if (version >= 2)
    w.u8(genome.projectile ? 1 : 0);
  if (genome.projectile) {
    const ProjectileGene& p = *genome.projectile;
    w.vec3(p.dimensions);
    w.f64(p.density);
    w.vec3(p.position);
    writeInput(w, p.trigger);
  }

  // (version 4) the morphogene fields of every node, then every connection's flip and mirror
  if (version >= 4) {
    for (const PartGene& node : genome.nodes) {
      w.f64(node.friction);
      w.f64(node.restitution);
      w.vec3(node.anchor);
      w.f64(node.segment_shrink);
      w.vec3(node.joint_damping);
    }
    for (const ConnectionGene& c : genome.connections)
      w.u8(static_cast<std::uint8_t>((c.flip ? 1 : 0) | (c.mirror ? 2 : 0)));
  }

  // (version 5) whether each node is photosensitive
  if (version >= 5) {
    for (const PartGene& node : genome.nodes)
      w.u8(node.photosensitive ? 1 : 0);
  }
  return out;
}

Genome deserializeGenome(const std::uint8_t* bytes, std::size_t size) {
  Reader r(bytes, size, "genome bytes");

  // header: tag and version
  if (size < kGenomeTag.size() || std::memcmp(bytes, kGenomeTag.data(), kGenomeTag.size()) != 0) {
    throw InputError("genome bytes: not a cambrian genome (bad magic)");
  }
  for (std::size_t i = 0; i < kGenomeTag.size(); ++i)
    r.u8();
  r.context("header version");
  std::uint32_t version = r.u32();
  if (version > kGenomeFormatVersion) {
    throw InputError("genome bytes: format version " + std::to_string(version) +
                     " is newer than this cambrian (" + std::to_string(kGenomeFormatVersion) + ")");
  }
  if (version == 0)
    throw InputError("genome bytes: format version 0 does not exist");

  // nodes
  Genome genome;
  r.context("node count");
  genome.nodes.resize(r.count(kNodeBytes));
  for (std::size_t i = 0; i < genome.nodes.size(); ++i) {
    std::string where = "node " + std::to_string(i);
    PartGene& node = genome.nodes[i];
    r.context(where);
    node.shape = static_cast<PartShape>(r.u8());
    node.dimensions = r.vec3();
    node.density = r.f64();
    node.joint_type = static_cast<JointType>(r.u8());
    node.joint_limit = r.vec3();
    node.recursive_limit = r.u8();
    node.neurons = readNeurons(r, where);
    r.context(where + " effectors");
    node.effectors.resize(r.count(kEffectorBytes));
    for (EffectorGene& effector : node.effectors)
      effector.input = readInput(r);
  }

  // connections
  r.context("connection count");
  genome.connections.resize(r.count(kConnectionBytes));
  for (std::size_t i = 0; i < genome.connections.size(); ++i) {
    ConnectionGene& c = genome.connections[i];
    r.context("connection " + std::to_string(i));
    c.from = r.u16();
    c.to = r.u16();
    c.position = r.vec3();
    c.orientation = r.vec3();
    c.scale = r.f64();
    c.reflection = r.u8();
    c.terminal_only = r.flag("terminal_only");
    // before version 3 only on / off
    const std::uint8_t controller_bits = r.upTo("controller.enabled", version >= 3 ? 3 : 1);
    c.controller.enabled = (controller_bits & 1) != 0;
    c.controller.amplitude = r.f64();
    c.controller.frequency = r.f64();
    c.controller.phase = r.f64();
    c.controller.offset = r.f64();
    if ((controller_bits & 2) != 0) {
      c.controller.kind = JointControllerKind::chaotic;
      for (double& v : c.controller.chua_start)
        v = r.f64();
      c.controller.chua_speed = r.f64();
    }
  }

  // brain, then (from version 2) the projectile, then nothing
  genome.brain = readNeurons(r, "brain");
  if (version >= 2) {
    r.context("projectile");
    if (r.flag("projectile")) {
      ProjectileGene& p = genome.projectile.emplace();
      p.dimensions = r.vec3();
      p.density = r.f64();
      p.position = r.vec3();
      p.trigger = readInput(r);
    }
  }
  if (version >= 4) {
    for (std::size_t i = 0; i < genome.nodes.size(); ++i) {
      r.context("node " + std::to_string(i) + " morphogene");
      PartGene& node = genome.nodes[i];
      node.friction = r.f64();
      node.restitution = r.f64();
      node.anchor = r.vec3();
      node.segment_shrink = r.f64();
      node.joint_damping = r.vec3();
    }
    for (std::size_t i = 0; i < genome.connections.size(); ++i) {
      r.context("connection " + std::to_string(i) + " flip and mirror");
      const std::uint8_t bits = r.upTo("flip and mirror", 3);
      genome.connections[i].flip = (bits & 1) != 0;
      genome.connections[i].mirror = (bits & 2) != 0;
    }
  }
  if (version >= 5) {
    for (std::size_t i = 0; i < genome.nodes.size(); ++i) {
      r.context("node " + std::to_string(i) + " photosensitive");
      genome.nodes[i].photosensitive = r.upTo("photosensitive", 1) != 0;
    }
  }
  r.context("end");
  r.expectEnd();
  // one genome, one byte string: a capsule in version 1 bytes, or version 4 bytes with nothing
  // past version 1 in them, would be written again otherwise
  const std::uint32_t needed = oldestVersionCarrying(genome);
  if (needed != version) {
    throw InputError("genome bytes: format version " + std::to_string(version) +
                     ", but this genome is written as version " + std::to_string(needed) +
                     (needed > version ? " (a field its version cannot carry)"
                                       : " (nothing in it needs a later version)"));
  }
  return genome;
}

}  // namespace cambrian::graph
