// Tests of the settings reference and help: one table per section in declaration order, readable
// defaults, escaped pipes, run-only keys marked; command lines and files into a schema.
#include "options.hpp"

#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "physics/physics_settings.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cambrian {
namespace {

// the creature settings' schema
struct Creature {
  CreatureSettings settings;
  SettingsSchema schema;
  Creature() { settings.declareSettings(schema); }
};

// one heading and table per section, in declaration order, with readable defaults
TEST(OptionsMarkdown, OneTablePerSection) {
  Creature c;
  std::string text = optionsMarkdown(c.schema);
  auto genome = text.find("### [genome]");
  auto physics = text.find("### [physics]");
  auto task = text.find("### [task]");
  auto environment = text.find("### [environment]");
  ASSERT_NE(genome, std::string::npos);
  ASSERT_NE(physics, std::string::npos);
  ASSERT_NE(task, std::string::npos);
  ASSERT_NE(environment, std::string::npos);
  EXPECT_LT(genome, physics);
  EXPECT_LT(physics, task);
  EXPECT_LT(task, environment);
  EXPECT_NE(text.find("| `genome.min_part_size` | 0.05 | smallest box side, m |"),
            std::string::npos);
  EXPECT_NE(text.find("| `physics.time_step` | 0.00416666666667 |"), std::string::npos);
  EXPECT_NE(text.find("| `physics.substeps` | 2 |"), std::string::npos);
  EXPECT_NE(text.find("| `physics.self_collision` | true |"), std::string::npos);
}

// a pipe inside a description does not split the table cell
TEST(OptionsMarkdown, PipesAreEscaped) {
  Creature c;
  std::string text = optionsMarkdown(c.schema);
  auto row = text.find("| `task.name` |");
  ASSERT_NE(row, std::string::npos);
  std::string line = text.substr(row, text.find('\n', row) - row);
  EXPECT_NE(line.find("walk (distance walked while measured) \\| jump"), std::string::npos) << line;
}

// the documented defaults are those at declaration: a changed default shows in the table
TEST(OptionsMarkdown, FollowsTheBoundDefaults) {
  CreatureSettings settings;
  settings.physics().motor_speed = 12.5;
  SettingsSchema schema;
  settings.declareSettings(schema);
  std::string text = optionsMarkdown(schema);
  EXPECT_NE(text.find("| `physics.motor_speed` | 12.5 |"), std::string::npos);
}

// run-only keys are marked in the reference
TEST(OptionsMarkdown, RunOnlyKeysAreMarked) {
  int value = 0;
  SettingsSchema schema;
  schema.add("run.every", value, "how often").runOnly();
  EXPECT_NE(optionsMarkdown(schema).find("| `run.every` | 0 | how often (run-only) |"),
            std::string::npos);
}

// command line and file: the command line wins, origins are recorded, errors name the source
TEST(ParseOptions, ATokenHoldingAParserPlaceholderIsRefusedNotLoopedOn) {
  // Boost's message would replace %original_token% by the token, which holds it again, forever
  // (found by fuzzing the command line)
  po::options_description cli;
  cli.add_options()("config", po::value<std::string>());
  for (const char* token : {"--foo%original_token%", "-a%original_token%", "--x%value%%option%"}) {
    Creature c;
    const char* argv[] = {"x", token};
    try {
      parseOptions(2, argv, cli, c.schema, nullptr, "config");
      ADD_FAILURE() << token << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::usage);
      EXPECT_NE(std::string(e.what()).find(std::string("'") + token + "' is not an option"),
                std::string::npos)
          << e.what();
    }
  }
}

// a bare word where the command takes none is refused, naming it and the way to give a file
// (Boost would drop it: `cambrian evolve walk.ini` ran the defaults)
TEST(ParseOptions, ABareWordIsRefusedWhereNoneIsTaken) {
  po::options_description cli;
  cli.add_options()("config", po::value<std::string>());
  Creature c;
  const char* argv[] = {"x", "walk.ini", "--physics.gravity", "3"};
  try {
    parseOptions(4, argv, cli, c.schema, nullptr, "config");
    ADD_FAILURE() << "walk.ini was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::usage);
    EXPECT_NE(std::string(e.what()).find("'walk.ini' is not an option"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("--config FILE"), std::string::npos) << e.what();
  }
}

TEST(ParseOptions, CommandLineWinsOverTheFileAndErrorsNameTheirSource) {
  std::string path = testing::TempDir() + "/cambrian_options_test.ini";
  std::ofstream(path) << "[physics]\ntime_step = 0.01\ngravity = 3\n[task]\nname = jump\n";
  Creature c;
  po::options_description cli;
  cli.add_options()("config", po::value<std::string>());
  const char* argv[] = {"x", "--config", path.c_str(), "--physics.gravity", "5"};
  OptionOrigins origins;
  parseOptions(5, argv, cli, c.schema, nullptr, "config", &origins);
  EXPECT_EQ(c.settings.physics().time_step, 0.01);
  EXPECT_EQ(c.settings.physics().gravity, 5.0);
  EXPECT_TRUE(origins.command_line.count("physics.gravity"));
  EXPECT_TRUE(origins.config_file.count("physics.time_step"));
  EXPECT_EQ(locateSettingError("physics.time_step = 0.01: x", origins),
            path + ": physics.time_step = 0.01: x");
  EXPECT_EQ(locateSettingError("physics.gravity = 5: x", origins),
            "command line: --physics.gravity = 5: x");

  // a value of the wrong type: usage on the command line, config in the file
  Creature d;
  const char* bad[] = {"x", "--physics.substeps", "many"};
  try {
    parseOptions(3, bad, cli, d.schema, nullptr, "config");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::usage);
    EXPECT_NE(std::string(e.what()).find("physics.substeps = many"), std::string::npos);
  }
  std::ofstream(path) << "[physics]\nsubsteps = many\n";
  const char* from_file[] = {"x", "--config", path.c_str()};
  Creature e;
  try {
    parseOptions(3, from_file, cli, e.schema, nullptr, "config");
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find(path + ": line 2: physics.substeps = many"),
              std::string::npos)
        << error.what();
  }
  // an unknown key in the file, and a key given twice
  std::ofstream(path) << "[physics]\nwarp = 9\n";
  Creature f;
  EXPECT_THROW(parseOptions(3, from_file, cli, f.schema, nullptr, "config"), ConfigError);
  std::ofstream(path) << "[physics]\ngravity = 1\ngravity = 2\n";
  Creature g;
  EXPECT_THROW(parseOptions(3, from_file, cli, g.schema, nullptr, "config"), ConfigError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace cambrian
