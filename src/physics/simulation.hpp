// cambrian: one creature living in a world — sensors read, the controller stepped, its commands
// clamped and applied, the world stepped, the monitors watching. The world and the controller
// are plug-ins held by interface.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/controller.hpp"
#include "cambrian/math.hpp"
#include "cambrian/outcome.hpp"

#include "physics/environment.hpp"
#include "physics/physics_settings.hpp"
#include "physics/world.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

/// A creature (its body plan and controller plan) in a world of its own, built by the world
/// named physics.world. The creature is born resting on the ground (lowest point `birth_height`
/// m above it). A creature that cannot be born has status() invalid_body or self_penetration
/// and stepping it does nothing. Single-threaded; evaluations are independent.
class Simulation {
 public:
  /// `plan`, `environment` and `controller` must outlive the simulation; `controller` may be null
  /// (nothing drives the effectors).
  Simulation(const BodyPlan& plan, const ControllerPlan* controller, const Environment& environment,
             const PhysicsSettings& settings, double birth_height = 0);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// One fixed step: sensors -> controller (when on) -> commands -> world step -> monitors.
  /// Does nothing once status() is not ok. No heap allocation.
  void step(bool controller_on);
  /// ok while every rule holds; otherwise the first rule broken.
  EvalStatus status() const { return status_; }
  /// Detail for a non-ok status.
  const std::string& message() const { return message_; }
  /// Steps taken so far.
  std::uint64_t steps() const { return steps_; }
  /// The fixed time step, s.
  double timeStep() const { return settings_.time_step; }
  /// Simulated time, s.
  double time() const { return static_cast<double>(steps_) * settings_.time_step; }

  /// Mass-weighted centre of the parts, world frame, m.
  Vec3 centerOfMass() const;
  /// Height of the creature's lowest point above the ground, m.
  double lowestPoint() const;
  /// The ground's friction coefficient from the next step on (World::setGroundFriction).
  void setGroundFriction(double friction) { world_->setGroundFriction(friction); }
  /// The creature's height: its highest point above its lowest, m.
  double height() const;
  /// World pose of every part (BodyPlan order).
  void partPoses(std::vector<Transform>& poses) const;
  /// World pose of every held object (BodyPlan::held order) and whether each has been let go.
  void heldPoses(std::vector<Transform>& poses, std::vector<std::uint8_t>& released) const;
  /// The body plan.
  const BodyPlan& plan() const { return plan_; }
  /// Per part, 1 when it touches the ground after the last step (juries that count contacts).
  const std::vector<std::uint8_t>& groundContacts() const { return world_->groundContacts(); }
  /// The environment the creature lives in.
  const Environment& environment() const { return environment_; }
  /// The world (for tasks that read the environment's objects).
  const World& world() const { return *world_; }
  /// Where the light the photosensors point at is now (the environment's at first), world, m.
  Vec3 light() const { return light_; }
  /// Moves the light (a task that makes the creature follow it); sensors see it from the next
  /// step.
  void moveLight(Vec3 position) { light_ = position; }
  /// The sensor values of the last step (BodyPlan sensor order).
  const std::vector<double>& sensors() const { return sensors_; }
  /// The commands in [-1, 1] of the last step with the controller on (BodyPlan effector order).
  const std::vector<double>& commands() const { return commands_; }
  /// The controller (null when the creature has none).
  const Controller* controller() const { return controller_.get(); }
  /// The largest rise of mechanical energy so far, over any stretch of steps, that gravity and
  /// the effectors' work bound do not explain, J (World::mechanicalEnergy, effectorWorkBound).
  /// Exact dynamics with friction, damping and inelastic contacts never makes it positive.
  double unexplainedEnergy() const { return unexplained_energy_; }
  /// The unit of physics.max_energy_gain for this body: its weight under 9.81 m/s^2 times its
  /// length (the larger of its horizontal span and its largest part side), J.
  double energyScale() const { return energy_scale_; }
  /// The speed of the fastest part's centre over the last step, m/s (0 before the first step):
  /// what a rest rule compares with its threshold.
  double fastestPartSpeed() const { return fastest_part_speed_; }

 private:
  void readSensors();
  void monitor();
  bool watchStep(const char* what, std::size_t index, Vec3 position, Vec3 previous);
  void watchEnergy();
  bool watchSpin();
  bool watchHits();
  void fail(EvalStatus status, std::string message);

  const BodyPlan& plan_;
  const Environment& environment_;
  PhysicsSettings settings_;
  std::unique_ptr<World> world_;
  std::unique_ptr<Controller> controller_;
  EvalStatus status_ = EvalStatus::ok;
  std::string message_;
  std::uint64_t steps_ = 0;

  std::vector<double> sensors_, drives_, commands_;
  bool reads_contacts_ = false;  // what the sensors need of the world
  Vec3 light_;                   // light(), moveLight()
  std::vector<Vec3> birth_position_, previous_position_;
  std::vector<Vec3> previous_held_;      // each held object's position at the last step
  std::vector<Quat> previous_rotation_;  // per part, when physics.max_angular_speed watches
  std::vector<int> hits_;  // per step of the last second, when physics.max_contact_rate watches
  int hits_in_window_ = 0;
  std::vector<std::pair<int, int>> touching_;  // the parts touching after the step before
  double energy_scale_ = 0;
  double lowest_balance_ = 0;  // lowest energy minus work bound so far
  double unexplained_energy_ = 0;
  double fastest_part_speed_ = 0;  // fastestPartSpeed(), set by monitor()
};

}  // namespace cambrian
