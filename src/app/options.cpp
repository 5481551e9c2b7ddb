// cambrian: command lines and experiment files into a settings schema; help and reference.
#include "options.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "core/small_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace cambrian {

namespace {

// the sections of a schema in the order their first key was declared
std::vector<std::string> sectionsOf(const SettingsSchema& schema) {
  std::vector<std::string> sections;
  for (const auto& setting : schema.settings()) {
    std::string section = setting->key().substr(0, setting->key().find('.'));
    if (std::find(sections.begin(), sections.end(), section) == sections.end())
      sections.push_back(section);
  }
  return sections;
}

// every key (of `only`'s sections, when given) as a command-line option taking text (lists:
// repeatable), with its readable default shown when `with_defaults`
po::options_description schemaOptions(const SettingsSchema& schema, bool with_defaults,
                                      const std::set<std::string>* only = nullptr) {
  po::options_description all;
  for (const std::string& section : sectionsOf(schema)) {
    if (only && !only->count(section))
      continue;
    std::string title = schema.sectionTitle(section);
    po::options_description group(title.empty() ? "[" + section + "]" : title);
    for (const auto& setting : schema.settings()) {
      if (setting->key().substr(0, setting->key().find('.')) != section)
        continue;
      const char* key = setting->key().c_str();
      if (setting->type() == Setting::Type::list) {
        group.add_options()(key, po::value<std::vector<std::string>>()->composing(),
                            setting->help().c_str());
      } else if (with_defaults) {
        group.add_options()(
            key,
            po::value<std::string>()->default_value(setting->text(), readableDefault(*setting)),
            setting->help().c_str());
      } else {
        group.add_options()(key, po::value<std::string>(), setting->help().c_str());
      }
    }
    all.add(group);
  }
  return all;
}

// an experiment file is text of a few kilobytes
constexpr std::size_t kConfigFileLimit = 16u << 20;

// the text of a config file; ConfigError naming it when it cannot be read
std::string readFile(const std::string& path) {
  SmallFile file = readSmallFile(path, kConfigFileLimit);
  if (!file.problem.empty())
    throw ConfigError(path + ": the config file " + file.problem);
  return std::move(file.bytes);
}

// a table cell: pipes escaped so they do not split the cell
std::string tableCell(const std::string& text) {
  std::string cell;
  for (char c : text) {
    if (c == '|')
      cell += '\\';
    cell += c;
  }
  return cell;
}

}  // namespace

po::variables_map parseOptions(int argc, const char* const* argv,
                               const po::options_description& cli_only, SettingsSchema& schema,
                               const po::positional_options_description* positional,
                               const std::string& config_key, OptionOrigins* origins,
                               const std::set<std::string>& foreign_sections) {
  po::options_description all;
  all.add(cli_only).add(schemaOptions(schema, false));
  po::variables_map vm;

  // command line first: it wins over the file
  try {
    po::command_line_parser parser(argc, argv);
    parser.options(all);
    if (positional)
      parser.positional(*positional);
    po::parsed_options parsed = parser.run();
    // a word that is no option, where the command takes none: Boost would drop it silently
    // (`cambrian evolve walk.ini` would run the defaults)
    if (!positional) {
      for (const po::option& option : parsed.options) {
        if (option.position_key >= 0 && !option.original_tokens.empty())
          throw Error(ExitCode::usage,
                      "command line: '" + option.original_tokens.front() +
                          "' is not an option (settings are --section.key VALUE; an experiment "
                          "file is --config FILE)");
      }
    }
    po::store(parsed, vm);
    po::notify(vm);
  } catch (const po::error& e) {
    // Boost fills the placeholders of its message (%original_token% and the like) until none is
    // left: a token holding one itself would never end (found by fuzzing), so it is not asked
    for (int i = 1; i < argc; ++i) {
      std::string argument = argv[i];
      for (const char* placeholder :
           {"%canonical_option%", "%option%", "%value%", "%original_token%", "%prefix%"}) {
        if (argument.find(placeholder) != std::string::npos)
          throw Error(ExitCode::usage, "command line: '" + argument +
                                           "' is not an option or value cambrian understands");
      }
    }
    throw Error(ExitCode::usage, e.what());
  }
  std::set<std::string> command_line;
  for (const auto& setting : schema.settings()) {
    const std::string& key = setting->key();
    if (!vm.count(key))
      continue;
    command_line.insert(key);
    try {
      if (setting->type() == Setting::Type::list) {
        for (const std::string& text : vm[key].as<std::vector<std::string>>())
          setting->set(text);
      } else {
        setting->set(vm[key].as<std::string>());
      }
    } catch (const SettingTypeError& e) {
      throw Error(ExitCode::usage, std::string("command line: --") + e.what());
    } catch (const ConfigError& e) {
      throw ConfigError(std::string("command line: --") + e.what());
    }
  }

  // then the experiment file, when one is named: every key once (lists may repeat)
  std::string path;
  std::set<std::string> from_file;
  if (!config_key.empty() && vm.count(config_key)) {
    path = vm[config_key].as<std::string>();
    for (const IniEntry& entry : parseIni(readFile(path), path)) {
      Setting* setting = schema.find(entry.key);
      if (!setting && foreign_sections.count(entry.key.substr(0, entry.key.find('.'))))
        continue;
      if (!setting)
        throw ConfigError(path + ": line " + std::to_string(entry.line) +
                          ": unrecognised option '" + entry.key + "'");
      bool list = setting->type() == Setting::Type::list;
      if (from_file.count(entry.key) && !list)
        throw ConfigError(path + ": line " + std::to_string(entry.line) + ": " + entry.key +
                          " is given more than once");
      from_file.insert(entry.key);
      if (command_line.count(entry.key))
        continue;
      try {
        setting->set(entry.value);
      } catch (const SettingTypeError& e) {
        throw ConfigError(path + ": line " + std::to_string(entry.line) + ": " + e.what());
      } catch (const ConfigError& e) {
        throw ConfigError(path + ": line " + std::to_string(entry.line) + ": " + e.what());
      }
    }
  }
  if (origins) {
    origins->command_line = command_line;
    origins->config_file.clear();
    for (const std::string& key : from_file) {
      if (!command_line.count(key))
        origins->config_file.insert(key);
    }
    origins->config_path = path;
  }
  return vm;
}

void checkSettings(const SettingsSchema& schema, const OptionOrigins& origins) {
  try {
    schema.check();
  } catch (const ConfigError& e) {
    throw ConfigError(locateSettingError(e.what(), origins));
  }
}

std::string locateSettingError(const std::string& message, const OptionOrigins& origins) {
  std::string key = message.substr(0, message.find(" = "));
  if (origins.config_file.count(key) && !origins.config_path.empty())
    return origins.config_path + ": " + message;
  if (origins.command_line.count(key))
    return "command line: --" + message;
  return message;
}

std::string readableDefault(const Setting& setting) {
  std::string text = setting.defaultText();
  if (setting.type() != Setting::Type::real || text.find('.') == std::string::npos)
    return text;
  // a number as a person writes it: twelve significant digits
  char shorter[32];
  std::snprintf(shorter, sizeof shorter, "%.12g", std::strtod(text.c_str(), nullptr));
  return shorter;
}

std::string optionsHelp(const po::options_description& cli_only, const SettingsSchema& schema) {
  std::ostringstream text;
  text << cli_only << "\n" << schemaOptions(schema, true);
  return text.str();
}

std::string sectionsHelp(const SettingsSchema& schema, const std::set<std::string>& sections) {
  std::ostringstream text;
  text << schemaOptions(schema, false, &sections);
  return text.str();
}

std::string optionsMarkdown(const SettingsSchema& schema) {
  std::ostringstream out;
  for (const std::string& section : sectionsOf(schema)) {
    out << (out.tellp() > 0 ? "\n" : "") << "### [" << section << "]\n\n"
        << "| key | default | meaning |\n| --- | --- | --- |\n";
    for (const auto& setting : schema.settings()) {
      if (setting->key().substr(0, setting->key().find('.')) != section)
        continue;
      out << "| `" << setting->key() << "` | " << tableCell(readableDefault(*setting)) << " | "
          << tableCell(setting->help()) << (setting->isRunOnly() ? " (run-only)" : "") << " |\n";
    }
  }
  return out.str();
}

void adoptGenomeEncoding(const std::string& path, SettingsSchema& schema,
                         const OptionOrigins& origins) {
  const std::string key = "genome.encoding";
  if (path.empty() || origins.command_line.count(key) > 0 || origins.config_file.count(key) > 0)
    return;
  try {
    schema.set(key, readGenomeFile(path).encoding().name());
  } catch (const Error&) {
    // the command reads the file again and reports what is wrong with it
  }
}

}  // namespace cambrian
