// cambrian: a springy organism's text and byte forms.
#include "encodings/springy/organism_forms.hpp"

#include "cambrian/error.hpp"

#include "core/bytes.hpp"
#include "core/number_text.hpp"
#include "core/text_line.hpp"

#include <cstring>
#include <map>
#include <set>
#include <sstream>

namespace cambrian::springy {

namespace {

constexpr const char* kFirstMoveNames[] = {"shorten", "lengthen"};

std::string vec3Text(Vec3 v) {
  return formatNumber(v.x) + " " + formatNumber(v.y) + " " + formatNumber(v.z);
}

// a node named on `line` (by a name given before)
int nodeNamed(TextLine& line, const std::map<std::string, int, std::less<>>& nodes,
              const char* field) {
  const std::string_view name = line.next(field, "a node name");
  const auto found = nodes.find(name);
  if (found == nodes.end())
    line.fail("no node named '" + std::string(name) + "' before this line");
  return found->second;
}

void parseMuscleFields(TextLine& line, Muscle& muscle) {
  while (line.more()) {
    const std::string key(line.next("muscle field", "a field"));
    if (key == "rest")
      muscle.rest_length = line.number("rest");
    else if (key == "amplitude")
      muscle.amplitude = line.number("amplitude");
    else if (key == "frequency")
      muscle.frequency = line.number("frequency");
    else if (key == "first")
      muscle.first_move = static_cast<FirstMove>(line.enumeration("first", kFirstMoveNames, 2));
    else
      line.fail("unknown muscle field '" + key + "' (one of: rest, amplitude, frequency, first)");
  }
  if (static_cast<int>(muscle.first_move) > 1)
    line.fail("first must be shorten or lengthen");
}

using Names = std::map<std::string, int, std::less<>>;

// a `node` statement: its name (new), position and optional fields
Node readNode(TextLine& line, const Organism& organism, Names& nodes) {
  Node node;
  node.name = std::string(line.next("node", "a name"));
  if (!isWritableName(node.name))
    line.fail("a node's name is one word of printable characters");
  line.context("node '" + node.name + "'");
  if (!nodes.emplace(node.name, static_cast<int>(organism.nodes.size())).second)
    line.fail("a node of this name comes before");
  node.position = line.vec3("position");
  while (line.more()) {
    const std::string key(line.next("node field", "a field"));
    if (key == "diameter")
      node.diameter = line.number("diameter");
    else if (key == "mass")
      node.mass = line.number("mass");
    else
      line.fail("unknown node field '" + key + "' (one of: diameter, mass)");
  }
  return node;
}

// a `rod` or `muscle` statement: its name (new), its two nodes (named before) and a muscle's
// fields
Tube readTube(const std::string& keyword, TextLine& line, const Organism& organism,
              const Names& nodes, Names& tubes) {
  Tube tube;
  tube.kind = keyword == "rod" ? TubeKind::rod : TubeKind::muscle;
  tube.name = std::string(line.next(keyword, "a name"));
  if (!isWritableName(tube.name))
    line.fail("a " + keyword + "'s name is one word of printable characters");
  line.context(keyword + " '" + tube.name + "'");
  if (!tubes.emplace(tube.name, static_cast<int>(organism.tubes.size())).second)
    line.fail("a rod or muscle of this name comes before");
  tube.a = nodeNamed(line, nodes, "first node");
  tube.b = nodeNamed(line, nodes, "second node");
  if (tube.kind == TubeKind::muscle) {
    // unwritten: resting at its initial length, still
    tube.muscle.rest_length = initialLength(organism, tube);
    parseMuscleFields(line, tube.muscle);
  }
  return tube;
}

}  // namespace

bool isWritableName(const std::string& name) {
  if (name.empty())
    return false;
  for (char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '#' || c == ' ' || byte < 0x20 || byte == 0x7f)
      return false;  // '#' starts a comment; spaces and control characters end a word
  }
  return true;
}

std::string organismToText(const Organism& organism) {
  std::ostringstream out;
  out << kOrganismTextHeader << " " << kOrganismTextVersion << "\n";
  out << "tube_diameter " << formatNumber(organism.tube_diameter) << "\n";
  for (const Node& node : organism.nodes) {
    out << "node " << node.name << " " << vec3Text(node.position) << " diameter "
        << formatNumber(node.diameter) << " mass " << formatNumber(node.mass) << "\n";
  }
  for (const Tube& tube : organism.tubes) {
    const std::string& a = organism.nodes[tube.a].name;
    const std::string& b = organism.nodes[tube.b].name;
    if (tube.kind == TubeKind::rod) {
      out << "rod " << tube.name << " " << a << " " << b << "\n";
      continue;
    }
    const Muscle& m = tube.muscle;
    out << "muscle " << tube.name << " " << a << " " << b << " rest " << formatNumber(m.rest_length)
        << " amplitude " << formatNumber(m.amplitude) << " frequency " << formatNumber(m.frequency)
        << " first " << kFirstMoveNames[static_cast<int>(m.first_move) & 1] << "\n";
  }
  out << "end\n";
  return out.str();
}

Organism parseOrganismText(const std::string& text, const std::string& source) {
  Organism organism;
  Names nodes, tubes;
  readStatements(text, source, kOrganismTextHeader, kOrganismTextVersion,
                 "tube_diameter, node, rod, muscle, end",
                 [&](const std::string& keyword, TextLine& line) {
                   if (keyword == "tube_diameter")
                     organism.tube_diameter = line.number("tube_diameter");
                   else if (keyword == "node")
                     organism.nodes.push_back(readNode(line, organism, nodes));
                   else if (keyword == "rod" || keyword == "muscle")
                     organism.tubes.push_back(readTube(keyword, line, organism, nodes, tubes));
                   else
                     return false;
                   return true;
                 });
  return organism;
}

std::vector<std::uint8_t> organismToBytes(const Organism& organism) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.raw(kOrganismTag.data(), kOrganismTag.size());
  w.u32(kOrganismBytesVersion);
  w.f64(organism.tube_diameter);
  w.u32(static_cast<std::uint32_t>(organism.nodes.size()));
  for (const Node& node : organism.nodes) {
    w.text(node.name);
    w.vec3(node.position);
    w.f64(node.diameter);
    w.f64(node.mass);
  }
  w.u32(static_cast<std::uint32_t>(organism.tubes.size()));
  for (const Tube& tube : organism.tubes) {
    w.text(tube.name);
    w.u32(static_cast<std::uint32_t>(tube.a));
    w.u32(static_cast<std::uint32_t>(tube.b));
    w.u8(static_cast<std::uint8_t>(tube.kind));
    if (tube.kind == TubeKind::muscle) {
      w.f64(tube.muscle.rest_length);
      w.f64(tube.muscle.amplitude);
      w.f64(tube.muscle.frequency);
      w.u8(static_cast<std::uint8_t>(tube.muscle.first_move));
    }
  }
  return out;
}

Organism organismFromBytes(const std::uint8_t* bytes, std::size_t size) {
  ByteReader r(bytes, size, "springy organism bytes");
  if (size < kOrganismTag.size() ||
      std::memcmp(bytes, kOrganismTag.data(), kOrganismTag.size()) != 0)
    throw InputError("springy organism bytes: not a springy organism (bad magic)");
  for (std::size_t i = 0; i < kOrganismTag.size(); ++i)
    r.u8();
  r.context("header version");
  const std::uint32_t version = r.u32();
  if (version == 0 || version > kOrganismBytesVersion)
    r.fail("format version " + std::to_string(version) + " is not one this cambrian reads (1)");
  Organism organism;
  r.context("tube_diameter");
  organism.tube_diameter = r.f64();
  // a node: a name (8 bytes of length at least), 5 numbers
  r.context("node count");
  organism.nodes.resize(r.count(8 + 5 * 8));
  for (std::size_t i = 0; i < organism.nodes.size(); ++i) {
    Node& node = organism.nodes[i];
    r.context("node " + std::to_string(i));
    node.name = r.text();
    if (!isWritableName(node.name))
      r.fail("node " + std::to_string(i) + ": its name cannot be written in the text form");
    node.position = r.vec3();
    node.diameter = r.f64();
    node.mass = r.f64();
  }
  r.context("tube count");
  organism.tubes.resize(r.count(8 + 4 + 4 + 1));
  for (std::size_t i = 0; i < organism.tubes.size(); ++i) {
    Tube& tube = organism.tubes[i];
    r.context("tube " + std::to_string(i));
    tube.name = r.text();
    if (!isWritableName(tube.name))
      r.fail("tube " + std::to_string(i) + ": its name cannot be written in the text form");
    const std::uint32_t a = r.u32(), b = r.u32();
    if (a >= organism.nodes.size() || b >= organism.nodes.size())
      r.fail("tube " + std::to_string(i) + " joins node " +
             std::to_string(a >= organism.nodes.size() ? a : b) + " of " +
             std::to_string(organism.nodes.size()));
    tube.a = static_cast<int>(a);
    tube.b = static_cast<int>(b);
    tube.kind = static_cast<TubeKind>(r.upTo("kind", 1));
    if (tube.kind == TubeKind::muscle) {
      tube.muscle.rest_length = r.f64();
      tube.muscle.amplitude = r.f64();
      tube.muscle.frequency = r.f64();
      tube.muscle.first_move = static_cast<FirstMove>(r.upTo("first move", 1));
    }
  }
  r.context("end");
  r.expectEnd();
  // names are how the text form refers to nodes: one each
  std::set<std::string> names;
  for (const Node& node : organism.nodes) {
    if (!names.insert(node.name).second)
      r.fail("two nodes are named '" + node.name + "'");
  }
  names.clear();
  for (const Tube& tube : organism.tubes) {
    if (!names.insert(tube.name).second)
      r.fail("two tubes are named '" + tube.name + "'");
  }
  return organism;
}

}  // namespace cambrian::springy
