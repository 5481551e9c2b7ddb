// cambrian: the readable, line-oriented text form of a genome (grammar in docs/genome.md).
#include "cambrian/error.hpp"

#include "core/number_text.hpp"
#include "core/text_line.hpp"
#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace cambrian::graph {
namespace {

constexpr const char* kHeader = "cambrian-genome";
constexpr const char* kEnd = "end";  // the last statement of a version-2 text

// whether a controller's chaotic fields are the default ones bit for bit
bool isDefaultChuaFields(const JointControllerGene& controller) {
  const JointControllerGene none;
  auto same = [](double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  };
  return same(controller.chua_start[0], none.chua_start[0]) &&
         same(controller.chua_start[1], none.chua_start[1]) &&
         same(controller.chua_start[2], none.chua_start[2]) &&
         same(controller.chua_speed, none.chua_speed);
}

// whether a controller is the default one bit for bit (a -0 offset is written: it is not 0)
bool isDefaultController(const JointControllerGene& controller) {
  const JointControllerGene none;
  auto same = [](double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  };
  return controller.enabled == none.enabled && controller.kind == none.kind &&
         same(controller.amplitude, none.amplitude) && same(controller.frequency, none.frequency) &&
         same(controller.phase, none.phase) && same(controller.offset, none.offset) &&
         isDefaultChuaFields(controller);
}

constexpr const char* kShapeNames[] = {"box", "capsule"};
constexpr const char* kSourceNames[] = {"constant",      "local_sensor", "local_neuron",
                                        "parent_neuron", "child_neuron", "brain_neuron",
                                        "brain_sensor"};
static_assert(sizeof(kSourceNames) / sizeof(kSourceNames[0]) == kSignalSourceCount);

//---------------------------------------------------------------- writing

// an enumeration's name, or its number when out of range (so any genome round-trips)
std::string enumText(int value, const char* const* names, int count) {
  if (value >= 0 && value < count)
    return names[value];
  return std::to_string(value);
}

std::string functionText(NeuronFunction function) {
  int value = static_cast<int>(function);
  if (value < kNeuronFunctionCount)
    return neuronFunctionName(function);
  return std::to_string(value);
}

std::string vec3Text(const Vec3& v) {
  return formatNumber(v.x) + " " + formatNumber(v.y) + " " + formatNumber(v.z);
}

std::string inputText(const NeuronInput& input) {
  return enumText(static_cast<int>(input.source), kSourceNames, kSignalSourceCount) + " " +
         std::to_string(input.slot) + " " + std::to_string(input.index) + " " +
         formatNumber(input.weight);
}

std::string reflectionText(std::uint8_t bits) {
  if ((bits & ~kReflectionMask) != 0)
    return std::to_string(bits);
  std::string text;
  if (bits & 1)
    text += 'x';
  if (bits & 2)
    text += 'y';
  if (bits & 4)
    text += 'z';
  return text.empty() ? "none" : text;
}

void writeNeuron(std::ostringstream& out, const NeuronGene& neuron) {
  out << "  neuron " << functionText(neuron.function) << " parameter "
      << formatNumber(neuron.parameter);
  for (const NeuronInput& input : neuron.inputs)
    out << " input " << inputText(input);
  out << "\n";
}

//---------------------------------------------------------------- parsing

using Line = TextLine;

NeuronFunction parseFunction(Line& line) {
  std::vector<const char*> names;
  for (int i = 0; i < kNeuronFunctionCount; ++i) {
    names.push_back(neuronFunctionName(static_cast<NeuronFunction>(i)));
  }
  if (line.more() && line.peek() == "if_positive") {
    line.next("function", "a name");
    return NeuronFunction::if_positive;
  }
  return static_cast<NeuronFunction>(
      line.enumeration("function", names.data(), kNeuronFunctionCount));
}

NeuronInput parseInput(Line& line) {
  NeuronInput input;
  input.source =
      static_cast<SignalSource>(line.enumeration("input source", kSourceNames, kSignalSourceCount));
  input.slot = static_cast<std::uint16_t>(line.integer("input slot", 0, 65535));
  input.index = static_cast<std::uint16_t>(line.integer("input index", 0, 65535));
  input.weight = line.number("input weight");
  return input;
}

// neuron fields: parameter P, input SOURCE SLOT INDEX WEIGHT (repeatable)
void parseNeuronFields(Line& line, NeuronGene& neuron) {
  while (line.more()) {
    std::string_view key = line.next("neuron field", "a field");
    if (key == "parameter") {
      neuron.parameter = line.number("parameter");
    } else if (key == "input") {
      neuron.inputs.push_back(parseInput(line));
    } else {
      line.fail("unknown neuron field '" + std::string(key) + "' (parameter, input)");
    }
  }
}

// node fields: shape, size, density, joint, limit, recursion, friction, restitution, anchor,
// shrink, damping, photosensitive (a flag)
void parseNodeFields(Line& line, PartGene& node) {
  while (line.more()) {
    std::string_view key = line.next("node field", "a field");
    if (key == "shape") {
      node.shape = static_cast<PartShape>(line.enumeration("shape", kShapeNames, kPartShapeCount));
    } else if (key == "size") {
      node.dimensions = line.vec3("size");
    } else if (key == "density") {
      node.density = line.number("density");
    } else if (key == "joint") {
      node.joint_type =
          static_cast<JointType>(line.enumeration("joint", kJointNames, kJointTypeCount));
    } else if (key == "limit") {
      node.joint_limit = line.vec3("limit");
    } else if (key == "recursion") {
      node.recursive_limit = static_cast<std::uint8_t>(line.integer("recursion", 0, 255));
    } else if (key == "friction") {
      node.friction = line.number("friction");
    } else if (key == "restitution") {
      node.restitution = line.number("restitution");
    } else if (key == "anchor") {
      node.anchor = line.vec3("anchor");
    } else if (key == "shrink") {
      node.segment_shrink = line.number("shrink");
    } else if (key == "damping") {
      node.joint_damping = line.vec3("damping");
    } else if (key == "photosensitive") {
      node.photosensitive = true;
    } else {
      line.fail("unknown node field '" + std::string(key) +
                "' (shape, size, density, joint, limit, recursion, friction, restitution, "
                "anchor, shrink, damping, photosensitive)");
    }
  }
}

std::uint8_t parseReflection(Line& line) {
  std::string_view token = line.next("reflect", "x, y, z, a combination or none");
  if (token == "none")
    return 0;
  std::uint8_t bits = 0;
  bool letters = !token.empty();
  for (char c : token) {
    std::uint8_t bit = c == 'x' ? 1 : c == 'y' ? 2 : c == 'z' ? 4 : 0;
    if (bit == 0 || (bits & bit) != 0)
      letters = false;
    bits = static_cast<std::uint8_t>(bits | bit);
  }
  if (letters)
    return bits;
  int value = 0;
  auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec == std::errc() && result.ptr == token.data() + token.size() && value >= 0 &&
      value <= 255) {
    return static_cast<std::uint8_t>(value);
  }
  line.fail("expected x, y, z, a combination such as xy, or none for 'reflect', got '" +
            std::string(token) + "'");
}

// connection fields: position, orientation, scale, reflect, terminal_only, flip, mirror
void parseConnectionFields(Line& line, ConnectionGene& c) {
  while (line.more()) {
    std::string_view key = line.next("connection field", "a field");
    if (key == "position") {
      c.position = line.vec3("position");
    } else if (key == "orientation") {
      c.orientation = line.vec3("orientation");
    } else if (key == "scale") {
      c.scale = line.number("scale");
    } else if (key == "reflect") {
      c.reflection = parseReflection(line);
    } else if (key == "terminal_only") {
      c.terminal_only = true;
    } else if (key == "flip") {
      c.flip = true;
    } else if (key == "mirror") {
      c.mirror = true;
    } else {
      line.fail("unknown connection field '" + std::string(key) +
                "' (position, orientation, scale, reflect, terminal_only, flip, mirror)");
    }
  }
}

// controller fields: off, sine, chaotic, amplitude, frequency, phase, offset, start, speed
void parseControllerFields(Line& line, JointControllerGene& controller) {
  controller.enabled = true;
  while (line.more()) {
    std::string_view key = line.next("controller field", "a field");
    if (key == "off") {
      controller.enabled = false;
    } else if (key == "sine") {
      controller.kind = JointControllerKind::sine;
    } else if (key == "chaotic") {
      controller.kind = JointControllerKind::chaotic;
    } else if (key == "start") {
      for (double& v : controller.chua_start)
        v = line.number("start");
    } else if (key == "speed") {
      controller.chua_speed = line.number("speed");
    } else if (key == "amplitude") {
      controller.amplitude = line.number("amplitude");
    } else if (key == "frequency") {
      controller.frequency = line.number("frequency");
    } else if (key == "phase") {
      controller.phase = line.number("phase");
    } else if (key == "offset") {
      controller.offset = line.number("offset");
    } else {
      line.fail("unknown controller field '" + std::string(key) +
                "' (off, sine, chaotic, amplitude, frequency, phase, offset, start, speed)");
    }
  }
}

// projectile fields: size, density, position, trigger
void parseProjectileFields(Line& line, ProjectileGene& projectile) {
  while (line.more()) {
    std::string_view key = line.next("projectile field", "a field");
    if (key == "size") {
      projectile.dimensions = line.vec3("size");
    } else if (key == "density") {
      projectile.density = line.number("density");
    } else if (key == "position") {
      projectile.position = line.vec3("position");
    } else if (key == "trigger") {
      projectile.trigger = parseInput(line);
    } else {
      line.fail("unknown projectile field '" + std::string(key) +
                "' (size, density, position, trigger)");
    }
  }
}

}  // namespace

std::string genomeToText(const Genome& genome) {
  std::ostringstream out;
  out << kHeader << " " << kGenomeTextVersion << "\n";

  // nodes with their neurons and effectors
  for (std::size_t i = 0; i < genome.nodes.size(); ++i) {
    const PartGene& node = genome.nodes[i];
    out << "node " << i;
    if (node.shape != PartShape::box) {
      out << " shape " << enumText(static_cast<int>(node.shape), kShapeNames, kPartShapeCount);
    }
    out << " size " << vec3Text(node.dimensions) << " density " << formatNumber(node.density)
        << " joint " << enumText(static_cast<int>(node.joint_type), kJointNames, kJointTypeCount)
        << " limit " << vec3Text(node.joint_limit) << " recursion "
        << static_cast<int>(node.recursive_limit);
    // the morphogene fields that differ from Sims' boxes
    const PartGene sims_part;
    if (!sameBits(node.friction, sims_part.friction))
      out << " friction " << formatNumber(node.friction);
    if (!sameBits(node.restitution, sims_part.restitution))
      out << " restitution " << formatNumber(node.restitution);
    if (!sameBits(node.anchor, sims_part.anchor))
      out << " anchor " << vec3Text(node.anchor);
    if (!sameBits(node.segment_shrink, sims_part.segment_shrink))
      out << " shrink " << formatNumber(node.segment_shrink);
    if (!sameBits(node.joint_damping, sims_part.joint_damping))
      out << " damping " << vec3Text(node.joint_damping);
    if (node.photosensitive)
      out << " photosensitive";
    out << "\n";
    for (const NeuronGene& neuron : node.neurons)
      writeNeuron(out, neuron);
    for (const EffectorGene& effector : node.effectors) {
      out << "  effector input " << inputText(effector.input) << "\n";
    }
  }

  // connections with their controllers
  for (const ConnectionGene& c : genome.connections) {
    out << "connection " << c.from << " -> " << c.to << " position " << vec3Text(c.position)
        << " orientation " << vec3Text(c.orientation) << " scale " << formatNumber(c.scale);
    if (c.reflection != 0)
      out << " reflect " << reflectionText(c.reflection);
    if (c.terminal_only)
      out << " terminal_only";
    if (c.flip)
      out << " flip";
    if (c.mirror)
      out << " mirror";
    out << "\n";
    if (!isDefaultController(c.controller)) {
      const JointControllerGene& j = c.controller;
      out << "  controller" << (j.enabled ? "" : " off")
          << (j.kind == JointControllerKind::chaotic ? " chaotic" : "") << " amplitude "
          << formatNumber(j.amplitude) << " frequency " << formatNumber(j.frequency) << " phase "
          << formatNumber(j.phase) << " offset " << formatNumber(j.offset);
      // a chaotic controller's circuit (a sine one's too, should they not be the defaults)
      if (j.kind == JointControllerKind::chaotic || !isDefaultChuaFields(j)) {
        out << " start " << formatNumber(j.chua_start[0]) << " " << formatNumber(j.chua_start[1])
            << " " << formatNumber(j.chua_start[2]) << " speed " << formatNumber(j.chua_speed);
      }
      out << "\n";
    }
  }

  // global brain
  if (!genome.brain.empty()) {
    out << "brain\n";
    for (const NeuronGene& neuron : genome.brain)
      writeNeuron(out, neuron);
  }

  // a catapult's projectile
  if (genome.projectile) {
    const ProjectileGene& p = *genome.projectile;
    out << "projectile size " << vec3Text(p.dimensions) << " density " << formatNumber(p.density)
        << " position " << vec3Text(p.position) << " trigger " << inputText(p.trigger) << "\n";
  }

  // the end marker: a file cut short lacks it
  out << kEnd << "\n";
  return out.str();
}

Genome parseGenomeText(const std::string& text, const std::string& source) {
  Genome genome;
  enum class Section { none, node, connection, brain };
  Section section = Section::none;
  bool have_header = false;
  int version = 0;
  int end_line = 0;                   // line of the `end` statement (version 2), 0 before it
  int last_statement = 0;             // line of the last statement, for the missing-`end` message
  NeuronGene* last_neuron = nullptr;  // target of `input` / `parameter` continuation lines
  std::string where;                  // the current item, for messages

  std::size_t start = 0;
  int line_number = 0;
  while (start <= text.size()) {
    // next line
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos)
      end = text.size();
    std::string_view raw(text.data() + start, end - start);
    start = end + 1;
    ++line_number;
    Line line(source, line_number, tokenizeLine(raw));
    if (!line.more())
      continue;
    std::string keyword(line.next("statement", "a keyword"));
    last_statement = line_number;

    // header first
    if (!have_header) {
      if (keyword != kHeader) {
        line.fail("expected the header 'cambrian-genome " + std::to_string(kGenomeTextVersion) +
                  "', got '" + keyword + "'");
      }
      long long number = line.integer("cambrian-genome", 0, 1LL << 32);
      if (number > kGenomeTextVersion) {
        line.fail("format version " + std::to_string(number) + " is newer than this cambrian (" +
                  std::to_string(kGenomeTextVersion) + ")");
      }
      if (number < 1)
        line.fail("format version " + std::to_string(number) + " does not exist");
      if (line.more())
        line.fail("unexpected '" + std::string(line.peek()) + "' after the header");
      have_header = true;
      version = static_cast<int>(number);
      continue;
    }

    // nothing but comments and blank lines after `end`
    if (end_line > 0) {
      line.fail("unexpected '" + keyword + "' after `end` (line " + std::to_string(end_line) +
                "): `end` must be the last statement");
    }
    if (keyword == kEnd) {
      if (version < 2) {
        line.fail("`end` is a statement of format version 2; this file's header says version " +
                  std::to_string(version));
      }
      if (line.more())
        line.fail("unexpected '" + std::string(line.peek()) + "' after `end`");
      end_line = line_number;
      continue;
    }

    if (keyword == "node") {
      // a new node, numbered in order
      line.context("node");
      long long index = line.integer("node", 0, 65535);
      if (static_cast<std::size_t>(index) != genome.nodes.size()) {
        line.fail("expected node " + std::to_string(genome.nodes.size()) + " next, got node " +
                  std::to_string(index));
      }
      where = "node " + std::to_string(index);
      line.context(where);
      genome.nodes.emplace_back();
      parseNodeFields(line, genome.nodes.back());
      section = Section::node;
      last_neuron = nullptr;
    } else if (keyword == "connection") {
      // a new connection: from -> to, then fields
      where = "connection " + std::to_string(genome.connections.size());
      line.context(where);
      ConnectionGene c;
      c.from = static_cast<std::uint16_t>(line.integer("from", 0, 65535));
      line.expect("->", "connection");
      c.to = static_cast<std::uint16_t>(line.integer("to", 0, 65535));
      genome.connections.push_back(c);
      parseConnectionFields(line, genome.connections.back());
      section = Section::connection;
      last_neuron = nullptr;
    } else if (keyword == "brain") {
      // the global neurons follow
      where = "brain";
      line.context(where);
      if (line.more())
        line.fail("unexpected '" + std::string(line.peek()) + "' after 'brain'");
      section = Section::brain;
      last_neuron = nullptr;
    } else if (keyword == "neuron") {
      // a neuron of the current node or of the brain
      std::vector<NeuronGene>* list = nullptr;
      if (section == Section::node)
        list = &genome.nodes.back().neurons;
      if (section == Section::brain)
        list = &genome.brain;
      line.context(where.empty() ? std::string("neuron") : where);
      if (list == nullptr)
        line.fail("a neuron line must follow a node or the brain line");
      line.context(where + ": neuron " + std::to_string(list->size()));
      list->emplace_back();
      list->back().function = parseFunction(line);
      parseNeuronFields(line, list->back());
      last_neuron = &list->back();
    } else if (keyword == "input" || keyword == "parameter") {
      // more fields of the last neuron
      line.context(where.empty() ? keyword : where);
      if (last_neuron == nullptr)
        line.fail("'" + keyword + "' must follow a neuron line");
      Line rest(source, line_number, tokenizeLine(raw));
      rest.context(where + ": neuron");
      parseNeuronFields(rest, *last_neuron);
    } else if (keyword == "effector") {
      // an effector of the current node: [input] SOURCE SLOT INDEX WEIGHT
      line.context(where.empty() ? std::string("effector") : where);
      if (section != Section::node)
        line.fail("an effector line must follow a node line");
      line.context(where + ": effector " + std::to_string(genome.nodes.back().effectors.size()));
      EffectorGene effector;
      if (line.more() && line.peek() == "input")
        line.next("effector", "'input'");
      if (line.more())
        effector.input = parseInput(line);
      if (line.more())
        line.fail("unexpected '" + std::string(line.peek()) + "' after the input");
      genome.nodes.back().effectors.push_back(effector);
      last_neuron = nullptr;
    } else if (keyword == "controller") {
      // the joint controller of the current connection
      line.context(where.empty() ? std::string("controller") : where);
      if (section != Section::connection)
        line.fail("a controller line must follow a connection");
      line.context(where + ": controller");
      parseControllerFields(line, genome.connections.back().controller);
      last_neuron = nullptr;
    } else if (keyword == "projectile") {
      // a catapult's projectile, once
      where = "projectile";
      line.context(where);
      if (genome.projectile)
        line.fail("a genome has one projectile");
      parseProjectileFields(line, genome.projectile.emplace());
      section = Section::none;
      last_neuron = nullptr;
    } else if (keyword == "cambrian-genome") {
      line.fail("the header may appear only once");
    } else {
      // more fields of the current node or connection
      line.context(where.empty() ? std::string("genome") : where);
      Line rest(source, line_number, tokenizeLine(raw));
      rest.context(where);
      if (section == Section::node) {
        parseNodeFields(rest, genome.nodes.back());
      } else if (section == Section::connection) {
        parseConnectionFields(rest, genome.connections.back());
      } else {
        line.fail("unknown statement '" + keyword +
                  "' (node, connection, brain, neuron, effector, controller, projectile, end)");
      }
      last_neuron = nullptr;
    }
  }
  if (!have_header) {
    throw InputError(source + ": empty genome text (expected the header 'cambrian-genome " +
                     std::to_string(kGenomeTextVersion) + "')");
  }

  // version 2 ends with `end`: without it the text was cut short (version 1 cannot tell)
  if (version >= 2 && end_line == 0) {
    throw InputError(source + ":" + std::to_string(last_statement) +
                     ": missing `end`: the file may be truncated after this line");
  }
  return genome;
}

}  // namespace cambrian::graph
