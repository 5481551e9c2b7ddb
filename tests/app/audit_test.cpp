// tests of `cambrian audit` through the executable: random bodies pass, the creepers kept as
// fixtures fail under Bullet's default contacts and pass under the defaults, bad arguments
#include "cambrian/error.hpp"

#include "app/cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace cambrian {
namespace {

using test::code;
using test::lineStartingWith;
using test::runCambrian;

// the fixtures: bodies that crept at rest before friction anchors
std::string fixture(const std::string& name) {
  return std::string(CAMBRIAN_SOURCE_DIR) + "/tests/physics/data/" + name + ".genome";
}
const char* kEarlierContacts = " --physics.friction_anchors false --physics.contact_slop 0";

// lines that start with `key`
int countLines(const std::string& output, const std::string& key) {
  std::istringstream in(output);
  int count = 0;
  for (std::string line; std::getline(in, line);)
    count += line.rfind(key, 0) == 0;
  return count;
}

// a hundred random bodies: every one at rest stays at rest, no passive energy from nothing
TEST(AuditCommand, RandomBodiesPass) {
  auto result = runCambrian("audit --random 100 --seed 5 --driven 2");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(lineStartingWith(result.output, "bodies").find("100 random"), std::string::npos);
  EXPECT_EQ(lineStartingWith(result.output, "audit"), "audit          every check holds");
  EXPECT_NE(lineStartingWith(result.output, "at rest").find("within 10 s"), std::string::npos);
  EXPECT_EQ(countLines(result.output, "BROKEN"), 0);
}

// the creepers crept under Bullet's default contacts (friction without anchors, no slop) and
// keep still under the defaults; the audit names each one
TEST(AuditCommand, CreepersAreCaughtAndGone) {
  std::string bodies = " --random 0 --driven 0 --genome " + fixture("creeper_3_parts") +
                       " --genome " + fixture("creeper_5_parts");
  auto earlier = runCambrian("audit" + bodies + kEarlierContacts);
  EXPECT_EQ(earlier.exit_code, code(ExitCode::audit_failed)) << earlier.output;
  EXPECT_EQ(countLines(earlier.output, "BROKEN"), 2) << earlier.output;
  EXPECT_NE(earlier.output.find("creeper_3_parts.genome: crept"), std::string::npos);
  EXPECT_NE(lineStartingWith(earlier.output, "audit").find("2 bodies broke a check"),
            std::string::npos);
  auto now = runCambrian("audit" + bodies);
  EXPECT_EQ(now.exit_code, 0) << now.output;
  EXPECT_EQ(countLines(now.output, "BROKEN"), 0) << now.output;
}

// the body a zero-strength evolution selected under explicit joint damping creeps with it (and
// with the free middle axis of its spherical joint and Bullet's joint speed clamp, as then:
// physics.solve_every_dof = false, physics.joint_speed_clamp = 100), and keeps still with the
// damping solved implicitly (the default)
TEST(AuditCommand, TheDampingCreeperKeepsStillUnderImplicitDamping) {
  std::string body = " --random 0 --driven 0 --genome " + fixture("damping_creeper");
  auto explicit_damping = runCambrian("audit" + body +
                                      " --physics.implicit_damping false"
                                      " --physics.solve_every_dof false"
                                      " --physics.joint_speed_clamp 100");
  EXPECT_EQ(explicit_damping.exit_code, code(ExitCode::audit_failed)) << explicit_damping.output;
  EXPECT_NE(explicit_damping.output.find("damping_creeper.genome: crept"), std::string::npos)
      << explicit_damping.output;
  auto now = runCambrian("audit" + body);
  EXPECT_EQ(now.exit_code, 0) << now.output;
  EXPECT_EQ(countLines(now.output, "BROKEN"), 0) << now.output;
}

// the body a zero-strength evolution selected before the fix keeps still
TEST(AuditCommand, TheZeroStrengthWalkerKeepsStill) {
  auto result = runCambrian("audit --random 0 --driven 0 --physics.strength_per_area 0 --genome " +
                            fixture("zero_strength_walker"));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(lineStartingWith(result.output, "at rest").find("1 within"), std::string::npos)
      << result.output;
}

// the best genomes of a history, and one row per body in the table
TEST(AuditCommand, HistoryGenomesAndTable) {
  std::string dir = testing::TempDir() + "/cambrian_audit_test_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  auto run = runCambrian(
      "evolve --evolution.population 6 --evolution.generations 1 --task.evaluation_time 1 "
      "--seed 3 --quiet --out " +
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  auto result =
      runCambrian("audit --history " + dir + "/history.h5 --top 3 --random 2 --driven 1 " +
                  "--measure 2 --tsv " + dir + "/audit.tsv");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(lineStartingWith(result.output, "bodies").find("5 (0 genome files, 3 from histories"),
            std::string::npos)
      << result.output;
  std::ifstream tsv(dir + "/audit.tsv");
  std::string header, line;
  std::getline(tsv, header);
  EXPECT_EQ(header.rfind("body\tparts\trest_status\tat_rest", 0), 0u) << header;
  int rows = 0;
  while (std::getline(tsv, line))
    ++rows;
  EXPECT_EQ(rows, 5);
  std::filesystem::remove_all(dir);
}

// bad arguments: usage (2), a missing genome (4), a table that cannot be written (5)
TEST(AuditCommand, BadArguments) {
  auto zero = runCambrian("audit --random 1 --rest-speed 0");
  EXPECT_EQ(zero.exit_code, code(ExitCode::usage)) << zero.output;
  EXPECT_NE(zero.output.find("--rest-speed"), std::string::npos) << zero.output;
  auto seed = runCambrian("audit --seed -3");
  EXPECT_EQ(seed.exit_code, code(ExitCode::usage)) << seed.output;
  auto missing = runCambrian("audit --random 0 --genome /nonexistent/creature.genome");
  EXPECT_EQ(missing.exit_code, code(ExitCode::input_file)) << missing.output;
  EXPECT_NE(missing.output.find("/nonexistent/creature.genome"), std::string::npos);
  auto table = runCambrian("audit --random 1 --tsv /nonexistent/dir/audit.tsv");
  EXPECT_EQ(table.exit_code, code(ExitCode::output_file)) << table.output;
  auto setting = runCambrian("audit --random 1 --physics.contact_slop -1");
  EXPECT_EQ(setting.exit_code, code(ExitCode::config)) << setting.output;
  EXPECT_NE(setting.output.find("physics.contact_slop"), std::string::npos);
}

}  // namespace
}  // namespace cambrian
