// cambrian: Sims' viscous drag (1994) — every face of a part resists the normal component of its
// velocity, in proportion to its area and that speed — integrated exactly over the faces of a
// rigid part, and taken over one step so that it never reverses a motion.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/math.hpp"

namespace cambrian {

/// A part's drag in its own frame: force -linear[i] v[i] and torque -angular[i] w[i] along each
/// axis i, for velocity v of its centre and angular velocity w (N s/m, N m s).
struct DragCoefficients {
  Vec3 linear;
  Vec3 angular;
};

/// The drag of a part of `shape` and full `size` in a fluid of `viscosity` (N s/m^3), summed
/// over its faces for the velocity field of a rigid body (linear over each face, so the sum is
/// exact): for a box of half sides h and face areas A (A_x = 4 h_y h_z, …)
/// linear_x = 2 viscosity A_x and angular_x = 2 viscosity (A_y h_z^2 + A_z h_y^2) / 3; for a
/// sphere of radius r, linear = viscosity 4/3 pi r^2 on every axis and no torque; a cylinder
/// along x (length L, radius r): linear_x = 2 viscosity pi r^2, linear_y = linear_z =
/// viscosity pi r L, angular_x = 0, angular_y = angular_z = viscosity pi r (L^3 / 12 + r^3 / 2);
/// a capsule as the cylinder of its length and radius.
DragCoefficients viscousDrag(PartShape shape, Vec3 size, double viscosity);

/// A force and a torque, in one frame.
struct Wrench {
  Vec3 force;
  Vec3 torque;
};

/// The drag on a part of `mass` and principal `inertia` (its own frame) moving at v and w (its
/// own frame) over a step of `step` s: on each axis the coefficient c is replaced by
/// mass (1 - exp(-c step / mass)) / step (inertia for the torque), the impulse that takes a free
/// body exactly to its decayed speed, so however light the part the step only slows it; for
/// c step << mass the two agree (relative difference about c step / 2 mass).
Wrench dragOverStep(const DragCoefficients& drag, double mass, Vec3 inertia, Vec3 v, Vec3 w,
                    double step);

}  // namespace cambrian
