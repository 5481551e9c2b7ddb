// cambrian: the settings shared by every subcommand, as Boost.Program_options definitions.
// Every key works in an INI file ("[physics]\ntime_step = 0.004") and on the command line
// ("--physics.time_step 0.004"); the command line wins.
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"

#include <boost/program_options.hpp>

#include <cstdint>
#include <iosfwd>
#include <set>
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

/// A seed option's value: a decimal integer in 0..2^64-1. Unlike a plain std::uint64_t option,
/// "-3" is refused instead of wrapping around to 18446744073709551613.
struct SeedValue {
  std::uint64_t value = 0;
};
std::ostream& operator<<(std::ostream& out, const SeedValue& seed);
/// Boost.Program_options' hook for SeedValue: digits only, in range, or invalid_option_value.
void validate(boost::any& value, const std::vector<std::string>& tokens, SeedValue*, int);

/// Where the settings of one parse came from: the keys given on the command line (the rest
/// came from the config file, when one was read, or are defaults).
struct OptionOrigins {
  std::set<std::string> command_line;
  std::set<std::string> config_file;
  std::string config_path;
  /// `key` now has a value from the command line (a short form such as --seed that sets it).
  void setOnCommandLine(const std::string& key) {
    command_line.insert(key);
    config_file.erase(key);
  }
};

/// A ConfigError message about a setting ("key = value: rule"), prefixed with where the value
/// came from: "FILE: " for a value read from the config file, "command line: " for one given
/// as an option, nothing for a default or a message that names no known key.
std::string locateSettingError(const std::string& message, const OptionOrigins& origins);

/// Adds the [genome], [physics] and [task] keys, bound to `settings`, with defaults and units.
po::options_description creatureOptions(CreatureSettings& settings);

/// Turns the string-valued keys into enums and checks every range; throws ConfigError naming
/// the key and the value. Call after po::notify().
void finishCreatureSettings(CreatureSettings& settings);
/// The same, the error naming also where the bad value came from (locateSettingError).
void finishCreatureSettings(CreatureSettings& settings, const OptionOrigins& origins);

/// Parses the command line and then, when `config_path` is non-empty, the INI file (command line
/// wins). Unknown keys are errors: a ConfigError naming the file and key, or a usage Error.
/// Calls po::notify. `positional` may be null; `origins`, when given, receives where each
/// setting came from (for locateSettingError).
po::variables_map parseOptions(int argc, const char* const* argv,
                               const po::options_description& cli_only,
                               const po::options_description& settings,
                               const po::positional_options_description* positional,
                               const std::string& config_key = "config",
                               OptionOrigins* origins = nullptr);

/// An option's default as a person writes it: "0.050000000000000003" becomes "0.05", a flag's
/// 0/1 becomes false/true (what --help and --help-markdown print).
std::string readableDefault(const po::option_description& option);

/// An options description as --help prints it, with readable defaults.
std::string optionsHelp(const po::options_description& desc);

/// The keys of an options description as Markdown: one "### [section]" heading and table
/// (key, default, meaning) per key prefix, in definition order (docs/user-guide.md is
/// generated so).
std::string optionsMarkdown(const po::options_description& desc);

}  // namespace cambrian
