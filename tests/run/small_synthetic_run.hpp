// The run driver's tests' one small run: synthetic creatures of 20 us, evaluated in process.
#pragma once

#include "run/evolution_run.hpp"
#include "tasks/task.hpp"

#include <cstdint>
#include <ostream>
#include <string>

namespace cambrian {

/// A synthetic run of `population` x `generations` in `mode` writing to `dir` (`fresh`: ignoring
/// a checkpoint left there); `run` may bring its own settings text, else one naming the mode,
/// sizes, directory and seed is made. evolution.generations and run.out are run-only (and
/// run.arrival_order for a steady state).
inline RunResult smallSyntheticRun(EvolutionMode mode, const std::string& dir, std::ostream& out,
                                   bool fresh, int population, int generations, RunSettings run,
                                   std::uint64_t seed) {
  EvolutionSettings settings;
  settings.mode = mode;
  settings.population = population;
  settings.generations = generations;
  settings.seed = seed;
  WorkerSettings worker;
  worker.creature.set("task.name", "synthetic");
  worker.creature.set("task.synthetic_cost_us", "20");
  InProcessEvaluator evaluator(worker);
  run.out_dir = dir;
  run.fresh = fresh;
  run.measures = worker.creature.task().measures();
  run.run_only = {"evolution.generations", "run.out"};
  if (mode == EvolutionMode::steady_state)
    run.run_only.insert("run.arrival_order");
  if (run.config_text.empty())
    run.config_text = std::string("[evolution]\n") +
                      (mode == EvolutionMode::steady_state ? "mode = steady_state\n" : "") +
                      "generations = " + std::to_string(generations) +
                      "\npopulation = " + std::to_string(population) + "\n\n[run]\nout = " + dir +
                      "\nseed = " + std::to_string(seed) + "\n";
  return runEvolution(settings, worker.creature.encoding(), {}, evaluator, run, out);
}

}  // namespace cambrian
