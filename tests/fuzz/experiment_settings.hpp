// Fuzz targets: every key `cambrian evolve` reads from its command line and experiment file,
// declared as src/app/evolve_command.cpp declares them (creature, evolution, run, dispatch and
// the workers' testing keys).
#pragma once

#include "cambrian/evaluate.hpp"

#include "core/settings.hpp"
#include "evolution/evolution_settings.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/worker.hpp"
#include "run/run_settings.hpp"

namespace cambrian::fuzz {

/// The settings and their schema, bound together.
struct ExperimentSettings {
  WorkerSettings worker;
  EvolutionSettings evolution;
  RunSettings run;
  DispatchSettings dispatch;
  SettingsSchema schema;

  ExperimentSettings() {
    worker.creature.declareSettings(schema);
    evolution.declareSettings(schema);
    run.declareSettings(schema);
    dispatch.declareSettings(schema);
    worker.declareTestingSettings(schema);
  }
};

}  // namespace cambrian::fuzz
