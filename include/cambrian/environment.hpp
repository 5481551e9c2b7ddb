// cambrian: the environment a creature is evaluated in, described apart from the creature — the
// ground, gravity, the fluid around it, free objects (a projectile, a cube to push) and the light
// the photosensors point at. Environment kinds (plane, water, hills) build it; tasks add the
// objects they need and may move the light.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/math.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

/// A terrain of heights on a square grid centred on the origin: sample (column c, row r) lies at
/// x = (c - (samples - 1) / 2) x spacing, y = (r - (samples - 1) / 2) x spacing. Between samples
/// the ground is two triangles per grid square, split along the diagonal from (c + 1, r) to
/// (c, r + 1), as Bullet's btHeightfieldTerrainShape triangulates it.
struct Heightfield {
  int samples = 0;     ///< per side (odd: a sample lies at the origin)
  double spacing = 1;  ///< m between neighbouring samples
  /// z of each sample, m, row after row (index r x samples + c); shared, since every evaluation
  /// of a run stands on the same terrain
  std::shared_ptr<const std::vector<double>> heights;

  /// Full side length, m.
  double size() const { return (samples - 1) * spacing; }
  /// The ground's z at (x, y) on the triangulated surface; outside the grid, the nearest edge's.
  double heightAt(double x, double y) const;
  /// At least the highest z of the surface over the rectangle [x_low, x_high] x [y_low, y_high]
  /// (the highest sample within one spacing of it).
  double highestIn(double x_low, double x_high, double y_low, double y_high) const;
};

/// The ground the creature stands on.
struct Ground {
  enum class Kind : std::uint8_t {
    plane,        ///< a flat plane at z = 0
    none,         ///< nothing to stand on (water)
    heightfield,  ///< the terrain of `heightfield` (hills)
  };
  Kind kind = Kind::plane;
  double friction = 1.0;
  double restitution = 0.0;
  Heightfield heightfield;  ///< with Kind::heightfield

  /// The ground's z at (x, y): 0 for a plane, the terrain's for a heightfield; none: -infinity.
  double heightAt(double x, double y) const;
  /// At least the highest ground z over a rectangle (Heightfield::highestIn); as heightAt for a
  /// plane or none.
  double highestIn(double x_low, double x_high, double y_low, double y_high) const;
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
