// cambrian: the consistency rules of a springy organism.
#include "encodings/springy/rules.hpp"

#include "cambrian/error.hpp"

#include "core/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace cambrian::springy {

namespace {

std::string quoted(const std::string& name) {
  return "'" + name + "'";
}

// "muscle 'm1' (nodes 'a' and 'b')"
std::string tubeText(const Organism& organism, const Tube& tube) {
  return std::string(tube.kind == TubeKind::muscle ? "muscle " : "rod ") + quoted(tube.name) +
         " (nodes " + quoted(organism.nodes[tube.a].name) + " and " +
         quoted(organism.nodes[tube.b].name) + ")";
}

[[noreturn]] void breaks(int rule, const char* says, const std::string& what) {
  throw GenomeError("springy organism: rule " + std::to_string(rule) + " (" + says + "): " + what);
}

// a number for a message: six significant digits (0.701, not 0.7010000000000001)
std::string readable(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

std::string metres(double value) {
  return readable(value) + " m";
}

bool positiveFinite(double value) {
  return value > 0 && std::isfinite(value);
}

// what is not an organism at all, before the rules
void checkStructure(const Organism& organism) {
  auto fail = [](const std::string& what) { throw GenomeError("springy organism: " + what); };
  if (organism.nodes.empty())
    fail("it has no nodes");
  if (!positiveFinite(organism.tube_diameter))
    fail("tube_diameter " + formatNumber(organism.tube_diameter) + " must be > 0 and finite");
  std::set<std::string> names;
  for (const Node& node : organism.nodes) {
    if (node.name.empty())
      fail("a node has no name");
    if (!names.insert(node.name).second)
      fail("two nodes are named " + quoted(node.name));
    const Vec3 p = node.position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("node " + quoted(node.name) + ": its position is not finite");
    if (!positiveFinite(node.diameter))
      fail("node " + quoted(node.name) + ": diameter " + formatNumber(node.diameter) +
           " must be > 0 and finite");
    if (!positiveFinite(node.mass))
      fail("node " + quoted(node.name) + ": mass " + formatNumber(node.mass) +
           " must be > 0 and finite");
  }
  names.clear();
  const int count = static_cast<int>(organism.nodes.size());
  for (const Tube& tube : organism.tubes) {
    if (tube.name.empty())
      fail("a tube has no name");
    if (!names.insert(tube.name).second)
      fail("two tubes are named " + quoted(tube.name));
    if (tube.a < 0 || tube.a >= count || tube.b < 0 || tube.b >= count)
      fail("tube " + quoted(tube.name) + " joins a node that does not exist");
    if (tube.a == tube.b)
      fail("tube " + quoted(tube.name) + " joins node " + quoted(organism.nodes[tube.a].name) +
           " to itself");
  }
}

// rule 1: one connected graph
void checkConnected(const Organism& organism) {
  std::vector<int> group(organism.nodes.size());
  for (std::size_t i = 0; i < group.size(); ++i)
    group[i] = static_cast<int>(i);
  auto root = [&](int i) {
    while (group[i] != i)
      i = group[i] = group[group[i]];
    return i;
  };
  for (const Tube& tube : organism.tubes)
    group[root(tube.a)] = root(tube.b);
  for (std::size_t i = 1; i < group.size(); ++i) {
    if (root(static_cast<int>(i)) != root(0)) {
      breaks(1, "the organism is one connected graph",
             "node " + quoted(organism.nodes[i].name) + " is not connected to node " +
                 quoted(organism.nodes[0].name));
    }
  }
}

// rule 2: no parts intersect, except tubes at their shared end node
void checkNoIntersection(const Organism& organism) {
  const char* says = "no parts intersect";
  const std::vector<Node>& nodes = organism.nodes;
  const double tube_radius = 0.5 * organism.tube_diameter;
  for (const Tube& tube : organism.tubes) {
    const double length = initialLength(organism, tube), touching = touchingLength(organism, tube);
    if (!(length > touching)) {
      breaks(2, says,
             tubeText(organism, tube) + ": its initial length " + metres(length) +
                 " is not above r1 + r2 = " + metres(touching));
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < nodes.size(); ++j) {
      const double apart = norm(nodes[j].position - nodes[i].position);
      const double touching = 0.5 * (nodes[i].diameter + nodes[j].diameter);
      if (!(apart > touching)) {
        breaks(2, says,
               "nodes " + quoted(nodes[i].name) + " and " + quoted(nodes[j].name) + " overlap (" +
                   metres(apart) + " apart, radii " + metres(touching) + ")");
      }
    }
  }
  for (const Tube& tube : organism.tubes) {
    const Vec3 p0 = nodes[tube.a].position, p1 = nodes[tube.b].position;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (static_cast<int>(k) == tube.a || static_cast<int>(k) == tube.b)
        continue;
      const double apart = pointSegmentDistance(nodes[k].position, p0, p1);
      if (!(apart > tube_radius + 0.5 * nodes[k].diameter)) {
        breaks(2, says,
               tubeText(organism, tube) + " passes through node " + quoted(nodes[k].name) + " (" +
                   metres(apart) + " from its centre)");
      }
    }
  }
  for (std::size_t i = 0; i < organism.tubes.size(); ++i) {
    const Tube& s = organism.tubes[i];
    for (std::size_t j = i + 1; j < organism.tubes.size(); ++j) {
      const Tube& t = organism.tubes[j];
      if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b)
        continue;  // they meet at a node
      const double apart = segmentDistance(nodes[s.a].position, nodes[s.b].position,
                                           nodes[t.a].position, nodes[t.b].position);
      if (!(apart > 2 * tube_radius)) {
        breaks(2, says,
               tubeText(organism, s) + " and " + tubeText(organism, t) + " intersect (" +
                   metres(apart) + " apart, tube diameter " + metres(organism.tube_diameter) + ")");
      }
    }
  }
}

}  // namespace

double pointSegmentDistance(Vec3 point, Vec3 p0, Vec3 p1) {
  const Vec3 d = p1 - p0;
  const double length2 = dot(d, d);
  const double s = length2 > 0 ? std::clamp(dot(point - p0, d) / length2, 0.0, 1.0) : 0.0;
  return norm(point - (p0 + d * s));
}

double segmentDistance(Vec3 p0, Vec3 p1, Vec3 q0, Vec3 q1) {
  // the closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9)
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  constexpr double kTiny = 1e-18;
  double s = 0, t = 0;
  if (a <= kTiny && e <= kTiny)
    return norm(r);
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denominator = a * e - b * b;
      s = denominator > kTiny ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return norm((p0 + d1 * s) - (q0 + d2 * t));
}

void checkMuscle(const Organism& organism, const Tube& tube, const MuscleLimits& limits) {
  const Muscle& m = tube.muscle;
  const std::string which = tubeText(organism, tube);
  if (!(m.amplitude >= 0) || !(m.frequency >= 0) || !std::isfinite(m.amplitude) ||
      !std::isfinite(m.frequency) || !std::isfinite(m.rest_length)) {
    breaks(3, "A >= 0 and f >= 0",
           which + ": amplitude " + readable(m.amplitude) + ", frequency " + readable(m.frequency) +
               ", rest length " + readable(m.rest_length));
  }
  const double initial = initialLength(organism, tube);
  const double shortest = m.rest_length - m.amplitude, longest = m.rest_length + m.amplitude;
  if (initial < shortest - kLengthTolerance || initial > longest + kLengthTolerance) {
    breaks(4, "L_r - A <= L_i <= L_r + A",
           which + ": its initial length " + metres(initial) + " is outside " + readable(shortest) +
               " .. " + metres(longest));
  }
  const double touching = touchingLength(organism, tube);
  if (!(shortest > touching)) {
    breaks(5, "r1 + r2 < L_r - A",
           which + ": its shortest length " + metres(shortest) +
               " is not above r1 + r2 = " + metres(touching));
  }
  if (longest > limits.max_length + kLengthTolerance) {
    breaks(6, "L_r + A <= the maximal muscle length",
           which + ": its longest length " + metres(longest) + " is above " +
               metres(limits.max_length));
  }
  if (m.frequency > limits.max_frequency) {
    breaks(7, "f <= the maximal frequency",
           which + ": frequency " + readable(m.frequency) + " Hz is above " +
               readable(limits.max_frequency) + " Hz");
  }
}

void checkOrganism(const Organism& organism, const MuscleLimits& limits) {
  checkStructure(organism);
  checkConnected(organism);
  checkNoIntersection(organism);
  for (const Tube& tube : organism.tubes) {
    if (tube.kind == TubeKind::muscle)
      checkMuscle(organism, tube, limits);
  }
}

}  // namespace cambrian::springy
