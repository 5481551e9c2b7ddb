// Tests of the resume rules: run-only keys may change, others may not; keys added since the
// checkpoint compare with their defaults; the settings hash leaves run-only keys out.
#include "run/resume.hpp"

#include "cambrian/error.hpp"

#include "core/hash.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

namespace cambrian {
namespace {

const std::string kConfig =
    "[evolution]\ngenerations = 5\npopulation = 4\n\n[physics]\ntime_step = 0.004\n\n[run]\n"
    "out = a\nquiet = true\nseed = 9\n";
const std::set<std::string> kRunOnly = {"evolution.generations", "run.out", "run.quiet"};

// the code and message of an Error from `call`
template <class F>
std::pair<ExitCode, std::string> failure(F call) {
  try {
    call();
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  return {ExitCode::ok, ""};
}

TEST(Resume, RunOnlyKeysMayChangeOthersMayNot) {
  std::string changed_out = kConfig;
  changed_out.replace(changed_out.find("out = a"), 7, "out = b");
  changed_out.replace(changed_out.find("generations = 5"), 15, "generations = 9");
  EXPECT_NO_THROW(checkResumeSettings("ck.h5", kConfig, changed_out, "", kRunOnly));
  EXPECT_EQ(resultConfigHash(kConfig, kRunOnly), resultConfigHash(changed_out, kRunOnly));
  EXPECT_NE(hashText(kConfig), hashText(changed_out));

  // a physics key: named with both values
  std::string changed_step = kConfig;
  changed_step.replace(changed_step.find("0.004"), 5, "0.002");
  auto [code, message] =
      failure([&] { checkResumeSettings("ck.h5", kConfig, changed_step, "", kRunOnly); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("ck.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("physics.time_step was '0.004'"), std::string::npos) << message;
  EXPECT_NE(message.find("'0.002' now"), std::string::npos) << message;
  EXPECT_NE(resultConfigHash(kConfig, kRunOnly), resultConfigHash(changed_step, kRunOnly));

  // the seed, and a key one side lacks
  std::string changed_seed = kConfig;
  changed_seed.replace(changed_seed.find("seed = 9"), 8, "seed = 10");
  std::tie(code, message) =
      failure([&] { checkResumeSettings("ck.h5", kConfig, changed_seed, "", kRunOnly); });
  EXPECT_NE(message.find("run.seed"), std::string::npos) << message;
  std::tie(code, message) = failure([&] {
    checkResumeSettings("ck.h5", kConfig, kConfig + "\n[task]\nname = walk\n", "", kRunOnly);
  });
  EXPECT_NE(message.find("task.name was (absent)"), std::string::npos) << message;
}

// several changed settings, and a newer one, are named in one message
TEST(Resume, EveryChangedSettingIsNamedAtOnce) {
  std::string earlier = kConfig + "\n[task]\nrest_check = false\n";
  std::string changed = kConfig;
  changed.replace(changed.find("0.004"), 5, "0.002");
  changed.replace(changed.find("seed = 9"), 8, "seed = 10");
  changed += "\n[task]\nrest_check = true\n";
  auto [code, message] =
      failure([&] { checkResumeSettings("ck.h5", kConfig, changed, earlier, kRunOnly); });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("physics.time_step was '0.004'"), std::string::npos) << message;
  EXPECT_NE(message.find("run.seed was '9'"), std::string::npos) << message;
  EXPECT_NE(message.find("restore the old values"), std::string::npos) << message;
  EXPECT_NE(message.find("set task.rest_check = false to continue"), std::string::npos) << message;
}

TEST(Resume, KeysAddedSinceTheCheckpointCompareWithWhatEarlierRunsUsed) {
  std::string earlier = kConfig + "\n[task]\nrest_check = false\n";
  EXPECT_NO_THROW(checkResumeSettings("ck.h5", kConfig, earlier, earlier, kRunOnly));
  auto [code, message] = failure([&] {
    checkResumeSettings("ck.h5", kConfig, kConfig + "\n[task]\nrest_check = true\n", earlier,
                        kRunOnly);
  });
  EXPECT_EQ(code, ExitCode::checkpoint);
  EXPECT_NE(message.find("that run behaved as task.rest_check = false, and now task.rest_check is "
                         "'true'"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("set task.rest_check = false to continue"), std::string::npos) << message;
  // a key the current settings lack is a change whatever the defaults say
  std::tie(code, message) =
      failure([&] { checkResumeSettings("ck.h5", earlier, kConfig, earlier, kRunOnly); });
  EXPECT_NE(message.find("task.rest_check was 'false'"), std::string::npos) << message;
}

TEST(Resume, ResultTextLeavesRunOnlyKeysOut) {
  std::string text = resultConfigText(kConfig, kRunOnly);
  EXPECT_EQ(text.find("out = a"), std::string::npos);
  EXPECT_EQ(text.find("generations = 5"), std::string::npos);
  EXPECT_NE(text.find("seed = 9"), std::string::npos);
  EXPECT_NE(text.find("population = 4"), std::string::npos);
}

}  // namespace
}  // namespace cambrian
