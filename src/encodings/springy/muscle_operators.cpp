// cambrian: the springy organisms' generator, mutations and crossover.
#include "encodings/springy/muscle_operators.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "core/number_text.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace cambrian::springy {

namespace {

// (L_r, A) uniform over the valid pairs: with x = L_r − A and y = L_r + A the rules read
// C_min < x <= L_i <= y <= C_max, a rectangle in (x, y) (the thesis' rotated rectangle in
// (L_r, A), Fig. 3.3), sampled in constant time
void drawRestAndAmplitude(Muscle& muscle, double initial, double touching, double longest,
                          Rng& rng) {
  double x = initial - rng.uniform() * (initial - touching);
  const double y = initial + rng.uniform() * (longest - initial);
  muscle.rest_length = 0.5 * (x + y);
  muscle.amplitude = 0.5 * (y - x);
  if (!(muscle.rest_length - muscle.amplitude > touching)) {
    // rounding touched C_min: the shortest length is the initial one instead
    x = initial;
    muscle.rest_length = 0.5 * (x + y);
    muscle.amplitude = 0.5 * (y - x);
  }
}

double drawFrequency(const MuscleOperatorSettings& settings, Rng& rng) {
  return settings.evolve_frequency ? rng.uniform() * settings.limits.max_frequency
                                   : settings.frozen_frequency;
}

FirstMove drawFirstMove(Rng& rng) {
  return rng.bernoulli(0.5) ? FirstMove::lengthen : FirstMove::shorten;
}

// tube `index` of `organism` drawn anew
void redrawMuscle(Organism& organism, int index, const MuscleOperatorSettings& settings, Rng& rng) {
  Tube& tube = organism.tubes[static_cast<std::size_t>(index)];
  tube.muscle =
      randomMuscle(initialLength(organism, tube), touchingLength(organism, tube), settings, rng);
}

// the geometric count of parametric mutation: 1 with probability p, 2 with p(1 − p), ...,
// clamped to `most` (bounded: at most `most` draws)
int geometricCount(double p, int most, Rng& rng) {
  int n = 1;
  while (n < most && !rng.bernoulli(p))
    ++n;
  return n;
}

// the parametric mutation: n of the control system's parameters drawn anew, (L_r, A) counting
// as one, then f (unless frozen), then δ
void mutateParameters(Organism& organism, const MuscleOperatorSettings& settings, Rng& rng) {
  const std::vector<int> muscles = muscleIndices(organism);
  const int per_muscle = settings.evolve_frequency ? 3 : 2;
  const int parameters = per_muscle * static_cast<int>(muscles.size());
  if (parameters == 0)
    return;
  const int n = settings.geometric_count ? geometricCount(settings.geometric_p, parameters, rng)
                                         : std::clamp(settings.parametric_count, 1, parameters);
  // n distinct parameters: a partial Fisher–Yates shuffle
  std::vector<int> order(static_cast<std::size_t>(parameters));
  std::iota(order.begin(), order.end(), 0);
  for (int k = 0; k < n; ++k) {
    const int pick = k + static_cast<int>(rng.below(static_cast<std::uint64_t>(parameters - k)));
    std::swap(order[static_cast<std::size_t>(k)], order[static_cast<std::size_t>(pick)]);
    const int parameter = order[static_cast<std::size_t>(k)];
    Tube& tube = organism.tubes[static_cast<std::size_t>(muscles[parameter / per_muscle])];
    int which = parameter % per_muscle;
    if (!settings.evolve_frequency && which == 1)
      which = 2;  // frozen: the second parameter is δ
    if (which == 0) {
      drawRestAndAmplitude(tube.muscle, initialLength(organism, tube),
                           touchingLength(organism, tube), settings.limits.max_length, rng);
      // frozen: a still muscle (a hand-made seed's) that now swings does so at the frozen frequency
      if (!settings.evolve_frequency)
        tube.muscle.frequency = settings.frozen_frequency;
    } else if (which == 1) {
      tube.muscle.frequency = drawFrequency(settings, rng);
    } else if (settings.flip_first_move) {
      tube.muscle.first_move =
          tube.muscle.first_move == FirstMove::lengthen ? FirstMove::shorten : FirstMove::lengthen;
    } else {
      tube.muscle.first_move = drawFirstMove(rng);
    }
  }
}

}  // namespace

Muscle randomMuscle(double initial_length, double touching_length,
                    const MuscleOperatorSettings& settings, Rng& rng) {
  const double longest = settings.limits.max_length;
  if (!(initial_length > touching_length) || !(initial_length <= longest)) {
    throw GenomeError("springy organism: no muscle of initial length " +
                      formatNumber(initial_length) +
                      " m fits between r1 + r2 = " + formatNumber(touching_length) +
                      " m and the maximal muscle length " + formatNumber(longest) + " m");
  }
  Muscle muscle;
  drawRestAndAmplitude(muscle, initial_length, touching_length, longest, rng);
  muscle.frequency = drawFrequency(settings, rng);
  muscle.first_move = drawFirstMove(rng);
  return muscle;
}

Organism randomControl(const Organism& organism, const MuscleOperatorSettings& settings, Rng& rng) {
  Organism drawn = organism;
  for (int index : muscleIndices(drawn))
    redrawMuscle(drawn, index, settings, rng);
  return drawn;
}

Organism mutateMuscles(const Organism& parent, const MuscleOperatorSettings& settings, Rng& rng) {
  Organism child = parent;
  const std::vector<int> muscles = muscleIndices(child);
  switch (settings.mutation) {
    case MuscleMutation::atomic:
      for (int index : muscles) {
        if (rng.bernoulli(settings.atomic_probability))
          redrawMuscle(child, index, settings, rng);
      }
      break;
    case MuscleMutation::quantity: {
      // n distinct muscles (a partial Fisher–Yates shuffle)
      std::vector<int> order = muscles;
      const int n = std::clamp(settings.quantity, 0, static_cast<int>(order.size()));
      for (int k = 0; k < n; ++k) {
        const std::size_t pick =
            static_cast<std::size_t>(k) + rng.below(order.size() - static_cast<std::size_t>(k));
        std::swap(order[static_cast<std::size_t>(k)], order[pick]);
        redrawMuscle(child, order[static_cast<std::size_t>(k)], settings, rng);
      }
      break;
    }
    case MuscleMutation::parametric:
      mutateParameters(child, settings, rng);
      break;
  }
  return child;
}

Organism crossMuscles(const Organism& mother, const Organism& father,
                      const MuscleOperatorSettings& settings, Rng& rng) {
  if (!sameMorphology(mother, father))
    throw GenomeError("springy organism: crossover needs two organisms of one morphology");
  const double share =
      settings.crossover_mother_share < 0 ? rng.uniform() : settings.crossover_mother_share;
  Organism child = mother;
  for (int index : muscleIndices(child)) {
    const std::size_t i = static_cast<std::size_t>(index);
    if (!(rng.uniform() < share))
      child.tubes[i].muscle = father.tubes[i].muscle;
  }
  return child;
}

}  // namespace cambrian::springy
