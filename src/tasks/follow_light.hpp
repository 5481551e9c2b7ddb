// cambrian: the follow_light task's light positions and fitness (tasks/follow_light.cpp), apart
// for its tests.
#pragma once

#include "cambrian/math.hpp"

namespace cambrian {

/// Where the light goes for the k-th of the task's positions: `distance` m from the centre of
/// mass `centre`, at its height, at bearing `first_degrees` + k x `turn_degrees` from +x
/// (anticlockwise seen from above).
Vec3 lightPosition(int k, Vec3 centre, double distance, double first_degrees, double turn_degrees);

}  // namespace cambrian
