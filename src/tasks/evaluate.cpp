// cambrian: evaluating one creature — validate, develop, build the world, run the task.
#include "cambrian/evaluate.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "physics/physics_settings.hpp"
#include "physics/simulation.hpp"
#include "tasks/episode.hpp"
#include "tasks/task.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <utility>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// the failure outcome for a broken rule
Outcome failure(EvalStatus status, const std::string& message) {
  Outcome outcome;
  outcome.status = status;
  outcome.fitness = kWorstFitness;
  outcome.message = message;
  return outcome;
}

// a developed creature through its task, in `physics`
Outcome evaluateBody(const Creature& creature, const CreatureSettings& settings,
                     const PhysicsSettings& physics, Clock::time_point start,
                     FrameObserver* observer) {
  const Task& task = settings.task();
  Environment environment = settings.environment();
  task.prepare(environment);
  Episode episode(creature, environment, physics, settings.episode(), start, observer);
  if (episode.born()) {
    task.run(episode);
    Outcome& outcome = episode.outcome();
    if (!std::isfinite(outcome.fitness) || outcome.fitness < 0)
      outcome.fitness = kWorstFitness;
  }
  return episode.finish();
}

// task.check_substeps: the creature (developed afresh) again at `substeps`; the second
// outcome, measures and all, replaces the first where it failed or scored lower
void checkAtSubsteps(const Creature& creature, const CreatureSettings& settings, int substeps,
                     Clock::time_point start, Outcome& outcome) {
  PhysicsSettings physics = settings.physics();
  physics.substeps = substeps;
  Outcome check = evaluateBody(creature, settings, physics, start, nullptr);
  check.steps += outcome.steps;
  if (check.status != EvalStatus::ok || check.fitness < outcome.fitness) {
    check.message = "at task.check_substeps = " + std::to_string(substeps) +
                    (check.message.empty() ? "" : ": " + check.message);
    outcome = std::move(check);
  } else {
    outcome.steps = check.steps;
  }
}

}  // namespace

std::uint64_t evaluationSeed(std::uint64_t run_seed, std::uint64_t id) {
  Rng rng(run_seed, RngPurpose::evaluation, 0, id);
  return rng.nextU64();
}

bool isViable(const Genotype& genome, const CreatureSettings& settings, std::string* reason) {
  try {
    const Encoding& encoding = settings.encoding();
    encoding.validate(genome);
    Creature creature = encoding.develop(genome);
    if (creature.body.parts.empty()) {
      if (reason)
        *reason = "no parts";
      return false;
    }
    Environment environment = settings.environment();
    settings.task().prepare(environment);
    Simulation simulation(creature.body, creature.controller.get(), environment,
                          settings.physics());
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

Outcome evaluate(const Genotype& genome, const CreatureSettings& settings, std::uint64_t eval_seed,
                 FrameObserver* observer) {
  auto start = Clock::now();
  Outcome outcome;
  try {
    const Task& task = settings.task();
    const Encoding& encoding = settings.encoding();
    if (!task.needsBody()) {
      outcome = task.evaluateGenome(genome, encoding, eval_seed);
    } else {
      // a genome that breaks a rule never reaches the physics
      bool valid = true;
      try {
        encoding.validate(genome);
      } catch (const GenomeError& e) {
        outcome = failure(EvalStatus::invalid_body, e.what());
        valid = false;
      }
      if (valid) {
        Creature creature = encoding.develop(genome);
        const std::size_t parts = creature.body.parts.size();
        const auto least = static_cast<std::size_t>(settings.episode().min_parts);
        if (parts == 0) {
          outcome = failure(EvalStatus::invalid_body, "no parts");
        } else if (parts < least) {
          outcome = failure(EvalStatus::invalid_body,
                            std::to_string(parts) + " part" + (parts == 1 ? "" : "s") +
                                ", fewer than task.min_parts = " + std::to_string(least));
          outcome.parts = static_cast<int>(parts);
        } else {
          outcome = evaluateBody(creature, settings, settings.physics(), start, observer);
          const int check = settings.episode().check_substeps;
          if (check > 0 && outcome.status == EvalStatus::ok)
            checkAtSubsteps(encoding.develop(genome), settings, check, start, outcome);
        }
      }
    }
  } catch (const std::exception& e) {
    outcome = failure(EvalStatus::failed, e.what());
  }
  outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return outcome;
}

}  // namespace cambrian
