// cambrian: the settings shared by every subcommand, as Boost.Program_options definitions.
// Every key works in an INI file ("[physics]\ntime_step = 0.004") and on the command line
// ("--physics.time_step 0.004"); the command line wins.
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"

#include <boost/program_options.hpp>

#include <string>
#include <vector>

namespace cambrian {

namespace po = boost::program_options;

/// Everything that decides how one creature is built and evaluated.
struct CreatureSettings {
  GenomeLimits limits;
  PhysicsSettings physics;
  TaskSettings task;
  std::string task_name = "walk";
  std::string normalisation_name = "none";
  std::string actuation_name = "motor";
  std::string synthetic_distribution_name = "uniform";
};

/// Adds the [genome], [physics] and [task] keys, bound to `settings`, with defaults and units.
po::options_description creatureOptions(CreatureSettings& settings);

/// Turns the string-valued keys into enums and checks every range; throws ConfigError naming
/// the key and the value. Call after po::notify().
void finishCreatureSettings(CreatureSettings& settings);

/// Parses the command line and then, when `config_path` is non-empty, the INI file (command line
/// wins). Unknown keys are errors: a ConfigError naming the file and key, or a usage Error.
/// Calls po::notify. `positional` may be null.
po::variables_map parseOptions(int argc, const char* const* argv,
                               const po::options_description& cli_only,
                               const po::options_description& settings,
                               const po::positional_options_description* positional,
                               const std::string& config_key = "config");

/// The keys of an options description as Markdown: one "### [section]" heading and table
/// (key, default, meaning) per key prefix, in definition order (docs/user-guide.md is
/// generated so).
std::string optionsMarkdown(const po::options_description& desc);

}  // namespace cambrian
