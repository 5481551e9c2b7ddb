// Tests of the creature settings: the plug-ins chosen by name, settings set and read by key,
// deep copies, the keys' text, the range checks.
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "core/settings.hpp"
#include "physics/physics_settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/task.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian {
namespace {

TEST(CreatureSettings, DefaultsChooseTheFirstOfEach) {
  CreatureSettings settings;
  EXPECT_EQ(settings.encoding().name(), "directed_graph");
  EXPECT_EQ(settings.task().name(), "walk");
  EXPECT_EQ(settings.physics().world, "featherstone");
  EXPECT_EQ(settings.environment().ground.friction, 1.0);
  EXPECT_NO_THROW(settings.check());
}

TEST(CreatureSettings, ChoicesAndValuesByKey) {
  CreatureSettings settings;
  settings.set("task.name", "jump");
  settings.set("physics.ground_friction", "0.5");
  settings.set("task.evaluation_time", "2");
  EXPECT_EQ(settings.task().name(), "jump");
  EXPECT_EQ(settings.value("physics.ground_friction"), "0.5");
  EXPECT_EQ(settings.environment().ground.friction, 0.5);
  EXPECT_EQ(settings.episode().evaluation_time, 2.0);
  EXPECT_THROW(settings.set("task.no_such_key", "1"), ConfigError);
  EXPECT_THROW(settings.set("task.evaluation_time", "soon"), ConfigError);
  EXPECT_THROW(settings.value("task.no_such_key"), ConfigError);
  settings.set("task.name", "fly");
  EXPECT_THROW(settings.check(), ConfigError);
  EXPECT_THROW(settings.task(), ConfigError);
}

TEST(CreatureSettings, CopiesAreDeep) {
  CreatureSettings a;
  a.set("task.normalisation", "chaumont");
  CreatureSettings b = a;
  b.set("task.normalisation", "volume");
  b.set("genome.max_parts", "7");
  EXPECT_EQ(a.value("task.normalisation"), "chaumont");
  EXPECT_EQ(b.value("task.normalisation"), "volume");
  EXPECT_EQ(a.value("genome.max_parts"), "30");
  a = b;
  EXPECT_EQ(a.value("genome.max_parts"), "7");
  b.set("genome.max_parts", "8");
  EXPECT_EQ(a.value("genome.max_parts"), "7");
}

TEST(CreatureSettings, IniTextHoldsEveryCreatureSection) {
  CreatureSettings settings;
  std::string text = settings.iniText();
  for (const char* line : {"[environment]\nhill_alpha = 3.3\n", "\nname = plane\nnet_gravity = 0\n",
                           "[genome]\ncatapult = false\nchua_limit = 2\n",
                           "\ncontact_sensors = part\nencoding = directed_graph\n",
                           "world = featherstone\n", "name = walk\n", "max_weight = 5\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line;
  // another schema bound to the same settings sets them
  SettingsSchema schema;
  settings.declareSettings(schema);
  schema.set("physics.gravity", "3.5");
  EXPECT_EQ(settings.physics().gravity, 3.5);
}

TEST(CreatureSettings, RangesAreChecked) {
  for (auto [key, value] :
       std::vector<std::pair<const char*, const char*>>{{"physics.time_step", "0"},
                                                        {"physics.substeps", "0"},
                                                        {"task.evaluation_time", "-1"},
                                                        {"genome.max_parts", "0"},
                                                        {"physics.world", "mujoco"},
                                                        {"environment.name", "moon"},
                                                        {"genome.encoding", "lsystem"},
                                                        {"task.synthetic_cv", "9"}}) {
    CreatureSettings settings;
    settings.set(key, value);
    try {
      settings.check();
      FAIL() << key << " = " << value << " passed";
    } catch (const ConfigError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string(key) + " = " + value + ": ", 0), 0u)
          << e.what();
    }
  }
}

// the rest rule's room: settle_max_time must hold the settle phases and the rest
TEST(CreatureSettings, RestRuleNeedsRoom) {
  CreatureSettings settings;
  settings.set("task.rest_check", "false");
  settings.set("task.settle_max_time", "0.2");
  EXPECT_NO_THROW(settings.check());
  settings.set("task.rest_check", "true");
  EXPECT_THROW(settings.check(), ConfigError);
}

TEST(EvaluationSeed, PureFunctionOfRunSeedAndId) {
  EXPECT_EQ(evaluationSeed(1, 5), evaluationSeed(1, 5));
  EXPECT_NE(evaluationSeed(1, 5), evaluationSeed(1, 6));
  EXPECT_NE(evaluationSeed(1, 5), evaluationSeed(2, 5));
}

}  // namespace
}  // namespace cambrian
