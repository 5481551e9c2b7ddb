// cambrian: a creature in a world — the step loop and the safety monitors.
#include "physics/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cambrian {

namespace {

// the unit of physics.max_energy_gain, m/s^2, whatever physics.gravity is
constexpr double kStandardGravity = 9.81;

}  // namespace

Simulation::Simulation(const BodyPlan& plan, const ControllerPlan* controller,
                       const Environment& environment, const PhysicsSettings& settings,
                       double birth_height)
    : plan_(plan), environment_(environment), settings_(settings), light_(environment.light) {
  // the controller first (a plan that does not fit the body throws), then the world
  sensors_.assign(plan_.sensors.size(), 0.0);
  for (const SensorPlan& sensor : plan_.sensors) {
    reads_contacts_ = reads_contacts_ || sensor.kind == SensorKind::contact ||
                      sensor.kind == SensorKind::contact_face;
  }
  drives_.assign(plan_.effectors.size(), 0.0);
  commands_.assign(plan_.effectors.size(), 0.0);
  if (controller)
    controller_ = controller->build(settings_.time_step, sensors_.size(), drives_.size());
  world_ = makeWorld(plan_, environment_, settings_, birth_height);
  if (world_->birthStatus() != EvalStatus::ok) {
    fail(world_->birthStatus(), world_->birthMessage());
    return;
  }

  // monitor state: where every part was born
  birth_position_.resize(plan_.parts.size());
  for (std::size_t i = 0; i < plan_.parts.size(); ++i)
    birth_position_[i] = world_->partPosition(static_cast<int>(i));
  previous_position_ = birth_position_;
  if (settings_.max_angular_speed > 0) {
    for (std::size_t i = 0; i < plan_.parts.size(); ++i)
      previous_rotation_.push_back(world_->partPose(static_cast<int>(i)).rotation);
  }
  if (settings_.max_contact_rate >= 0)
    hits_.assign(static_cast<std::size_t>(std::max(1.0, std::round(1 / settings_.time_step))), 0);
  for (std::size_t h = 0; h < plan_.held.size(); ++h)
    previous_held_.push_back(world_->heldPose(static_cast<int>(h)).position);

  // the energy watch: its unit and its starting balance
  double mass = 0, length = bodyLength(plan_);
  for (const PartPlan& part : plan_.parts) {
    mass += part.mass;
    length = std::max({length, part.size.x, part.size.y, part.size.z});
  }
  energy_scale_ = mass * kStandardGravity * length;
  lowest_balance_ = world_->mechanicalEnergy();
}

Simulation::~Simulation() = default;

void Simulation::fail(EvalStatus status, std::string message) {
  if (status_ != EvalStatus::ok)
    return;
  status_ = status;
  message_ = std::move(message);
}

void Simulation::readSensors() {
  // contacts (when a sensor reads them), then every sensor slot; a photosensor's part sees the
  // light's direction in its own frame (made once for a run of sensors on one part)
  static const std::vector<std::uint8_t> kNoContacts;
  const std::vector<std::uint8_t>& contact = reads_contacts_ ? world_->contacts() : kNoContacts;
  Vec3 to_light;
  int light_part = -1;
  for (std::size_t s = 0; s < plan_.sensors.size(); ++s) {
    const SensorPlan& sensor = plan_.sensors[s];
    switch (sensor.kind) {
      case SensorKind::joint_angle: {
        double limit = std::max(0.1, plan_.parts[sensor.part].joint_limit[sensor.axis]);
        sensors_[s] = world_->jointPosition(sensor.part, sensor.axis) / limit;
        break;
      }
      case SensorKind::contact:
        sensors_[s] = contact[sensor.part] != 0 ? 1.0 : 0.0;
        break;
      case SensorKind::contact_face:
        sensors_[s] = (contact[sensor.part] >> sensor.axis & 1u) != 0 ? 1.0 : -1.0;
        break;
      case SensorKind::photo:
        if (sensor.part != light_part) {
          light_part = sensor.part;
          to_light = world_->directionInPart(sensor.part, light_);
        }
        sensors_[s] = to_light[sensor.axis];
        break;
    }
  }
}

bool Simulation::watchStep(const char* what, std::size_t index, Vec3 position, Vec3 previous) {
  // non-finite state, or a numerical explosion: too fast (messages made only on failure)
  if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
    fail(EvalStatus::non_finite,
         std::string(what) + " " + std::to_string(index) + " has a non-finite position");
    return false;
  }
  const Vec3 moved = position - previous;
  const double max_step = settings_.max_speed * settings_.time_step;
  if (dot(moved, moved) > max_step * max_step) {
    std::ostringstream message;
    message << what << " " << index << " moved at " << norm(moved) / settings_.time_step
            << " m/s (physics.max_speed " << settings_.max_speed << ") at step " << steps_;
    fail(EvalStatus::exploded, message.str());
    return false;
  }
  return true;
}

void Simulation::monitor() {
  const double max_displacement_sq = settings_.max_displacement * settings_.max_displacement;
  double largest_step_sq = 0;  // the fastest part's displacement this step, squared
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    Vec3 position = world_->partPosition(static_cast<int>(i));
    if (!watchStep("part", i, position, previous_position_[i]))
      return;

    // numerical explosion: too far
    Vec3 from_birth = position - birth_position_[i];
    if (dot(from_birth, from_birth) > max_displacement_sq) {
      std::ostringstream message;
      message << "part " << i << " is " << norm(from_birth)
              << " m from where it was born (physics.max_displacement "
              << settings_.max_displacement << ") at step " << steps_;
      fail(EvalStatus::exploded, message.str());
      return;
    }
    const Vec3 moved = position - previous_position_[i];
    largest_step_sq = std::max(largest_step_sq, dot(moved, moved));
    previous_position_[i] = position;
  }
  fastest_part_speed_ = std::sqrt(largest_step_sq) / settings_.time_step;

  // a joint broken under its load (Walking with Dinosaurs' dismemberment)
  if (const int part = world_->brokenJoint(); part >= 0) {
    std::ostringstream message;
    message << "the joint of part " << part << " broke under more than physics.joint_breaking "
            << settings_.joint_breaking << " x its strength at step " << steps_;
    fail(EvalStatus::dismembered, message.str());
    return;
  }

  // a joint turning implausibly fast (Minemonics' discard)
  if (settings_.max_joint_speed > 0) {
    const JointSpeed joint = world_->fastestJoint();
    if (joint.speed > settings_.max_joint_speed) {
      std::ostringstream message;
      message << "the joint of part " << joint.part << " (degree of freedom " << joint.dof
              << ") moved at " << joint.speed << " rad/s (physics.max_joint_speed "
              << settings_.max_joint_speed << ") at step " << steps_;
      fail(EvalStatus::exploded, message.str());
      return;
    }
  }

  // a part spinning too fast, a joint come apart, parts hitting each other too often (the
  // springy organisms' monitors)
  if (!previous_rotation_.empty() && !watchSpin())
    return;
  if (settings_.max_joint_error > 0) {
    const double error = world_->largestJointError();
    if (error > settings_.max_joint_error) {
      std::ostringstream message;
      message << "a joint came " << error << " m apart (physics.max_joint_error "
              << settings_.max_joint_error << ") at step " << steps_;
      fail(EvalStatus::joint_error, message.str());
      return;
    }
  }
  if (!hits_.empty() && !watchHits())
    return;

  // what the creature holds or has thrown: watched as a part is, except for the distance (it
  // may go as far as it is thrown)
  for (std::size_t h = 0; h < previous_held_.size(); ++h) {
    const Vec3 position = world_->heldPose(static_cast<int>(h)).position;
    if (!watchStep("held object", h, position, previous_held_[h]))
      return;
    previous_held_[h] = position;
  }
  watchEnergy();
}

bool Simulation::watchSpin() {
  // the angle each part turned through in the step, over the step; parts without a collider of
  // their own (a springy organism's proxies, massive points of its muscles) are not watched
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    if (!plan_.parts[i].solid)
      continue;
    const Quat rotation = world_->partPose(static_cast<int>(i)).rotation;
    const Quat turn = conjugate(previous_rotation_[i]) * rotation;
    const double angle =
        2 * std::atan2(std::sqrt(turn.x * turn.x + turn.y * turn.y + turn.z * turn.z),
                       std::abs(turn.w));
    previous_rotation_[i] = rotation;
    if (angle > settings_.max_angular_speed * settings_.time_step) {
      std::ostringstream message;
      message << "part " << i << " turned at " << angle / settings_.time_step
              << " rad/s (physics.max_angular_speed " << settings_.max_angular_speed << ") at step "
              << steps_;
      fail(EvalStatus::exploded, message.str());
      return false;
    }
  }
  return true;
}

bool Simulation::watchHits() {
  // a hit: a pair of parts touching that did not touch after the step before; counted over the
  // last simulated second (a ring of per-step counts)
  const std::vector<std::pair<int, int>>& touching = world_->partContacts();
  int hits = 0;
  for (const auto& pair : touching)
    hits += std::binary_search(touching_.begin(), touching_.end(), pair) ? 0 : 1;
  touching_ = touching;
  const std::size_t slot = static_cast<std::size_t>(steps_ % hits_.size());
  hits_in_window_ += hits - hits_[slot];
  hits_[slot] = hits;
  const double window = static_cast<double>(hits_.size()) * settings_.time_step;
  if (hits_in_window_ > settings_.max_contact_rate * window) {
    std::ostringstream message;
    message << "the parts hit each other " << hits_in_window_ << " times in the last " << window
            << " s (physics.max_contact_rate " << settings_.max_contact_rate << " per s) at step "
            << steps_;
    fail(EvalStatus::self_contact, message.str());
    return false;
  }
  return true;
}

void Simulation::watchEnergy() {
  // energy minus the effectors' work bound never rises in exact dynamics; any rise over any
  // stretch of steps is energy from nothing (a contact or limit correction, the integrator)
  const double balance = world_->mechanicalEnergy() - world_->effectorWorkBound();
  lowest_balance_ = std::min(lowest_balance_, balance);
  unexplained_energy_ = std::max(unexplained_energy_, balance - lowest_balance_);
  const double allowed = settings_.max_energy_gain * energy_scale_;
  if (settings_.max_energy_gain > 0 && unexplained_energy_ > allowed) {
    std::ostringstream message;
    message << "the body gained " << unexplained_energy_
            << " J that gravity and its effectors do not explain (physics.max_energy_gain "
            << settings_.max_energy_gain << " x " << energy_scale_ << " J) at step " << steps_;
    fail(EvalStatus::exploded, message.str());
  }
}

void Simulation::step(bool controller_on) {
  if (status_ != EvalStatus::ok)
    return;

  // sense, think: drives clamped to [-1, 1] (non-finite ones to 0)
  readSensors();
  if (controller_on && controller_) {
    controller_->step(sensors_, drives_);
    for (std::size_t e = 0; e < drives_.size(); ++e)
      commands_[e] = std::isfinite(drives_[e]) ? std::clamp(drives_[e], -1.0, 1.0) : 0.0;
  }

  // act, then watch
  world_->step(controller_on && controller_ ? std::span<const double>(commands_)
                                            : std::span<const double>());
  ++steps_;
  monitor();
}

Vec3 Simulation::centerOfMass() const {
  Vec3 weighted;
  double mass = 0;
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    Vec3 position = world_->partPosition(static_cast<int>(i));
    weighted = weighted + position * plan_.parts[i].mass;
    mass += plan_.parts[i].mass;
  }
  return mass > 0 ? weighted * (1.0 / mass) : weighted;
}

double Simulation::lowestPoint() const {
  return world_->lowestPoint();
}

double Simulation::height() const {
  // each solid part's reach up and down from its centre, as placed now
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (std::size_t i = 0; i < plan_.parts.size(); ++i) {
    const PartPlan& part = plan_.parts[i];
    if (!part.solid)
      continue;
    const Transform pose = world_->partPose(static_cast<int>(i));
    top = std::max(top,
                   pose.position.z + shapeReach(part.shape, part.size, pose.rotation, {0, 0, 1}));
    bottom = std::min(
        bottom, pose.position.z - shapeReach(part.shape, part.size, pose.rotation, {0, 0, -1}));
  }
  return top > bottom ? top - bottom : 0;
}

void Simulation::partPoses(std::vector<Transform>& poses) const {
  poses.resize(plan_.parts.size());
  for (std::size_t i = 0; i < plan_.parts.size(); ++i)
    poses[i] = world_->partPose(static_cast<int>(i));
}

void Simulation::heldPoses(std::vector<Transform>& poses,
                           std::vector<std::uint8_t>& released) const {
  poses.resize(plan_.held.size());
  released.resize(plan_.held.size());
  for (std::size_t i = 0; i < plan_.held.size(); ++i) {
    poses[i] = world_->heldPose(static_cast<int>(i));
    released[i] = world_->released(static_cast<int>(i)) ? 1 : 0;
  }
}

}  // namespace cambrian
