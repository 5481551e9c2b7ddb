// cambrian: tasks as plug-ins. A task is one file: a class that names itself, declares its
// settings and the measures (juries) it reports, runs its phases on an Episode and turns the
// juries into a fitness; one line in task_list.cpp registers it. docs/design.md says how.
#pragma once

#include "cambrian/encoding.hpp"
#include "cambrian/environment.hpp"
#include "cambrian/outcome.hpp"

#include <memory>
#include <string>
#include <vector>

namespace cambrian {

class Episode;
class SettingsSchema;

/// What is asked of a creature and how it is measured.
class Task {
 public:
  virtual ~Task() = default;
  /// A copy with the same settings.
  virtual std::unique_ptr<Task> clone() const = 0;
  /// The name users give (task.name = NAME).
  virtual std::string name() const = 0;
  /// One line for --help.
  virtual std::string summary() const = 0;
  /// Declares its own settings ([task] keys), bound to this instance.
  virtual void declareSettings(SettingsSchema&) {}
  /// Every measure its outcomes may carry, in the order histories store them.
  virtual std::vector<MeasureInfo> measures() const = 0;

  /// False for a task that evaluates genomes without bodies (synthetic).
  virtual bool needsBody() const { return true; }
  /// True when an outcome is a pure function of the genome and the settings, so that the same
  /// genome always gives the same bits and a copy may take its original's outcome
  /// (run.reuse_outcomes): every task with bodies (an episode draws no random numbers); false
  /// for a task that uses the evaluation seed.
  virtual bool repeatable() const { return needsBody(); }
  /// Adds what the task needs to the environment (a projectile, a target) before birth.
  virtual void prepare(Environment&) const {}
  /// Runs the task's phases on a born creature and sets the outcome's measures and fitness
  /// (episode.outcome()); returns early when a phase ends the evaluation.
  virtual void run(Episode& episode) const;
  /// A task without bodies: the outcome of `genome` (of `encoding`), a pure function of both,
  /// the task's settings and `eval_seed`.
  virtual Outcome evaluateGenome(const Genotype& genome, const Encoding& encoding,
                                 std::uint64_t eval_seed) const;
};

/// Every registered task (prototypes, default settings), in registration order.
const std::vector<const Task*>& tasks();
/// The names of every registered task.
std::vector<std::string> taskNames();

}  // namespace cambrian
