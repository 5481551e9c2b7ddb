// cambrian: the water environment.
#include "physics/water_environment.hpp"

#include "core/settings.hpp"

#include <cmath>

namespace cambrian {

std::unique_ptr<EnvironmentKind> WaterEnvironment::clone() const {
  return std::make_unique<WaterEnvironment>(*this);
}

void WaterEnvironment::declareSettings(SettingsSchema& s) {
  s.add("environment.viscosity", viscosity,
        "water: N s/m^3, the force on each face against its normal velocity per m^2 of face and "
        "m/s (Sims 1994)")
      .require([this] { return viscosity >= 0 && std::isfinite(viscosity); },
               "must be >= 0 and finite");
  s.add("environment.net_gravity", net_gravity,
        "water: gravity minus buoyancy, m/s^2 downwards (0: neutrally buoyant, Sims' gravity off)")
      .require([this] { return net_gravity >= 0 && std::isfinite(net_gravity); },
               "must be >= 0 and finite");
}

Environment WaterEnvironment::build(const PhysicsSettings&) const {
  Environment environment;
  environment.ground.kind = Ground::Kind::none;
  environment.gravity = net_gravity;
  environment.fluid.viscosity = viscosity;
  return environment;
}

}  // namespace cambrian
