// cambrian: Sims' water (1994) — no ground, gravity turned off (a neutrally buoyant body), and a
// viscous force against the normal velocity of every face of every part.
#pragma once

#include "physics/environment.hpp"

namespace cambrian {

/// Water: nothing to stand on, environment.net_gravity (0: Sims' "turning off gravity"), every
/// face of every part and object resisted by environment.viscosity; the light 10 m along +x.
class WaterEnvironment : public EnvironmentKind {
 public:
  std::unique_ptr<EnvironmentKind> clone() const override;
  std::string name() const override { return "water"; }
  void declareSettings(SettingsSchema& schema) override;
  Environment build(const PhysicsSettings& physics) const override;

  /// N s / m^3: a face of area A moving at normal speed v feels viscosity x A x v
  double viscosity = 100;
  /// m / s^2: gravity minus buoyancy; 0, a body as dense as the water (Sims)
  double net_gravity = 0;
};

}  // namespace cambrian
