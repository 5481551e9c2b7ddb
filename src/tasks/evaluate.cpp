#include "cambrian/evaluate.hpp"

#include "cambrian/error.hpp"

#include "physics/simulation.hpp"
#include "tasks/juries.hpp"
#include "tasks/synthetic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// whole steps in a phase of `seconds`
std::uint64_t stepsIn(double seconds, double time_step) {
  return static_cast<std::uint64_t>(std::llround(seconds / time_step));
}

// a frame observer and the pose buffer it is shown (allocated once, only when observing)
struct Watch {
  FrameObserver* observer = nullptr;
  std::uint64_t stride = 1;
  std::vector<Transform> poses;

  // shows the observer the world as it is now
  void show(const Simulation& simulation, EvalPhase phase) {
    simulation.partPoses(poses);
    EvalFrame frame;
    frame.step = simulation.steps();
    frame.time = simulation.time();
    frame.phase = phase;
    frame.center_of_mass = simulation.centerOfMass();
    frame.poses = poses;
    observer->frame(frame);
  }
};

// Chaumont et al.'s rest rule over a settle phase: the creature is at rest once every part's
// centre of mass has moved slower than `speed` for `steps_needed` consecutive steps
class RestCheck {
 public:
  RestCheck(double speed, std::uint64_t steps_needed, double time_step)
      : speed_(speed), steps_needed_(steps_needed), time_step_(time_step) {}

  // a new phase: rest counts from its first step
  void begin(const Simulation& simulation) {
    simulation.partPoses(poses_);
    previous_.resize(poses_.size());
    for (std::size_t i = 0; i < poses_.size(); ++i)
      previous_[i] = poses_[i].position;
    run_ = 0;
    longest_run_ = 0;
  }

  // after each step: the fastest part's speed, and whether the rest has lasted long enough
  bool observe(const Simulation& simulation) {
    simulation.partPoses(poses_);
    fastest_ = 0;
    for (std::size_t i = 0; i < poses_.size(); ++i) {
      fastest_ = std::max(fastest_, norm(poses_[i].position - previous_[i]) / time_step_);
      previous_[i] = poses_[i].position;
    }
    run_ = fastest_ <= speed_ ? run_ + 1 : 0;
    longest_run_ = std::max(longest_run_, run_);
    return run_ >= steps_needed_;
  }

  double fastest() const { return fastest_; }
  std::uint64_t longestRun() const { return longest_run_; }

 private:
  double speed_;
  std::uint64_t steps_needed_;
  double time_step_;
  std::vector<Transform> poses_;
  std::vector<Vec3> previous_;
  std::uint64_t run_ = 0, longest_run_ = 0;
  double fastest_ = 0;
};

// how a phase ended
enum class PhaseEnd { done, stopped, unstable };

// runs `steps` steps, or, with a rest check, at least `steps` and until the creature is at rest
// (at most `max_steps`); stopped when a rule broke or the wall-clock bound passed
PhaseEnd runPhase(Simulation& simulation, std::uint64_t steps, bool brain_on, Jury* jury,
                  Clock::time_point deadline, bool bounded, EvalPhase phase, Watch* watch,
                  RestCheck* rest = nullptr, std::uint64_t max_steps = 0) {
  if (rest)
    rest->begin(simulation);
  const std::uint64_t last = rest ? std::max(steps, max_steps) : steps;
  for (std::uint64_t s = 0; s < last; ++s) {
    simulation.step(brain_on);
    if (simulation.status() != EvalStatus::ok)
      return PhaseEnd::stopped;
    if (jury)
      jury->observe(simulation);
    // a frame for the observer, if any (it only reads)
    if (watch && simulation.steps() % watch->stride == 0)
      watch->show(simulation, phase);
    // wall-clock bound, looked at every 256 steps
    if (bounded && (simulation.steps() & 255) == 0 && Clock::now() > deadline)
      return PhaseEnd::stopped;
    // a settle phase with the rest check ends once the body has rested long enough
    if (rest && rest->observe(simulation) && s + 1 >= steps)
      return PhaseEnd::done;
  }
  return rest ? PhaseEnd::unstable : PhaseEnd::done;
}

// the failure outcome for a broken rule
Outcome failure(EvalStatus status, const std::string& message) {
  Outcome outcome;
  outcome.status = status;
  outcome.fitness = kWorstFitness;
  outcome.message = message;
  return outcome;
}

Outcome evaluateBody(const BodyPlan& plan, const TaskSettings& task, const PhysicsSettings& physics,
                     Clock::time_point start, FrameObserver* observer) {
  Outcome outcome;
  outcome.parts = static_cast<int>(plan.parts.size());
  outcome.joints = plan.jointCount();
  outcome.neurons = static_cast<int>(plan.neurons.size());

  // birth: build the world, reject self-penetrating bodies
  Simulation simulation(plan, physics, task.target);
  bool bounded = physics.max_wall_seconds > 0;
  auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(physics.max_wall_seconds));
  auto finish = [&](Outcome& result) -> Outcome& {
    result.steps = simulation.steps();
    if (simulation.status() != EvalStatus::ok) {
      result.status = simulation.status();
      result.message = simulation.message();
      result.fitness = kWorstFitness;
    } else if (bounded && Clock::now() > deadline) {
      result.status = EvalStatus::timeout;
      result.message = "evaluation exceeded physics.max_wall_seconds";
      result.fitness = kWorstFitness;
    }
    return result;
  };

  // the observer sees the body at birth, then every stride steps
  Watch watch_storage;
  Watch* watch = nullptr;
  if (observer) {
    watch = &watch_storage;
    watch->observer = observer;
    watch->stride = std::max<std::uint64_t>(1, observer->frameStride());
    observer->begin(plan, physics);
    watch->show(simulation, EvalPhase::settle);
  }
  if (simulation.status() != EvalStatus::ok)
    return finish(outcome);

  // Chaumont's start-up: settle brain off, trial brain on, settle again (walk);
  // jump: settle only. With the rest check a settle phase lasts until the body is at rest
  const double dt = physics.time_step;
  RestCheck rest_check(task.rest_speed, stepsIn(task.rest_time, dt), dt);
  RestCheck* rest = task.rest_check ? &rest_check : nullptr;
  const std::uint64_t settle_max = stepsIn(task.settle_max_time, dt);
  auto settle = [&](double seconds, EvalPhase phase) {
    PhaseEnd end = runPhase(simulation, stepsIn(seconds, dt), false, nullptr, deadline, bounded,
                            phase, watch, rest, settle_max);
    if (end == PhaseEnd::unstable) {
      std::ostringstream message;
      message << "not at rest within task.settle_max_time = " << task.settle_max_time
              << " s in the " << phaseName(phase) << " phase: no " << task.rest_time
              << " s (task.rest_time) with every part slower than task.rest_speed = "
              << task.rest_speed << " m/s (longest rest " << rest->longestRun() * dt
              << " s; fastest part at the end " << rest->fastest() << " m/s)";
      outcome.status = EvalStatus::unstable;
      outcome.message = message.str();
      outcome.fitness = kWorstFitness;
    }
    return end == PhaseEnd::done;
  };
  bool alive = settle(task.settle_time, EvalPhase::settle);
  if (alive && task.kind == TaskKind::walk) {
    alive = runPhase(simulation, stepsIn(task.trial_time, dt), true, nullptr, deadline, bounded,
                     EvalPhase::trial, watch) == PhaseEnd::done &&
            settle(task.resettle_time, EvalPhase::resettle);
  }
  if (!alive)
    return finish(outcome);

  // measured phase, brain on
  DistanceJury distance;
  HeightJury height;
  Jury* jury = task.kind == TaskKind::walk ? static_cast<Jury*>(&distance) : &height;
  jury->begin(simulation);
  alive = runPhase(simulation, stepsIn(task.evaluation_time, dt), true, jury, deadline, bounded,
                   EvalPhase::measure, watch) == PhaseEnd::done;
  if (!alive)
    return finish(outcome);

  // combine the juries into a fitness
  if (task.kind == TaskKind::walk) {
    double d = distance.value(simulation);
    double length = bodyLength(plan);
    outcome.measures.push_back({"distance", d});
    outcome.measures.push_back({"body_length", length});
    outcome.measures.push_back({"body_lengths", length > 0 ? d / length : 0});
    switch (task.normalisation) {
      case WalkNormalisation::none:
        outcome.fitness = d;
        break;
      case WalkNormalisation::chaumont:
        outcome.fitness = d * chaumontFactor(plan, task.chaumont_k);
        break;
      case WalkNormalisation::volume:
        outcome.fitness = d * volumeFactor(plan);
        break;
    }
  } else {
    outcome.measures.push_back({"height", height.value(simulation)});
    outcome.fitness = height.value(simulation);
  }
  if (!std::isfinite(outcome.fitness) || outcome.fitness < 0)
    outcome.fitness = kWorstFitness;
  return finish(outcome);
}

}  // namespace

const char* taskName(TaskKind kind) {
  switch (kind) {
    case TaskKind::walk:
      return "walk";
    case TaskKind::jump:
      return "jump";
    case TaskKind::synthetic:
      return "synthetic";
  }
  return "unknown";
}

bool isViable(const Genome& genome, const GenomeLimits& limits, const PhysicsSettings& physics,
              std::string* reason) {
  try {
    validateGenome(genome, limits);
    BodyPlan plan = develop(genome, limits);
    if (plan.parts.empty()) {
      if (reason)
        *reason = "no parts";
      return false;
    }
    Simulation simulation(plan, physics);
    if (simulation.status() != EvalStatus::ok) {
      if (reason)
        *reason = std::string(statusName(simulation.status())) + ": " + simulation.message();
      return false;
    }
    return true;
  } catch (const std::exception& e) {
    if (reason)
      *reason = e.what();
    return false;
  }
}

Outcome evaluate(const Genome& genome, const GenomeLimits& limits, const TaskSettings& task,
                 const PhysicsSettings& physics, std::uint64_t eval_seed, FrameObserver* observer) {
  auto start = Clock::now();
  Outcome outcome;
  try {
    if (task.kind == TaskKind::synthetic) {
      outcome = evaluateSynthetic(genome, task, eval_seed);
    } else {
      // a genome that breaks a rule never reaches the physics
      try {
        validateGenome(genome, limits);
      } catch (const GenomeError& e) {
        outcome = failure(EvalStatus::invalid_body, e.what());
      }
      if (outcome.message.empty()) {
        BodyPlan plan = develop(genome, limits);
        outcome = plan.parts.empty() ? failure(EvalStatus::invalid_body, "no parts")
                                     : evaluateBody(plan, task, physics, start, observer);
      }
    }
  } catch (const std::exception& e) {
    outcome = failure(EvalStatus::failed, e.what());
  }
  outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return outcome;
}

}  // namespace cambrian
