// cambrian: a springy organism's lengths and its muscles' sinusoids.
#include "encodings/springy/organism.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian::springy {

double initialLength(const Organism& organism, const Tube& tube) {
  return norm(organism.nodes[tube.b].position - organism.nodes[tube.a].position);
}

double touchingLength(const Organism& organism, const Tube& tube) {
  return 0.5 * (organism.nodes[tube.a].diameter + organism.nodes[tube.b].diameter);
}

std::vector<int> muscleIndices(const Organism& organism) {
  std::vector<int> muscles;
  for (std::size_t i = 0; i < organism.tubes.size(); ++i) {
    if (organism.tubes[i].kind == TubeKind::muscle)
      muscles.push_back(static_cast<int>(i));
  }
  return muscles;
}

bool sameMorphology(const Organism& a, const Organism& b) {
  if (a.nodes != b.nodes || a.tubes.size() != b.tubes.size() || a.tube_diameter != b.tube_diameter)
    return false;
  for (std::size_t i = 0; i < a.tubes.size(); ++i) {
    const Tube &s = a.tubes[i], &t = b.tubes[i];
    if (s.name != t.name || s.a != t.a || s.b != t.b || s.kind != t.kind)
      return false;
  }
  return true;
}

double musclePhase(const Muscle& muscle, double initial_length) {
  if (!(muscle.amplitude > 0))
    return 0;
  // the rules keep |L_i − L_r| <= A; rounding may not
  const double ratio =
      std::clamp((initial_length - muscle.rest_length) / muscle.amplitude, -1.0, 1.0);
  const double rising = std::asin(ratio);
  return muscle.first_move == FirstMove::lengthen ? rising : kPi - rising;
}

double muscleLength(const Muscle& muscle, double initial_length, double t) {
  if (!(muscle.amplitude > 0))
    return initial_length;
  const double phase = musclePhase(muscle, initial_length);
  return muscle.rest_length + muscle.amplitude * std::sin(2 * kPi * muscle.frequency * t + phase);
}

double muscleSpeed(const Muscle& muscle, double initial_length, double t) {
  if (!(muscle.amplitude > 0))
    return 0;
  const double omega = 2 * kPi * muscle.frequency;
  const double phase = musclePhase(muscle, initial_length);
  return muscle.amplitude * omega * std::cos(omega * t + phase);
}

}  // namespace cambrian::springy
