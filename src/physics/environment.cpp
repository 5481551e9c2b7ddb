// cambrian: the registered environment kinds — one line each — and the plane.
#include "physics/environment.hpp"

#include "physics/water_environment.hpp"

namespace cambrian {

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
  static const std::vector<const EnvironmentKind*> registered = {
      &plane,  // a flat ground
      &water,  // Sims' viscous water without gravity
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
