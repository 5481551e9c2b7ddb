// cambrian: typed settings — parsing values from text, writing them as INI text, range checks.
#include "core/settings.hpp"

#include "cambrian/error.hpp"

#include "core/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

namespace cambrian {

namespace {

// text without spaces and tabs at either end
std::string trim(const std::string& text) {
  std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// the words of a list value: split at spaces, tabs and commas
std::vector<std::string> words(const std::string& text) {
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream in(spaced);
  std::vector<std::string> out;
  std::string word;
  while (in >> word)
    out.push_back(word);
  return out;
}

// a whole-text number of type T (an optional leading '+'); false when it does not parse
template <class T>
bool parseNumber(const std::string& text, T& value) {
  std::string t = trim(text);
  if (!t.empty() && t.front() == '+')
    t.erase(0, 1);
  if (t.empty())
    return false;
  auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
  return error == std::errc() && end == t.data() + t.size();
}

// "a, b or c"
std::string alternatives(const std::vector<std::string>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0)
      text += i + 1 == words.size() ? " or " : ", ";
    text += words[i];
  }
  return text;
}

}  // namespace

Setting::Setting(std::string key, Type type, void* variable, std::string help)
    : key_(std::move(key)), type_(type), variable_(variable), help_(std::move(help)) {
  default_text_ = text();
}

Setting::Setting(std::string key, std::vector<std::string> names, std::function<std::string()> get,
                 std::function<bool(const std::string&)> set, std::string help)
    : key_(std::move(key)),
      type_(Type::choice),
      variable_(nullptr),
      help_(std::move(help)),
      choices_(std::move(names)),
      choice_get_(std::move(get)),
      choice_set_(std::move(set)) {
  default_text_ = text();
}

Setting& Setting::require(std::function<bool()> ok, std::string rule) {
  rules_.emplace_back(std::move(ok), std::move(rule));
  return *this;
}

Setting& Setting::oneOf(std::vector<std::string> choices) {
  const auto* value = static_cast<const std::string*>(variable_);
  std::string rule = "must be " + alternatives(choices);
  return require(
      [value, choices = std::move(choices)] {
        return std::find(choices.begin(), choices.end(), *value) != choices.end();
      },
      rule);
}

Setting& Setting::runOnly() {
  run_only_ = true;
  return *this;
}

Setting& Setting::earlierRunsUsed(std::string value) {
  earlier_text_ = std::move(value);
  return *this;
}

std::string Setting::text() const {
  switch (type_) {
    case Type::real:
      return formatNumber(*static_cast<const double*>(variable_));
    case Type::integer:
      return std::to_string(*static_cast<const int*>(variable_));
    case Type::count:
    case Type::seed:
      return std::to_string(*static_cast<const std::uint64_t*>(variable_));
    case Type::flag:
      return *static_cast<const bool*>(variable_) ? "true" : "false";
    case Type::text:
      return *static_cast<const std::string*>(variable_);
    case Type::choice:
      return choice_get_();
    case Type::list: {
      std::string text;
      for (const std::string& item : *static_cast<const std::vector<std::string>*>(variable_))
        text += (text.empty() ? "" : " ") + item;
      return text;
    }
  }
  return "";
}

void Setting::set(const std::string& text) {
  auto bad = [&](const char* expected) {
    throw SettingTypeError(key_ + " = " + text + ": " + expected);
  };
  switch (type_) {
    case Type::real:
      if (!parseNumber(text, *static_cast<double*>(variable_)))
        bad("not a number");
      return;
    case Type::integer:
      if (!parseNumber(text, *static_cast<int*>(variable_)))
        bad("not an integer");
      return;
    case Type::count:
      if (!parseNumber(text, *static_cast<std::uint64_t*>(variable_)))
        bad("not a whole number in 0..18446744073709551615");
      return;
    case Type::seed:
      if (!parseSeed(text, *static_cast<std::uint64_t*>(variable_)))
        bad("not a seed (a whole number in 0..18446744073709551615)");
      return;
    case Type::flag: {
      std::string t = trim(text);
      std::transform(t.begin(), t.end(), t.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      bool& value = *static_cast<bool*>(variable_);
      if (t == "true" || t == "1" || t == "yes" || t == "on")
        value = true;
      else if (t == "false" || t == "0" || t == "no" || t == "off")
        value = false;
      else
        bad("not true or false");
      return;
    }
    case Type::text:
      *static_cast<std::string*>(variable_) = trim(text);
      return;
    case Type::choice:
      if (!choice_set_(trim(text)))
        throw ConfigError(key_ + " = " + trim(text) + ": must be " + alternatives(choices_));
      return;
    case Type::list: {
      auto& list = *static_cast<std::vector<std::string>*>(variable_);
      for (std::string& word : words(text))
        list.push_back(std::move(word));
      return;
    }
  }
}

void Setting::reset() {
  if (type_ == Type::list) {
    static_cast<std::vector<std::string>*>(variable_)->clear();
    for (std::string& word : words(default_text_))
      static_cast<std::vector<std::string>*>(variable_)->push_back(std::move(word));
    return;
  }
  set(default_text_);
}

std::string Setting::problem() const {
  for (const auto& [ok, rule] : rules_) {
    if (!ok())
      return key_ + " = " + text() + ": " + rule;
  }
  return "";
}

Setting& SettingsSchema::insert(std::unique_ptr<Setting> setting) {
  if (by_key_.count(setting->key()))
    throw Error(ExitCode::failure, "setting " + setting->key() + " is declared twice");
  if (setting->key().find('.') == std::string::npos)
    throw Error(ExitCode::failure, "setting " + setting->key() + " has no section");
  by_key_[setting->key()] = setting.get();
  settings_.push_back(std::move(setting));
  return *settings_.back();
}

Setting& SettingsSchema::add(const std::string& key, double& v, const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::real, &v, help));
}

Setting& SettingsSchema::add(const std::string& key, int& v, const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::integer, &v, help));
}

Setting& SettingsSchema::add(const std::string& key, std::uint64_t& v, const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::count, &v, help));
}

Setting& SettingsSchema::add(const std::string& key, bool& v, const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::flag, &v, help));
}

Setting& SettingsSchema::add(const std::string& key, std::string& v, const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::text, &v, help));
}

Setting& SettingsSchema::add(const std::string& key, std::vector<std::string>& v,
                             const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::list, &v, help));
}

Setting& SettingsSchema::addSeed(const std::string& key, std::uint64_t& v,
                                 const std::string& help) {
  return insert(std::make_unique<Setting>(key, Setting::Type::seed, &v, help));
}

void SettingsSchema::addCheck(std::function<void()> check) {
  checks_.push_back(std::move(check));
}

void SettingsSchema::describeSection(const std::string& section, const std::string& title) {
  titles_[section] = title;
}

std::string SettingsSchema::sectionTitle(const std::string& section) const {
  auto it = titles_.find(section);
  return it == titles_.end() ? "" : it->second;
}

Setting* SettingsSchema::find(const std::string& key) const {
  auto it = by_key_.find(key);
  return it == by_key_.end() ? nullptr : it->second;
}

void SettingsSchema::set(const std::string& key, const std::string& text) {
  Setting* setting = find(key);
  if (!setting)
    throw ConfigError("unrecognised option '" + key + "'");
  setting->set(text);
}

void SettingsSchema::check() const {
  for (const auto& setting : settings_) {
    std::string problem = setting->problem();
    if (!problem.empty())
      throw ConfigError(problem);
  }
  for (const auto& check : checks_)
    check();
}

void SettingsSchema::reset() {
  for (const auto& setting : settings_)
    setting->reset();
}

std::string SettingsSchema::iniText() const {
  return ini([](const Setting& setting) { return setting.text(); });
}

std::string SettingsSchema::defaultIniText() const {
  return ini([](const Setting& setting) { return setting.defaultText(); });
}

std::string SettingsSchema::earlierRunsIniText() const {
  return ini([](const Setting& s) {
    return s.earlierRunsText().empty() ? s.defaultText() : s.earlierRunsText();
  });
}

std::string SettingsSchema::ini(const std::function<std::string(const Setting&)>& value) const {
  // sections and keys sorted, so equal settings give equal text
  std::map<std::string, std::map<std::string, std::string>> sections;
  for (const auto& setting : settings_) {
    const std::string& key = setting->key();
    std::size_t dot = key.find('.');
    sections[key.substr(0, dot)][key.substr(dot + 1)] = value(*setting);
  }
  std::string text;
  for (const auto& [section, keys] : sections) {
    text += (text.empty() ? "[" : "\n[") + section + "]\n";
    for (const auto& [key, text_value] : keys)
      text += key + " = " + text_value + "\n";
  }
  return text;
}

std::set<std::string> SettingsSchema::runOnlyKeys() const {
  std::set<std::string> keys;
  for (const auto& setting : settings_) {
    if (setting->isRunOnly())
      keys.insert(setting->key());
  }
  return keys;
}

std::map<std::string, std::string> SettingsSchema::earlierRunValues() const {
  std::map<std::string, std::string> values;
  for (const auto& setting : settings_) {
    if (!setting->earlierRunsText().empty())
      values[setting->key()] = setting->earlierRunsText();
  }
  return values;
}

bool parseSeed(const std::string& text, std::uint64_t& value) {
  std::string t = trim(text);
  std::uint64_t parsed = 0;
  auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), parsed);
  if (t.empty() || error != std::errc() || end != t.data() + t.size())
    return false;
  value = parsed;
  return true;
}

std::vector<IniEntry> parseIni(const std::string& text, const std::string& source) {
  std::vector<IniEntry> entries;
  std::istringstream lines(text);
  std::string raw, section;
  int number = 0;
  while (std::getline(lines, raw)) {
    ++number;
    // comments run from # or ; to the end of the line
    std::size_t comment = raw.find_first_of("#;");
    std::string line = trim(comment == std::string::npos ? raw : raw.substr(0, comment));
    if (line.empty())
      continue;
    auto fail = [&](const std::string& what) {
      throw ConfigError(source + ": line " + std::to_string(number) + ": " + what + ": '" +
                        trim(raw) + "'");
    };
    if (line.front() == '[') {
      if (line.back() != ']' || line.size() < 3)
        fail("a section header is [name]");
      section = trim(line.substr(1, line.size() - 2));
      continue;
    }
    std::size_t equals = line.find('=');
    if (equals == std::string::npos)
      fail("expected key = value");
    std::string key = trim(line.substr(0, equals));
    if (key.empty())
      fail("expected key = value");
    if (section.empty())
      fail("key " + key + " is outside any [section]");
    entries.push_back({section + "." + key, trim(line.substr(equals + 1)), number});
  }
  return entries;
}

std::map<std::string, std::string> iniValues(const std::string& text) {
  std::map<std::string, std::string> values;
  for (const IniEntry& entry : parseIni(text, "<settings>"))
    values[entry.key] = entry.value;
  return values;
}

std::string iniTextWithout(const std::string& text, const std::set<std::string>& leave_out) {
  // the lines of the text minus those keys (sections kept in order)
  std::istringstream lines(text);
  std::string line, section, out;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.front() == '[' && line.back() == ']')
      section = line.substr(1, line.size() - 2);
    std::size_t equals = line.find(" = ");
    if (equals != std::string::npos && leave_out.count(section + "." + line.substr(0, equals)))
      continue;
    out += line + "\n";
  }
  return out;
}

}  // namespace cambrian
