// cambrian: the registered tasks — a declaration and one list entry each — and the defaults of
// the Task interface.
#include "cambrian/error.hpp"

#include "tasks/task.hpp"

namespace cambrian {

const Task& walkTask();           // tasks/walk.cpp
const Task& jumpTask();           // tasks/jump.cpp
const Task& syntheticTask();      // tasks/synthetic.cpp
const Task& swimTask();           // tasks/swim.cpp
const Task& followLightTask();    // tasks/follow_light.cpp
const Task& catapultTask();       // tasks/catapult.cpp
const Task& juriesTask();         // tasks/juries_task.cpp
const Task& flagTask();           // tasks/flag.cpp
const Task& iterativeMoveTask();  // tasks/iterative_move.cpp
const Task& combinationTask();    // tasks/combination.cpp

const std::vector<const Task*>& tasks() {
  static const std::vector<const Task*> registered = {
      &walkTask(),     &jumpTask(),   &syntheticTask(), &swimTask(),          &followLightTask(),
      &catapultTask(), &juriesTask(), &flagTask(),      &iterativeMoveTask(), &combinationTask(),
  };
  return registered;
}

std::vector<std::string> taskNames() {
  std::vector<std::string> names;
  for (const Task* task : tasks())
    names.push_back(task->name());
  return names;
}

void Task::run(Episode&) const {
  throw Error(ExitCode::failure, "task " + name() + " has no body to run");
}

Outcome Task::evaluateGenome(const Genotype&, const Encoding&, std::uint64_t) const {
  throw Error(ExitCode::failure, "task " + name() + " evaluates bodies, not bare genomes");
}

}  // namespace cambrian
