// cambrian: Sims' viscous drag on a part's faces.
#include "physics/viscous_drag.hpp"

#include <cmath>

namespace cambrian {

namespace {

// the coefficient of a free body of inertia `inertia` that decays exactly over the step
double overStep(double coefficient, double inertia, double step) {
  if (coefficient <= 0)
    return 0;
  if (!(inertia > 0))
    return coefficient;
  return inertia * -std::expm1(-coefficient * step / inertia) / step;
}

}  // namespace

DragCoefficients viscousDrag(PartShape shape, Vec3 size, double viscosity) {
  DragCoefficients drag;
  switch (shape) {
    case PartShape::box: {
      const Vec3 h = size * 0.5;
      const Vec3 area{4 * h.y * h.z, 4 * h.x * h.z, 4 * h.x * h.y};  // of the face normal to each
      drag.linear = area * (2 * viscosity);
      drag.angular =
          Vec3{area.y * h.z * h.z + area.z * h.y * h.y, area.x * h.z * h.z + area.z * h.x * h.x,
               area.x * h.y * h.y + area.y * h.x * h.x} *
          (2 * viscosity / 3);
      break;
    }
    case PartShape::sphere: {
      const double r = 0.5 * size.x;
      const double c = viscosity * 4.0 / 3.0 * kPi * r * r;
      drag.linear = {c, c, c};
      break;
    }
    case PartShape::capsule:
    case PartShape::cylinder: {
      const double r = 0.5 * size.y, length = size.x;
      const double side = viscosity * kPi * r * length;
      const double turn = viscosity * kPi * r * (length * length * length / 12 + r * r * r / 2);
      drag.linear = {viscosity * 2 * kPi * r * r, side, side};
      drag.angular = {0, turn, turn};
      break;
    }
  }
  return drag;
}

Wrench dragOverStep(const DragCoefficients& drag, double mass, Vec3 inertia, Vec3 v, Vec3 w,
                    double step) {
  Wrench wrench;
  for (int i = 0; i < 3; ++i) {
    wrench.force[i] = -overStep(drag.linear[i], mass, step) * v[i];
    wrench.torque[i] = -overStep(drag.angular[i], inertia[i], step) * w[i];
  }
  return wrench;
}

}  // namespace cambrian
