// cambrian: the command line and experiment files of every subcommand. The settings themselves
// are declared once, in a SettingsSchema (core/settings.hpp), by the module that owns them; this
// turns a schema into command-line options ("--physics.time_step 0.004"), reads an experiment
// file (INI: "[physics]\ntime_step = 0.004") into it — the command line wins — and prints its
// help and Markdown reference.
#pragma once

#include "core/settings.hpp"

#include <boost/program_options.hpp>

#include <set>
#include <string>

namespace cambrian {

namespace po = boost::program_options;

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
/// came from: "FILE: " for a value read from the config file, "command line: --" for one given
/// as an option, nothing for a default or a message that names no known key.
std::string locateSettingError(const std::string& message, const OptionOrigins& origins);

/// Parses the command line (`cli_only` options and every key of `schema` as --section.key) and
/// then, when the option `config_key` names a file, that experiment file (command line wins),
/// setting the schema's variables. A command line that does not parse (an unknown option, a
/// value of the wrong type) is Error(usage); an unreadable file, a line that is not INI, an
/// unknown key or a bad value in it is a ConfigError naming the file. Range checks are not run
/// (checkSettings). `origins`, when given, receives where each setting came from. Keys of the
/// file in `foreign_sections` that the schema does not have are another command's (an
/// experiment file's [evolution] and [run] keys, read by simulate) and are passed over.
po::variables_map parseOptions(int argc, const char* const* argv,
                               const po::options_description& cli_only, SettingsSchema& schema,
                               const po::positional_options_description* positional,
                               const std::string& config_key = "config",
                               OptionOrigins* origins = nullptr,
                               const std::set<std::string>& foreign_sections = {});

/// The sections of an experiment file that only `evolve` reads.
inline const std::set<std::string> kEvolveOnlySections = {"evolution", "islands", "run"};

/// Runs every range check of `schema`; the ConfigError names where the bad value came from.
void checkSettings(const SettingsSchema& schema, const OptionOrigins& origins);

/// Sets genome.encoding to the encoding of the genome file `path` (told by its tag or its text
/// header) when neither the command line nor the config file gave it, so that a genome file of
/// any encoding is simulated and inspected without naming its encoding. A file that cannot be
/// read leaves the settings as they are (reading it later says why).
void adoptGenomeEncoding(const std::string& path, SettingsSchema& schema,
                         const OptionOrigins& origins);

/// A setting's default as a person writes it: "0.0041666666666666666" becomes
/// "0.00416666666667" (what --help and --help-markdown print).
std::string readableDefault(const Setting& setting);

/// The command-line options and every key of `schema`, one group per section, as --help prints
/// them, with readable defaults.
std::string optionsHelp(const po::options_description& cli_only, const SettingsSchema& schema);

/// The keys of `schema` in `sections` ("physics"), one group per section, as --help prints them
/// but without defaults (for a command whose settings start from stored values: replay).
std::string sectionsHelp(const SettingsSchema& schema, const std::set<std::string>& sections);

/// The keys of `schema` as Markdown: one "### [section]" heading and table (key, default,
/// meaning) per section, in declaration order (docs/user-guide.md is generated so).
std::string optionsMarkdown(const SettingsSchema& schema);

}  // namespace cambrian
