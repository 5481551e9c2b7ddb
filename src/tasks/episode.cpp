// cambrian: an evaluation's phases, the rest rule, the wall-clock bound and the observer.
#include "tasks/episode.hpp"

#include "core/settings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cambrian {

namespace {

// whole steps in a phase of `seconds`
std::uint64_t stepsIn(double seconds, double time_step) {
  return static_cast<std::uint64_t>(std::llround(seconds / time_step));
}

}  // namespace

void EpisodeSettings::declareSettings(SettingsSchema& s) {
  EpisodeSettings& t = *this;
  auto seconds = [](double v) { return v >= 0 && v <= 3600; };
  s.add("task.evaluation_time", t.evaluation_time, "measured time, s")
      .require([&t] { return t.evaluation_time > 0 && t.evaluation_time <= 3600; },
               "must be in (0, 3600] s");
  s.add("task.settle_time", t.settle_time, "brain off before the trial, s")
      .require([&t, seconds] { return seconds(t.settle_time); }, "must be in [0, 3600] s");
  s.add("task.trial_time", t.trial_time, "brain on, unmeasured, s")
      .require([&t, seconds] { return seconds(t.trial_time); }, "must be in [0, 3600] s");
  s.add("task.resettle_time", t.resettle_time, "brain off again before measuring, s")
      .require([&t, seconds] { return seconds(t.resettle_time); }, "must be in [0, 3600] s");
  s.add("task.rest_check", t.rest_check,
        "Chaumont's rest rule: each settle phase lasts until the body is at rest (at least "
        "task.settle_time / task.resettle_time); no rest within task.settle_max_time: unstable");
  s.add("task.rest_speed", t.rest_speed,
        "rest check: largest speed of any part's centre of mass counted as rest, m/s")
      .require([&t] { return t.rest_speed > 0 && std::isfinite(t.rest_speed); }, "must be > 0 m/s");
  s.add("task.rest_time", t.rest_time, "rest check: how long the body must stay at rest, s")
      .require([&t, seconds] { return seconds(t.rest_time); }, "must be in [0, 3600] s");
  s.add("task.settle_max_time", t.settle_max_time,
        "rest check: the longest a settle phase may last, s")
      .require([&t, seconds] { return seconds(t.settle_max_time); }, "must be in [0, 3600] s")
      // with the rest check on, a settle phase must have room for its minimum and for the rest
      .require(
          [&t] {
            return !t.rest_check ||
                   t.settle_max_time >= std::max({t.settle_time, t.resettle_time, t.rest_time});
          },
          "must be >= task.settle_time, task.resettle_time and task.rest_time when "
          "task.rest_check is on");
  s.add("task.min_parts", t.min_parts,
        "a creature of fewer parts is not evaluated: status invalid_body, the worst fitness "
        "(Minemonics: 2, it discards creatures of 0 or 1 limb)")
      .require([&t] { return t.min_parts >= 1 && t.min_parts <= 1000; }, "must be in 1..1000");
  s.add("task.check_substeps", t.check_substeps,
        "evaluate every creature that passes again at this many physics substeps: its fitness "
        "is the lower of the two, and one that fails there fails (a gait that rides one "
        "discretisation keeps only what it keeps at the other); 0: once")
      .require([&t] { return t.check_substeps >= 0 && t.check_substeps <= 100; },
               "must be in 0..100 (0: no second evaluation)");
  s.add("task.relaxation", t.relaxation,
        "Walking with Dinosaurs' relaxation before the start-up: controller off on a frictionless "
        "ground until the centre of mass keeps its height (task.relax_*); never: unstable");
  s.add("task.relax_steps", t.relax_steps,
        "relaxation: steps in a row the centre of mass must keep its height (the seed: 'a certain "
        "amount of simulation steps ... found empirically')")
      .require([&t] { return t.relax_steps >= 1 && t.relax_steps <= 10000000; },
               "must be in 1..10000000");
  s.add("task.relax_tolerance", t.relax_tolerance,
        "relaxation: the most the centre of mass may rise or sink meanwhile, m")
      .require([&t] { return t.relax_tolerance >= 0 && std::isfinite(t.relax_tolerance); },
               "must be >= 0 and finite");
  s.add("task.relax_max_time", t.relax_max_time,
        "relaxation: the longest it may last, s (the seed: 'we have to restrict the time that the "
        "relaxation can occur')")
      .require([&t, seconds] { return t.relax_max_time > 0 && seconds(t.relax_max_time); },
               "must be in (0, 3600] s");
  s.add("task.max_height", t.max_height,
        "the tallest a creature may stand once relaxed (or at birth), m: taller is too_tall "
        "(Walking with Dinosaurs: 15); 0: no limit")
      .require([&t] { return t.max_height >= 0 && std::isfinite(t.max_height); },
               "must be >= 0 and finite");
}

Episode::Episode(const Creature& creature, const Environment& environment,
                 const PhysicsSettings& physics, const EpisodeSettings& settings,
                 Clock::time_point start, FrameObserver* observer)
    : creature_(creature),
      environment_(environment),
      physics_(physics),
      settings_(settings),
      simulation_(std::make_unique<Simulation>(creature.body, creature.controller.get(),
                                               environment, physics)),
      observer_(observer) {
  const BodyPlan& plan = creature.body;
  outcome_.parts = static_cast<int>(plan.parts.size());
  outcome_.joints = plan.jointCount();
  outcome_.neurons = creature.controller ? creature.controller->neuronCount() : 0;
  bounded_ = physics.max_wall_seconds > 0;
  deadline_ = start + std::chrono::duration_cast<Clock::duration>(
                          std::chrono::duration<double>(physics.max_wall_seconds));

  // the observer sees the body at birth, then every stride steps
  if (observer_) {
    stride_ = std::max<std::uint64_t>(1, observer_->frameStride());
    observer_->begin(plan, physics.time_step, environment);
    show(EvalPhase::settle);
  }
}

void Episode::restart() {
  steps_before_ += simulation_->steps();
  simulation_ = std::make_unique<Simulation>(creature_.body, creature_.controller.get(),
                                             environment_, physics_);
  if (observer_)
    show(EvalPhase::settle);
}

void Episode::show(EvalPhase phase) {
  simulation_->partPoses(poses_);
  simulation_->heldPoses(held_poses_, held_released_);
  EvalFrame frame;
  frame.step = totalSteps();
  frame.time = static_cast<double>(frame.step) * simulation_->timeStep();
  frame.phase = phase;
  frame.center_of_mass = simulation_->centerOfMass();
  frame.poses = poses_;
  frame.held_poses = held_poses_;
  frame.held_released = held_released_;
  frame.light = simulation_->light();
  observer_->frame(frame);
}

bool Episode::pastDeadline() const {
  return bounded_ && Clock::now() > deadline_;
}

Episode::PhaseEnd Episode::runSteps(std::uint64_t steps, bool controller_on, EvalPhase phase,
                                    std::initializer_list<Jury*> juries, bool rest) {
  // the rest check: every part's centre slower than rest_speed for rest_time in a row
  const double dt = simulation_->timeStep();
  const std::uint64_t rest_needed = stepsIn(settings_.rest_time, dt);
  const std::uint64_t last = rest ? std::max(steps, stepsIn(settings_.settle_max_time, dt)) : steps;
  std::uint64_t run = 0, longest = 0;
  double fastest = 0;
  for (Jury* jury : juries)
    jury->begin(*simulation_);

  for (std::uint64_t s = 0; s < last; ++s) {
    simulation_->step(controller_on);
    if (simulation_->status() != EvalStatus::ok)
      return PhaseEnd::stopped;
    bool finished = false;
    for (Jury* jury : juries) {
      jury->observe(*simulation_);
      finished = finished || jury->finished();
    }
    if (!watched(phase))
      return PhaseEnd::stopped;
    // a jury that has measured all it will ends the phase
    if (finished)
      return PhaseEnd::done;
    // a settle phase with the rest check ends once the body has rested long enough
    if (rest) {
      fastest = simulation_->fastestPartSpeed();
      run = fastest <= settings_.rest_speed ? run + 1 : 0;
      longest = std::max(longest, run);
      if (run >= rest_needed && s + 1 >= steps)
        return PhaseEnd::done;
    }
  }
  if (!rest)
    return PhaseEnd::done;

  // never at rest: unstable
  std::ostringstream message;
  message << "not at rest within task.settle_max_time = " << settings_.settle_max_time
          << " s in the " << phaseName(phase) << " phase: no " << settings_.rest_time
          << " s (task.rest_time) with every part slower than task.rest_speed = "
          << settings_.rest_speed << " m/s (longest rest " << longest * dt
          << " s; fastest part at the end " << fastest << " m/s)";
  refuse(EvalStatus::unstable, message.str());
  return PhaseEnd::unstable;
}

bool Episode::watched(EvalPhase phase) {
  // a frame for the observer, if any (it only reads)
  if (observer_ && totalSteps() % stride_ == 0)
    show(phase);
  // wall-clock bound, looked at every 256 steps
  return !(bounded_ && (totalSteps() & 255) == 0 && Clock::now() > deadline_);
}

void Episode::refuse(EvalStatus status, std::string message) {
  outcome_.status = status;
  outcome_.message = std::move(message);
  outcome_.fitness = kWorstFitness;
}

bool Episode::relax() {
  if (settings_.relaxation) {
    // on a frictionless ground, controller off, until the centre of mass keeps its height
    simulation_->setGroundFriction(0);
    const std::uint64_t last = stepsIn(settings_.relax_max_time, simulation_->timeStep());
    const auto needed = static_cast<std::uint64_t>(settings_.relax_steps);
    double height = simulation_->centerOfMass().z;
    std::uint64_t still = 0;
    for (std::uint64_t s = 0; s < last && still < needed; ++s) {
      simulation_->step(false);
      if (simulation_->status() != EvalStatus::ok || !watched(EvalPhase::settle))
        return false;
      const double z = simulation_->centerOfMass().z;
      still = std::abs(z - height) <= settings_.relax_tolerance ? still + 1 : 0;
      if (still == 0)
        height = z;
    }
    if (still < needed) {
      std::ostringstream message;
      message << "not relaxed within task.relax_max_time = " << settings_.relax_max_time
              << " s: the centre of mass never kept its height within task.relax_tolerance = "
              << settings_.relax_tolerance << " m for task.relax_steps = " << settings_.relax_steps
              << " steps";
      refuse(EvalStatus::unstable, message.str());
      return false;
    }
    simulation_->setGroundFriction(environment_.ground.friction);
  }
  // the height test
  if (settings_.max_height > 0 && simulation_->height() > settings_.max_height) {
    std::ostringstream message;
    message << "the creature stands " << simulation_->height() << " m tall"
            << (settings_.relaxation ? " once relaxed" : " at birth") << " (task.max_height "
            << settings_.max_height << " m)";
    refuse(EvalStatus::too_tall, message.str());
    return false;
  }
  return true;
}

bool Episode::settle(double seconds, EvalPhase phase) {
  return runSteps(stepsIn(seconds, simulation_->timeStep()), false, phase, {},
                  settings_.rest_check) == PhaseEnd::done;
}

bool Episode::startUp() {
  return relax() && settle(settings_.settle_time, EvalPhase::settle) &&
         run(settings_.trial_time, EvalPhase::trial) &&
         settle(settings_.resettle_time, EvalPhase::resettle);
}

bool Episode::run(double seconds, EvalPhase phase, std::initializer_list<Jury*> juries) {
  return runSteps(stepsIn(seconds, simulation_->timeStep()), true, phase, juries, false) ==
         PhaseEnd::done;
}

Outcome Episode::finish() {
  outcome_.steps = totalSteps();
  if (simulation_->status() != EvalStatus::ok) {
    outcome_.status = simulation_->status();
    outcome_.message = simulation_->message();
    outcome_.fitness = kWorstFitness;
  } else if (pastDeadline()) {
    outcome_.status = EvalStatus::timeout;
    outcome_.message = "evaluation exceeded physics.max_wall_seconds";
    outcome_.fitness = kWorstFitness;
  }
  return outcome_;
}

}  // namespace cambrian
