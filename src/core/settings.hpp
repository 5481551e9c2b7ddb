// cambrian: the one typed configuration. Every setting of every plug-in is declared once, in a
// SettingsSchema: its key ("physics.time_step"), the variable it sets, what it means, its default,
// the range check that lives next to it, and whether it is run-only (may change between a
// checkpoint and its resume because it changes no result). The schema reads values from text
// (experiment files, the command line, a history's settings) and writes the effective settings as
// INI text, the form stored in every history and checkpoint.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace cambrian {

/// A value that does not parse as its setting's type ("many" for an integer). The caller decides
/// whether that is a usage error (command line) or a config error (file).
class SettingTypeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One declared setting. Made by SettingsSchema::add; refined with its builder methods.
class Setting {
 public:
  /// What the bound variable is.
  enum class Type { real, integer, count, seed, flag, text, list, choice };

  /// Binds `variable` (which must outlive the schema) of `type` to `key`.
  Setting(std::string key, Type type, void* variable, std::string help);
  /// A choice among named values: `get` names the current value, `set` takes a name (false when
  /// it names none of `names`).
  Setting(std::string key, std::vector<std::string> names, std::function<std::string()> get,
          std::function<bool(const std::string&)> set, std::string help);

  /// The value must satisfy `ok` ("key = value: RULE" otherwise).
  Setting& require(std::function<bool()> ok, std::string rule);
  /// The value must be one of `words` ("key = value: must be a, b or c" otherwise).
  Setting& oneOf(std::vector<std::string> words);
  /// The setting changes no result: a resumed run may change it, the settings hash leaves it out.
  Setting& runOnly();
  /// The key is newer than some stored runs, which behaved as `value`: a stored settings text
  /// without the key (a history, a checkpoint) means this value, not the default.
  Setting& earlierRunsUsed(std::string value);

  const std::string& key() const { return key_; }
  const std::string& help() const { return help_; }
  Type type() const { return type_; }
  bool isRunOnly() const { return run_only_; }
  /// What runs stored before the key existed used (empty: the default, as for most keys).
  const std::string& earlierRunsText() const { return earlier_text_; }
  /// The value at declaration, as INI text.
  const std::string& defaultText() const { return default_text_; }
  /// The current value as INI text (numbers in the shortest form that reads back exactly).
  std::string text() const;
  /// Sets the value from text; a list appends the words of `text` (split at spaces and commas).
  /// Throws SettingTypeError naming the key and the text when it does not parse.
  void set(const std::string& text);
  /// Back to the default (lists: empty).
  void reset();
  /// "" when every rule holds, else "key = value: rule" of the first broken one.
  std::string problem() const;
  /// The names a choice accepts (empty for other types).
  const std::vector<std::string>& choices() const { return choices_; }

 private:
  std::string key_;
  Type type_;
  void* variable_;
  std::string help_;
  std::string default_text_;
  std::string earlier_text_;
  bool run_only_ = false;
  std::vector<std::pair<std::function<bool()>, std::string>> rules_;
  std::vector<std::string> choices_;
  std::function<std::string()> choice_get_;
  std::function<bool(const std::string&)> choice_set_;
};

/// Every setting of an experiment, in declaration order, grouped by section (the key's prefix).
class SettingsSchema {
 public:
  SettingsSchema() = default;
  SettingsSchema(const SettingsSchema&) = delete;
  SettingsSchema& operator=(const SettingsSchema&) = delete;

  Setting& add(const std::string& key, double& variable, const std::string& help);
  Setting& add(const std::string& key, int& variable, const std::string& help);
  /// An unsigned 64-bit count (0..2^64-1).
  Setting& add(const std::string& key, std::uint64_t& variable, const std::string& help);
  Setting& add(const std::string& key, bool& variable, const std::string& help);
  Setting& add(const std::string& key, std::string& variable, const std::string& help);
  /// A list of words (paths): repeated keys and words separated by spaces or commas append.
  Setting& add(const std::string& key, std::vector<std::string>& variable, const std::string& help);
  /// A seed: a decimal integer in 0..2^64-1 ("-3" is refused, not wrapped).
  Setting& addSeed(const std::string& key, std::uint64_t& variable, const std::string& help);
  /// A choice: `variable` takes the value paired with the name given ("motor" ->
  /// Actuation::saturated_motor); another name is a config error listing the names.
  template <class T>
  Setting& addChoice(const std::string& key, T& variable,
                     std::vector<std::pair<std::string, T>> choices, const std::string& help) {
    std::vector<std::string> names;
    for (const auto& choice : choices)
      names.push_back(choice.first);
    auto get = [&variable, choices] {
      for (const auto& [name, value] : choices) {
        if (value == variable)
          return name;
      }
      return std::string("?");
    };
    auto set = [&variable, choices](const std::string& text) {
      for (const auto& [name, value] : choices) {
        if (name == text) {
          variable = value;
          return true;
        }
      }
      return false;
    };
    return insert(std::make_unique<Setting>(key, names, get, set, help));
  }
  /// A check over several settings, run after the per-setting rules; it throws ConfigError.
  void addCheck(std::function<void()> check);
  /// A one-line title for a section's group in --help ("genome" -> "limits of the genome").
  void describeSection(const std::string& section, const std::string& title);

  /// The settings in declaration order.
  const std::vector<std::unique_ptr<Setting>>& settings() const { return settings_; }
  /// The setting with this key, or null.
  Setting* find(const std::string& key) const;
  /// Sets `key` from text; ConfigError when the key is unknown, SettingTypeError when the text
  /// does not parse.
  void set(const std::string& key, const std::string& text);
  /// Runs every rule, then every check; throws ConfigError "key = value: rule" for the first one
  /// broken.
  void check() const;
  /// Every setting at its default again.
  void reset();

  /// The current values as INI text: sections sorted, keys sorted within, "key = value" lines.
  std::string iniText() const;
  /// The defaults in the same form.
  std::string defaultIniText() const;
  /// What each setting was in runs stored before it existed, in the same form: its declared
  /// earlier value (Setting::earlierRunsUsed), else its default.
  std::string earlierRunsIniText() const;
  /// The keys declared run-only.
  std::set<std::string> runOnlyKeys() const;
  /// key -> value for the keys whose absence from a stored settings text means something other
  /// than their default (Setting::earlierRunsUsed).
  std::map<std::string, std::string> earlierRunValues() const;
  /// The title of `section` ("" when none was given).
  std::string sectionTitle(const std::string& section) const;

 private:
  Setting& insert(std::unique_ptr<Setting> setting);
  std::string ini(const std::function<std::string(const Setting&)>& value) const;
  std::vector<std::unique_ptr<Setting>> settings_;
  std::map<std::string, Setting*> by_key_;
  std::vector<std::function<void()>> checks_;
  std::map<std::string, std::string> titles_;
};

/// A seed from text: a decimal integer in 0..2^64-1, nothing else (no sign, no spaces inside);
/// false when `text` is not one.
bool parseSeed(const std::string& text, std::uint64_t& value);

/// One `key = value` line of INI text, the key with its section ("physics.time_step").
struct IniEntry {
  std::string key;
  std::string value;
  int line = 0;  ///< 1-based line number
};

/// Reads INI text: `[section]` headers, `key = value` (or `key=value`) lines, blank lines and
/// comments (from `#` or `;` to the end of the line). Throws ConfigError naming `source` and the
/// line for a line that is none of these or a key outside any section.
std::vector<IniEntry> parseIni(const std::string& text, const std::string& source);

/// The `section.key -> value` map of INI text (a later line wins).
std::map<std::string, std::string> iniValues(const std::string& text);

/// `text` (INI) without the lines of the keys in `leave_out` (sections kept in order).
std::string iniTextWithout(const std::string& text, const std::set<std::string>& leave_out);

}  // namespace cambrian
