// cambrian: the springy organisms' operators (Krčah 2008, §3.4.3–3.4.5): the generator of
// random control systems, the three muscle mutations and the uniform muscle crossover. Each
// touches the muscles only and keeps every muscle inside rules 3 to 7.
#pragma once

#include "encodings/springy/organism.hpp"

#include <cstdint>

namespace cambrian {
class Rng;
}

namespace cambrian::springy {

/// Which mutation the runs use (the thesis' Algorithms 3.4, 3.5 and 3.6).
enum class MuscleMutation : std::uint8_t {
  atomic,      ///< each muscle, with probability atomic_probability, drawn anew
  quantity,    ///< `quantity` muscles drawn anew
  parametric,  ///< n parameters drawn anew: (L_r, A) as one, f, δ
};

/// The operators' settings, with the thesis' values as defaults.
struct MuscleOperatorSettings {
  MuscleLimits limits;
  /// Off: every muscle's frequency is frozen_frequency, drawn and mutated never ("Evolve
  /// frequency = no"; Exp. 6 froze it at 1 Hz)
  bool evolve_frequency = true;
  double frozen_frequency = 1;  ///< Hz
  MuscleMutation mutation = MuscleMutation::parametric;
  double atomic_probability = 0.33;  ///< p_m (Exp. 1)
  int quantity = 1;                  ///< n muscles (Exp. 2)
  /// parametric: n from a geometric distribution with parameter geometric_p (Exp. 4–6), else
  /// the constant parametric_count (Exp. 3); clamped to 1 .. the number of parameters
  bool geometric_count = true;
  double geometric_p = 0.5;
  int parametric_count = 1;
  /// a mutated δ flips instead of being drawn again (added in Exp. 4)
  bool flip_first_move = true;
  /// uniform crossover: the chance a muscle comes from the mother; negative: drawn in [0, 1)
  /// for each crossover
  double crossover_mother_share = 0.5;
};

/// A muscle drawn uniformly over every valid setting for a tube of initial length
/// `initial_length` whose end nodes touch at `touching_length`: (L_r, A) uniform over the
/// rectangle of valid pairs (no rejection), f uniform in [0, f_max) or frozen, δ by a fair coin.
/// Throws GenomeError when no setting is valid (initial_length above the maximal length).
Muscle randomMuscle(double initial_length, double touching_length,
                    const MuscleOperatorSettings& settings, Rng& rng);
/// `organism` with every muscle drawn anew (Algorithm 3.3, the generator).
Organism randomControl(const Organism& organism, const MuscleOperatorSettings& settings, Rng& rng);
/// `parent` mutated by settings.mutation.
Organism mutateMuscles(const Organism& parent, const MuscleOperatorSettings& settings, Rng& rng);
/// The uniform muscle crossover (Algorithm 3.7): the mother's organism with each muscle's
/// parameters from the mother or the father. Throws GenomeError unless both have the same
/// morphology.
Organism crossMuscles(const Organism& mother, const Organism& father,
                      const MuscleOperatorSettings& settings, Rng& rng);

}  // namespace cambrian::springy
