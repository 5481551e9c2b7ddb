// cambrian: the environment a creature is evaluated in, described apart from the creature — the
// ground, gravity, the fluid around it, free objects (a projectile, a cube to push) and the light
// the photosensors point at. Environment kinds (plane, water) build it; tasks add the objects
// they need and may move the light.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/math.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

/// The ground the creature stands on.
struct Ground {
  enum class Kind : std::uint8_t {
    plane,  ///< a flat plane at z = 0
    none,   ///< nothing to stand on (water)
  };
  Kind kind = Kind::plane;
  double friction = 1.0;
  double restitution = 0.0;
};

/// The medium around the creature: Sims' viscous water, or nothing (air, not modelled).
struct Fluid {
  /// N s / m^3: each face of a part (and of a free object) feels a force against the normal
  /// component of its velocity, viscosity x its area x that speed (Sims 1994); 0: no fluid.
  double viscosity = 0;
};

/// A rigid object of the environment that is not part of the creature.
struct FreeObject {
  std::string name;  ///< what the task calls it ("projectile")
  PartShape shape = PartShape::box;
  Vec3 size{0.1, 0.1, 0.1};  ///< full size, m (see PartShape)
  double mass = 0.1;         ///< kg; 0: fixed in place
  Material material;         ///< friction and restitution (negative: physics.restitution)
  Transform pose;            ///< world pose at the start
};

/// Everything around the creature.
struct Environment {
  Ground ground;
  /// m / s^2 downwards (-z), after buoyancy; unset: physics.gravity
  std::optional<double> gravity;
  Fluid fluid;
  std::vector<FreeObject> objects;
  Vec3 light{10, 0, 0};  ///< the point the photosensors point at, m
};

}  // namespace cambrian
