// cambrian: the swim task's fitness (tasks/swim.cpp), apart for its tests.
#pragma once

namespace cambrian {

/// Sims' swimming fitness: the straight-line speed over the measured phase (`distance` in
/// `seconds`) and over its final phase (`final_distance` in `final_seconds`), averaged with
/// weights 1 and `final_weight`, m/s.
double swimFitness(double distance, double seconds, double final_distance, double final_seconds,
                   double final_weight);

}  // namespace cambrian
