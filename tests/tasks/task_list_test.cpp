// Tests of the task registry: distinct names, every task declares measures and reports only
// those it declares (for a walker and for a failure), settings keys do not collide.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "core/settings.hpp"
#include "tasks/task.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace cambrian {
namespace {

TEST(Tasks, NamesAreDistinctAndEachDeclaresMeasures) {
  std::set<std::string> names;
  for (const Task* task : tasks()) {
    names.insert(task->name());
    EXPECT_FALSE(task->measures().empty()) << task->name();
    EXPECT_FALSE(task->summary().empty()) << task->name();
    std::set<std::string> measures;
    for (const MeasureInfo& measure : task->measures())
      measures.insert(measure.name);
    EXPECT_EQ(measures.size(), task->measures().size()) << task->name();
  }
  EXPECT_EQ(names.size(), tasks().size());
  EXPECT_EQ(taskNames(), (std::vector<std::string>{"walk", "jump", "synthetic", "swim",
                                                   "follow_light", "catapult", "juries", "flag",
                                                   "iterative_move", "combination"}));
}

// every task's settings fit in one schema: no key is declared by two tasks
TEST(Tasks, SettingsDoNotCollide) {
  std::vector<std::unique_ptr<Task>> copies;
  SettingsSchema schema;
  for (const Task* task : tasks()) {
    copies.push_back(task->clone());
    EXPECT_NO_THROW(copies.back()->declareSettings(schema)) << task->name();
  }
  EXPECT_NO_THROW(schema.check());
}

// what a task reports is what it declares, for every task, on a walker and on random creatures
TEST(Tasks, OutcomesCarryOnlyDeclaredMeasures) {
  Genotype walker =
      readGenomeFile(std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/walker4.genome");
  for (const std::string& name : taskNames()) {
    CreatureSettings settings;
    settings.set("task.name", name);
    settings.set("task.evaluation_time", "0.5");
    settings.set("task.synthetic_cost_us", "10");
    std::vector<MeasureInfo> declared = settings.task().measures();
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      Genotype genome = seed == 0 ? walker : settings.encoding().random(seed, 0, 0);
      Outcome outcome = evaluate(genome, settings, seed);
      for (const Measure& measure : outcome.measures) {
        EXPECT_TRUE(std::any_of(declared.begin(), declared.end(),
                                [&](const MeasureInfo& m) { return m.name == measure.name; }))
            << name << " reported the undeclared measure " << measure.name;
      }
      if (outcome.status == EvalStatus::ok) {
        EXPECT_EQ(outcome.measures.size(), declared.size()) << name;
      }
    }
  }
}

// a task with bodies refuses to evaluate bare genomes and the other way round
TEST(Tasks, WrongKindOfEvaluationIsAnError) {
  const Task& walk = *tasks()[0];
  EXPECT_THROW(walk.evaluateGenome(Genotype(), *encodings()[0], 0), Error);
}

}  // namespace
}  // namespace cambrian
