// cambrian: one creature in a fresh Bullet world — build, sense, act, step, watch.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/math.hpp"
#include "cambrian/outcome.hpp"

#include "brain/brain.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

struct BulletWorld;  // the Bullet objects, private to simulation.cpp

/// A creature built from a BodyPlan as a Featherstone multibody (btMultiBody) on a ground plane,
/// in a world of its own. Multi-degree-of-freedom joints are chains of revolute joints through
/// light virtual links. The creature is born resting on the ground (lowest point at z = 0).
/// Single-threaded; nothing is shared between instances, so evaluations are independent.
class Simulation {
 public:
  /// Builds the world with the creature's lowest point `birth_height` m above the ground (0:
  /// resting on it). A body that overlaps itself at birth gets status() self_penetration; stepping
  /// it does nothing. Unless `settings.self_collision`, parts touch only the ground afterwards.
  Simulation(const BodyPlan& plan, const PhysicsSettings& settings, Vec3 target = {10, 0, 0},
             double birth_height = 0);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// One fixed step: sensors -> brain (when on) -> joint torques -> Bullet step -> monitors.
  /// Does nothing once status() is not ok. No heap allocation.
  void step(bool brain_on);
  /// ok while every rule holds; otherwise the first rule broken.
  EvalStatus status() const { return status_; }
  /// Detail for a non-ok status.
  const std::string& message() const { return message_; }
  /// Steps taken so far.
  std::uint64_t steps() const { return steps_; }
  /// Simulated time, s.
  double time() const { return static_cast<double>(steps_) * settings_.time_step; }

  /// Mass-weighted centre of the parts, world frame, m.
  Vec3 centerOfMass() const;
  /// Height of the lowest box corner above the ground, m.
  double lowestPoint() const;
  /// World pose of every part (BodyPlan order).
  void partPoses(std::vector<Transform>& poses) const;
  /// Number of part pairs in contact with each other or the ground, after the last step.
  const std::vector<std::uint8_t>& partContacts() const { return contact_; }
  /// The controller (for tests and tracing).
  const Brain& brain() const { return brain_; }

 private:
  void build(double birth_height);
  void checkBirthPenetration();
  void stopSelfContacts();
  void readSensors();
  void applyTorques(bool brain_on, double substep);
  void monitor();
  void fail(EvalStatus status, std::string message);

  const BodyPlan& plan_;
  PhysicsSettings settings_;
  Vec3 target_;
  Brain brain_;
  std::unique_ptr<BulletWorld> bullet_;
  EvalStatus status_ = EvalStatus::ok;
  std::string message_;
  std::uint64_t steps_ = 0;

  // per part: Bullet link of each degree of freedom (-1 none), torque limit, previous position
  std::vector<std::array<int, 3>> dof_link_;
  std::vector<double> max_torque_;
  std::vector<Vec3> birth_position_, previous_position_;
  std::vector<std::uint8_t> contact_;
  std::vector<int> damped_links_;  // every revolute link, real or virtual
};

/// Bullet's scalar type in this build: "float64" (the float64 package, the default) or
/// "float32"; recorded in every history (bullet_precision), since results depend on it.
const char* bulletPrecision();

}  // namespace cambrian
