#include "options.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian {
namespace {

// one heading and table per section, in definition order, with readable defaults
TEST(OptionsMarkdown, OneTablePerSection) {
  CreatureSettings settings;
  std::string text = optionsMarkdown(creatureOptions(settings));
  auto genome = text.find("### [genome]");
  auto physics = text.find("### [physics]");
  auto task = text.find("### [task]");
  ASSERT_NE(genome, std::string::npos);
  ASSERT_NE(physics, std::string::npos);
  ASSERT_NE(task, std::string::npos);
  EXPECT_LT(genome, physics);
  EXPECT_LT(physics, task);
  EXPECT_NE(text.find("| `genome.min_part_size` | 0.05 | smallest box side, m |"),
            std::string::npos);
  EXPECT_NE(text.find("| `physics.substeps` | 2 |"), std::string::npos);
  EXPECT_NE(text.find("| `physics.self_collision` | false |"), std::string::npos);
}

// a pipe inside a description does not split the table cell
TEST(OptionsMarkdown, PipesAreEscaped) {
  CreatureSettings settings;
  std::string text = optionsMarkdown(creatureOptions(settings));
  auto row = text.find("| `task.name` |");
  ASSERT_NE(row, std::string::npos);
  std::string line = text.substr(row, text.find('\n', row) - row);
  EXPECT_NE(line.find("walk \\| jump"), std::string::npos) << line;
}

// the documented settings parse back: a changed default shows in the table
TEST(OptionsMarkdown, FollowsTheBoundDefaults) {
  CreatureSettings settings;
  settings.physics.motor_speed = 12.5;
  std::string text = optionsMarkdown(creatureOptions(settings));
  EXPECT_NE(text.find("| `physics.motor_speed` | 12.5 |"), std::string::npos);
}

}  // namespace
}  // namespace cambrian
