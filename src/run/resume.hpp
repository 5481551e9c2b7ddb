// cambrian: what a resumed run must share with the run that wrote its checkpoint — the
// settings that change results — and the hash that identifies them.
#pragma once

#include <set>
#include <string>

namespace cambrian {

/// `config_text` (INI) without the run-only keys: the settings that change results.
std::string resultConfigText(const std::string& config_text, const std::set<std::string>& run_only);

/// The hash of resultConfigText(): equal for runs that must give equal results.
std::string resultConfigHash(const std::string& config_text, const std::set<std::string>& run_only);

/// Compares the settings of a checkpoint with the current ones, key by key. Throws
/// Error(checkpoint) naming `path`, the first differing key that changes results, its old and
/// its new value, when one differs. A key the checkpoint lacks (a setting added after it was
/// written) is no change when its current value is what runs before the key used, as
/// `earlier_config_text` says (SettingsSchema::earlierRunsIniText); otherwise the message says
/// which value continues the run.
void checkResumeSettings(const std::string& path, const std::string& saved_config_text,
                         const std::string& current_config_text,
                         const std::string& earlier_config_text,
                         const std::set<std::string>& run_only);

}  // namespace cambrian
