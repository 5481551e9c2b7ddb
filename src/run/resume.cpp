// cambrian: the resume check and the settings hash.
#include "run/resume.hpp"

#include "cambrian/error.hpp"

#include "core/hash.hpp"
#include "core/settings.hpp"

#include <vector>

namespace cambrian {

std::string resultConfigText(const std::string& config_text,
                             const std::set<std::string>& run_only) {
  return iniTextWithout(config_text, run_only);
}

std::string resultConfigHash(const std::string& config_text,
                             const std::set<std::string>& run_only) {
  return hashText(resultConfigText(config_text, run_only));
}

void checkResumeSettings(const std::string& path, const std::string& saved_config_text,
                         const std::string& current_config_text,
                         const std::string& earlier_config_text,
                         const std::set<std::string>& run_only) {
  std::map<std::string, std::string> saved = iniValues(saved_config_text);
  std::map<std::string, std::string> current = iniValues(current_config_text);
  std::map<std::string, std::string> earlier = iniValues(earlier_config_text);

  // every key of either side, in order
  std::set<std::string> keys;
  for (const auto& [key, value] : saved)
    keys.insert(key);
  for (const auto& [key, value] : current)
    keys.insert(key);
  std::vector<std::string> continuing, now;  // keys added since, not at their earlier value
  std::vector<std::string> changed;          // keys at another value than the checkpoint's
  for (const std::string& key : keys) {
    if (run_only.count(key))
      continue;
    auto old_value = saved.find(key);
    auto new_value = current.find(key);
    // a key added since the checkpoint, at the value runs used before it existed: no change
    // (the others are collected, to name them all at once)
    auto earlier_value = earlier.find(key);
    if (old_value == saved.end() && new_value != current.end() && earlier_value != earlier.end()) {
      if (earlier_value->second != new_value->second) {
        continuing.push_back(key + " = " + earlier_value->second);
        now.push_back(key + " is '" + new_value->second + "'");
      }
      continue;
    }
    std::string before = old_value == saved.end() ? "(absent)" : "'" + old_value->second + "'";
    std::string after = new_value == current.end() ? "(absent)" : "'" + new_value->second + "'";
    if (before != after)
      changed.push_back(key + " was " + before + " when the checkpoint was written and is " +
                        after + " now");
  }
  auto joined = [](const std::vector<std::string>& items, const char* separator) {
    std::string text;
    for (const std::string& item : items)
      text += (text.empty() ? "" : separator) + item;
    return text;
  };
  // every changed setting named at once, then every newer one
  std::string message;
  if (changed.size() == 1) {
    message = "setting " + changed[0] +
              "; it changes results, so the run cannot continue with it (restore the old value, "
              "or start over with --fresh)";
  } else if (changed.size() > 1) {
    message = "settings " + joined(changed, "; ") +
              "; they change results, so the run cannot continue with them (restore the old "
              "values, or start over with --fresh)";
  }
  if (!continuing.empty()) {
    message += std::string(message.empty() ? "" : "; and ") +
               "settings added since the checkpoint was written change its results: that run "
               "behaved as " +
               joined(continuing, ", ") + ", and now " + joined(now, ", ") + "; set " +
               joined(continuing, ", ") + " to continue the run, or start over with --fresh";
  }
  if (!message.empty())
    throw Error(ExitCode::checkpoint, path + ": " + message);
}

}  // namespace cambrian
