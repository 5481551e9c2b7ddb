// cambrian: environment kinds as plug-ins (plane, water, hills), chosen by
// environment.name; each builds the Environment (cambrian/environment.hpp) an evaluation runs
// in. Tasks add the objects they need (Task::prepare) and read them back from the world.
#pragma once

#include "cambrian/environment.hpp"

#include "physics/physics_settings.hpp"

#include <memory>
#include <string>
#include <vector>

namespace cambrian {

class SettingsSchema;

/// A kind of environment (a plug-in): its settings and how it builds the environment.
class EnvironmentKind {
 public:
  virtual ~EnvironmentKind() = default;
  /// A copy with the same settings.
  virtual std::unique_ptr<EnvironmentKind> clone() const = 0;
  /// The name users give (environment.name = NAME).
  virtual std::string name() const = 0;
  /// Declares its own settings (environment.* keys), bound to this instance.
  virtual void declareSettings(SettingsSchema&) {}
  /// The environment, given the physics settings (ground friction and restitution).
  virtual Environment build(const PhysicsSettings& physics) const = 0;
};

/// A flat, infinite ground plane (physics.ground_friction, physics.restitution) under
/// physics.gravity, nothing on it, no fluid, the light 10 m ahead along +x.
class PlaneEnvironment : public EnvironmentKind {
 public:
  std::unique_ptr<EnvironmentKind> clone() const override;
  std::string name() const override { return "plane"; }
  Environment build(const PhysicsSettings& physics) const override;
};

/// Every registered environment kind (prototypes), in registration order.
const std::vector<const EnvironmentKind*>& environmentKinds();
/// The names of every registered environment kind.
std::vector<std::string> environmentNames();

}  // namespace cambrian
