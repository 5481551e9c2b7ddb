// cambrian: the registered environment kinds — one line each — the plane, and the ground's height.
#include "physics/environment.hpp"

#include "physics/hills_environment.hpp"
#include "physics/water_environment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cambrian {

double Heightfield::heightAt(double x, double y) const {
  // the grid square and the place in it, clamped to the grid
  const double half = (samples - 1) / 2.0;
  const double gx = std::clamp(x / spacing + half, 0.0, samples - 1.0);
  const double gy = std::clamp(y / spacing + half, 0.0, samples - 1.0);
  const int c = std::min(static_cast<int>(gx), samples - 2);
  const int r = std::min(static_cast<int>(gy), samples - 2);
  const double u = gx - c, v = gy - r;
  const std::vector<double>& h = *heights;
  auto at = [&](int dc, int dr) { return h[static_cast<std::size_t>(r + dr) * samples + c + dc]; };
  // Bullet's split: triangle (0,0) (0,1) (1,0), then (1,0) (0,1) (1,1)
  if (u + v <= 1)
    return at(0, 0) + u * (at(1, 0) - at(0, 0)) + v * (at(0, 1) - at(0, 0));
  return at(1, 1) + (1 - u) * (at(0, 1) - at(1, 1)) + (1 - v) * (at(1, 0) - at(1, 1));
}

double Heightfield::highestIn(double x_low, double x_high, double y_low, double y_high) const {
  // every sample within one spacing of the rectangle (a point's height interpolates samples of
  // its own grid square), clamped to the grid
  const double half = (samples - 1) / 2.0;
  auto index = [&](double grid) { return static_cast<int>(std::clamp(grid, 0.0, samples - 1.0)); };
  const int c0 = index(std::floor(x_low / spacing + half));
  const int c1 = index(std::ceil(x_high / spacing + half));
  const int r0 = index(std::floor(y_low / spacing + half));
  const int r1 = index(std::ceil(y_high / spacing + half));
  const std::vector<double>& h = *heights;
  double highest = -std::numeric_limits<double>::infinity();
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      highest = std::max(highest, h[static_cast<std::size_t>(r) * samples + c]);
  return highest;
}

double Ground::highestIn(double x_low, double x_high, double y_low, double y_high) const {
  if (kind == Kind::heightfield)
    return heightfield.highestIn(x_low, x_high, y_low, y_high);
  return heightAt(x_low, y_low);
}

double Ground::heightAt(double x, double y) const {
  switch (kind) {
    case Kind::plane:
      return 0;
    case Kind::heightfield:
      return heightfield.heightAt(x, y);
    case Kind::none:
      break;
  }
  return -std::numeric_limits<double>::infinity();
}

std::unique_ptr<EnvironmentKind> PlaneEnvironment::clone() const {
  return std::make_unique<PlaneEnvironment>(*this);
}

Environment PlaneEnvironment::build(const PhysicsSettings& physics) const {
  Environment environment;
  environment.ground.kind = Ground::Kind::plane;
  environment.ground.friction = physics.ground_friction;
  environment.ground.restitution = physics.restitution;
  return environment;
}

const std::vector<const EnvironmentKind*>& environmentKinds() {
  static const PlaneEnvironment plane;
  static const WaterEnvironment water;
  static const HillsEnvironment hills;
  static const std::vector<const EnvironmentKind*> registered = {
      &plane,  // a flat ground
      &water,  // Sims' viscous water without gravity
      &hills,  // fractal hills (Minemonics)
  };
  return registered;
}

std::vector<std::string> environmentNames() {
  std::vector<std::string> names;
  for (const EnvironmentKind* kind : environmentKinds())
    names.push_back(kind->name());
  return names;
}

}  // namespace cambrian
