// cambrian: physics worlds as plug-ins. A World holds one creature (a BodyPlan) in an
// environment and steps it; the Bullet Featherstone multibody world is the first, a constrained
// rigid-body world (rigid_body_world.hpp) the second; physics.world chooses. Everything a task, a
// sensor or a monitor reads goes through this interface.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/math.hpp"
#include "cambrian/outcome.hpp"

#include "physics/environment.hpp"
#include "physics/physics_settings.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace cambrian {

/// A joint degree of freedom and how fast it moves.
struct JointSpeed {
  int part = 0;      ///< the part the joint attaches to its parent
  int dof = 0;       ///< its degree of freedom
  double speed = 0;  ///< |velocity|, rad/s (prismatic: m/s)
};

/// One creature in a world of its own. Single-threaded; nothing shared between instances.
class World {
 public:
  virtual ~World() = default;

  /// ok when the creature was born; otherwise why not: invalid_body for a plan this world cannot
  /// build (the message says what and which world can), self_penetration for parts overlapping
  /// at birth.
  virtual EvalStatus birthStatus() const = 0;
  /// Detail for a non-ok birth status.
  virtual const std::string& birthMessage() const = 0;

  /// One fixed time step: joint commands in [-1, 1] (one per BodyPlan effector; empty: the
  /// controller is off) applied through the substeps, then the step itself.
  virtual void step(std::span<const double> commands) = 0;

  /// World position of part `part`'s centre, m.
  virtual Vec3 partPosition(int part) const = 0;
  /// World pose of part `part`.
  virtual Transform partPose(int part) const = 0;
  /// Position of degree of freedom `dof` of the joint between `part` and its parent (radians,
  /// prismatic: m); 0 for a fixed joint.
  virtual double jointPosition(int part, int dof) const = 0;
  /// The world direction of the axis of degree of freedom `dof` of the joint between `part` and
  /// its parent (for a multi-degree-of-freedom joint: where the earlier degrees of freedom have
  /// turned it); zero for a part without that degree of freedom.
  virtual Vec3 jointAxis(int part, int dof) const = 0;
  /// Part `part`'s mass as simulated, kg.
  virtual double partMass(int part) const = 0;
  /// Part `part`'s principal moments of inertia about its centre, in its own frame, kg m^2.
  virtual Vec3 partInertia(int part) const = 0;
  /// The joint degree of freedom turning fastest after the last step: its part, dof and speed
  /// (rad/s, prismatic: m/s); speed 0 for a body without joints.
  virtual JointSpeed fastestJoint() const = 0;
  /// Per part, what touches it after the last step: bit f set when something touches its face f
  /// (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z, the face a contact point lies nearest to); 0 when
  /// nothing touches it.
  virtual const std::vector<std::uint8_t>& contacts() = 0;
  /// Per part, 1 when it touches the ground (plane or terrain) after the last step, else 0.
  virtual const std::vector<std::uint8_t>& groundContacts() = 0;
  /// The pairs of the creature's own parts that touch each other after the last step, each
  /// (lower part, higher part), in increasing order.
  virtual const std::vector<std::pair<int, int>>& partContacts() = 0;
  /// How far the joint that has come most apart after the last step is from holding, m: the
  /// distance between its pivots on its two parts, over the joints that hold a point and turn
  /// about it (revolute, universal, spherical; 0 in a world whose joints cannot part).
  virtual double largestJointError() const = 0;
  /// The unit direction from part `part` towards the world point `point`, in the part's frame.
  virtual Vec3 directionInPart(int part, Vec3 point) const = 0;
  /// Height of the creature's lowest point above z = 0, m.
  virtual double lowestPoint() const = 0;
  /// The ground's friction coefficient from the next step on (Walking with Dinosaurs relaxes a
  /// creature on a frictionless ground, then measures it on the ground it was born on).
  virtual void setGroundFriction(double friction) = 0;
  /// The part whose joint has broken under more than its breaking load (physics.joint_breaking x
  /// its strength), or -1: none has (always, in a world whose joints cannot break).
  virtual int brokenJoint() const { return -1; }
  /// World pose of free object `object` of the environment (Environment::objects order).
  virtual Transform objectPose(int object) const = 0;
  /// World pose of held object `held` (BodyPlan::held order).
  virtual Transform heldPose(int held) const = 0;
  /// Whether held object `held` has been let go (its release effector fired).
  virtual bool released(int held) const = 0;
  /// The creature's mechanical energy, J: kinetic plus gravitational (m g z, z = 0 at the ground)
  /// of every body the world simulates for it.
  virtual double mechanicalEnergy() const = 0;
  /// An upper bound on the work the effectors have done since birth, J: the sum over steps of
  /// torque limit x |command| x |joint speed| x time (no motor or torque can deliver more).
  virtual double effectorWorkBound() const = 0;
};

/// Makes a world of one kind: the plan, the environment, the physics settings and the height of
/// the creature's lowest point above the ground at birth.
using WorldFactory = std::function<std::unique_ptr<World>(
    const BodyPlan&, const Environment&, const PhysicsSettings&, double birth_height)>;

/// A registered world kind.
struct WorldKind {
  std::string name;     ///< physics.world = NAME
  std::string summary;  ///< one line for --help
  WorldFactory make;
};

/// Every registered world kind, in registration order.
const std::vector<WorldKind>& worldKinds();
/// The names of every registered world.
std::vector<std::string> worldNames();
/// "a | b" for help texts.
std::string worldNamesText();
/// The world named `physics.world` holding `plan` in `environment`, its lowest point
/// `birth_height` m above the ground. Throws ConfigError for an unknown name.
std::unique_ptr<World> makeWorld(const BodyPlan& plan, const Environment& environment,
                                 const PhysicsSettings& physics, double birth_height = 0);

}  // namespace cambrian
