// cambrian: the registered world kinds — one line each.
#include "physics/world.hpp"

#include "cambrian/error.hpp"

#include "physics/featherstone_world.hpp"
#include "physics/rigid_body_world.hpp"

#include <btBulletDynamicsCommon.h>

namespace cambrian {

const std::vector<WorldKind>& worldKinds() {
  static const std::vector<WorldKind> registered = {
      {FeatherstoneWorld::kName, "Bullet Featherstone multibody (tree-shaped bodies)",
       [](const BodyPlan& plan, const Environment& environment, const PhysicsSettings& physics,
          double birth_height) -> std::unique_ptr<World> {
         return std::make_unique<FeatherstoneWorld>(plan, environment, physics, birth_height);
       }},
      {RigidBodyWorld::kName,
       "Bullet rigid bodies joined by 6-DoF constraints (closed loops allowed; Minemonics)",
       [](const BodyPlan& plan, const Environment& environment, const PhysicsSettings& physics,
          double birth_height) -> std::unique_ptr<World> {
         return std::make_unique<RigidBodyWorld>(plan, environment, physics, birth_height);
       }},
  };
  return registered;
}

std::vector<std::string> worldNames() {
  std::vector<std::string> names;
  for (const WorldKind& kind : worldKinds())
    names.push_back(kind.name);
  return names;
}

std::string worldNamesText() {
  std::string text;
  for (const WorldKind& kind : worldKinds())
    text += (text.empty() ? "" : " | ") + kind.name + " (" + kind.summary + ")";
  return text;
}

std::unique_ptr<World> makeWorld(const BodyPlan& plan, const Environment& environment,
                                 const PhysicsSettings& physics, double birth_height) {
  for (const WorldKind& kind : worldKinds()) {
    if (kind.name == physics.world)
      return kind.make(plan, environment, physics, birth_height);
  }
  throw ConfigError("physics.world = " + physics.world + ": no such world");
}

const char* bulletPrecision() {
  return sizeof(btScalar) == 8 ? "float64" : "float32";
}

}  // namespace cambrian
