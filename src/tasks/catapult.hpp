// cambrian: the catapult task's fitness (tasks/catapult.cpp), apart for its tests.
#pragma once

namespace cambrian {

/// What a catapult is selected for (task.catapult_fitness).
enum class CatapultFitness {
  distance,  ///< F_D = D_p: how far the projectile went
  aim,       ///< F_a = alpha_p D_p - alpha_t D_t: far, and near the target
};

/// Chaumont et al.'s aim, F_a = alpha_p D_p - alpha_t D_t, m.
double catapultAim(double distance, double miss, double alpha_distance, double alpha_miss);

/// The fitness of a throw: D_p for `distance`; for `aim`, F_a raised by alpha_t times the
/// target's distance `target_range` from the birth place on the ground (the same order as F_a:
/// a throw that misses by no more than that scores >= 0), never below 0.
double catapultFitness(CatapultFitness kind, double distance, double miss, double target_range,
                       double alpha_distance, double alpha_miss);

}  // namespace cambrian
