// Test organisms for the springy encoding's tests.
#pragma once

#include "encodings/springy/organism.hpp"

#include <cmath>
#include <string>

namespace cambrian::springy::test {

/// A node named `name` at (x, y, z) with the thesis' diameter and mass.
inline Node node(const std::string& name, double x, double y, double z) {
  Node n;
  n.name = name;
  n.position = {x, y, z};
  return n;
}

/// A tube named `name` from node a to node b.
inline Tube tube(const std::string& name, int a, int b, TubeKind kind) {
  Tube t;
  t.name = name;
  t.a = a;
  t.b = b;
  t.kind = kind;
  return t;
}

/// A pyramid: a triangle of rods 1 m a side on the ground, its apex 0.8 m up joined to each
/// corner by a muscle resting at its initial length (A = 0, f = 0).
inline Organism pyramid() {
  Organism o;
  const double h = std::sqrt(3.0) / 2;
  o.nodes = {node("a", 0, 0, 0.1), node("b", 1, 0, 0.1), node("c", 0.5, h, 0.1),
             node("top", 0.5, h / 3, 0.9)};
  o.tubes = {tube("ab", 0, 1, TubeKind::rod),     tube("bc", 1, 2, TubeKind::rod),
             tube("ca", 2, 0, TubeKind::rod),     tube("m_a", 3, 0, TubeKind::muscle),
             tube("m_b", 3, 1, TubeKind::muscle), tube("m_c", 3, 2, TubeKind::muscle)};
  for (Tube& t : o.tubes) {
    if (t.kind == TubeKind::muscle)
      t.muscle.rest_length = initialLength(o, t);
  }
  return o;
}

/// The muscle of the thesis' editor screenshot (Fig. A.5): L_r 0.916 m, A 0.215 m, f 1.8 Hz,
/// expanding first, between two nodes 1.04 m apart.
inline Organism screenshotMuscle() {
  Organism o;
  o.nodes = {node("left", 0, 0, 0.1), node("right", 1.04, 0, 0.1)};
  o.tubes = {tube("m", 0, 1, TubeKind::muscle)};
  o.tubes[0].muscle = {0.916, 0.215, 1.8, FirstMove::lengthen};
  return o;
}

}  // namespace cambrian::springy::test
