#include "cambrian/evaluate.hpp"

#include "cambrian/error.hpp"

#include "physics/simulation.hpp"
#include "tasks/juries.hpp"
#include "tasks/synthetic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
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

// runs `steps` steps; false when a rule broke or the wall-clock bound passed
bool runPhase(Simulation& simulation, std::uint64_t steps, bool brain_on, Jury* jury,
              Clock::time_point deadline, bool bounded, EvalPhase phase, Watch* watch) {
  for (std::uint64_t s = 0; s < steps; ++s) {
    simulation.step(brain_on);
    if (simulation.status() != EvalStatus::ok)
      return false;
    if (jury)
      jury->observe(simulation);
    // a frame for the observer, if any (it only reads)
    if (watch && simulation.steps() % watch->stride == 0)
      watch->show(simulation, phase);
    // wall-clock bound, looked at every 256 steps
    if (bounded && (simulation.steps() & 255) == 0 && Clock::now() > deadline)
      return false;
  }
  return true;
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
  // jump: settle only
  const double dt = physics.time_step;
  bool alive = runPhase(simulation, stepsIn(task.settle_time, dt), false, nullptr, deadline,
                        bounded, EvalPhase::settle, watch);
  if (alive && task.kind == TaskKind::walk) {
    alive = runPhase(simulation, stepsIn(task.trial_time, dt), true, nullptr, deadline, bounded,
                     EvalPhase::trial, watch) &&
            runPhase(simulation, stepsIn(task.resettle_time, dt), false, nullptr, deadline, bounded,
                     EvalPhase::resettle, watch);
  }
  if (!alive)
    return finish(outcome);

  // measured phase, brain on
  DistanceJury distance;
  HeightJury height;
  Jury* jury = task.kind == TaskKind::walk ? static_cast<Jury*>(&distance) : &height;
  jury->begin(simulation);
  alive = runPhase(simulation, stepsIn(task.evaluation_time, dt), true, jury, deadline, bounded,
                   EvalPhase::measure, watch);
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
