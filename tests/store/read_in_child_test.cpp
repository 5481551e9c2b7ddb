// Tests of reading a file in a child process first: a read that returns or throws lets the caller
// go on; one that crashes or never ends is an error naming the file, within the bound; the
// damaged files fuzzing found (HDF5 1.10 crashing and looping) are refused by both readers.
#include "store/read_in_child.hpp"

#include "cambrian/error.hpp"

#include "store/checkpoint.hpp"
#include "store/history.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace cambrian {
namespace {

// sets CAMBRIAN_READ_SECONDS for one test
class ReadSeconds {
 public:
  explicit ReadSeconds(const char* value) { ::setenv("CAMBRIAN_READ_SECONDS", value, 1); }
  ~ReadSeconds() { ::unsetenv("CAMBRIAN_READ_SECONDS"); }
};

std::string dataFile(const std::string& name) {
  return std::string(CAMBRIAN_SOURCE_DIR) + "/tests/store/data/" + name;
}

std::string scratchFile(const std::string& name) {
  std::string path = testing::TempDir() + "/cambrian_read_in_child_test_" + name;
  std::filesystem::remove(path);
  return path;
}

// the error readInChildFirst throws for `read`, or "" when it returns
std::string errorOf(const std::function<void()>& read, ExitCode code = ExitCode::input_file) {
  try {
    readInChildFirst("some.h5", code, read);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code);
    return e.what();
  }
  return "";
}

TEST(ReadInChildFirst, AReadThatReturnsOrThrowsLetsTheCallerGoOn) {
  std::string marker = scratchFile("marker");
  EXPECT_EQ(errorOf([&] { std::ofstream(marker) << "read"; }), "");
  // the child did read
  EXPECT_TRUE(std::filesystem::exists(marker));
  EXPECT_EQ(errorOf([] { throw InputError("some.h5: corrupt"); }), "");
}

TEST(ReadInChildFirst, AReadThatCrashesIsAnErrorNamingTheFile) {
  std::string message = errorOf([] { std::raise(SIGKILL); }, ExitCode::checkpoint);
  EXPECT_NE(message.find("some.h5: reading the file crashed the HDF5 library"), std::string::npos)
      << message;
  EXPECT_NE(message.find("signal 9"), std::string::npos) << message;
  // an exception that is not cambrian's is a crash too
  message = errorOf([] { throw std::runtime_error("not ours"); });
  EXPECT_NE(message.find("crashed"), std::string::npos) << message;
}

TEST(ReadInChildFirst, AReadThatNeverEndsIsStoppedAtTheBound) {
  ReadSeconds seconds("1");
  auto start = std::chrono::steady_clock::now();
  std::string message = errorOf([] {
    for (;;)
      ::pause();
  });
  double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(message.find("some.h5: reading the file did not end within 1 s"), std::string::npos)
      << message;
  EXPECT_LT(waited, 30.0);
}

TEST(ReadInChildFirst, TheBoundGrowsWithTheFileAndZeroTurnsTheChildOff) {
  std::string path = scratchFile("sized.h5");
  std::ofstream(path, std::ios::binary) << std::string(9u << 20, 'x');
  EXPECT_EQ(childReadSeconds(path), 22u);
  EXPECT_EQ(childReadSeconds(path + ".missing"), 20u);
  ReadSeconds off("0");
  EXPECT_EQ(childReadSeconds(path), 0u);
  std::string marker = scratchFile("not_read");
  EXPECT_EQ(errorOf([&] { std::ofstream(marker) << "read"; }), "");
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(ReadInChildFirst, AHistoryThatCrashesHdf5IsAnInputError) {
  std::string path = dataFile("history_hdf5_crash.h5");
  try {
    HistoryReader reader(path);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": reading the file crashed"), std::string::npos)
        << e.what();
  }
}

TEST(ReadInChildFirst, AHistoryOrCheckpointThatSendsHdf5IntoAnEndlessLoopIsRefusedAtTheBound) {
  ReadSeconds seconds("2");
  std::string history = dataFile("history_hdf5_endless_loop.h5");
  try {
    HistoryReader reader(history);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(history + ": reading the file did not end within 2 s"),
              std::string::npos)
        << e.what();
  }
  std::string checkpoint = dataFile("checkpoint_hdf5_endless_loop.h5");
  try {
    readCheckpoint(checkpoint);
    FAIL() << "read";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::checkpoint);
    EXPECT_NE(std::string(e.what()).find(checkpoint + ": reading the file did not end within 2 s"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cambrian
