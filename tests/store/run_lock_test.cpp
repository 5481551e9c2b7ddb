// Tests of the output directory's lock: a live holder keeps a second run out, a holder that ends
// (or whose pid is gone, or that is on another host) is waited for within the bound, and the
// holder's line is read and described.
#include "store/run_lock.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cambrian {
namespace {

std::string tempDir(const std::string& name) {
  std::string dir = testing::TempDir() + "/cambrian_run_lock_test_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string thisHost() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return host;
}

// a pid that no process has any more (a child, reaped)
pid_t endedPid() {
  pid_t child = ::fork();
  if (child == 0)
    ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// a child process that locks DIR/run.lock, writes `holder_line` into it ("" = takes RunLock,
// which writes its own), tells the parent, and holds it for `hold_ms` (or until killed)
pid_t holdLock(const std::string& dir, const std::string& holder_line, int hold_ms) {
  int ready[2];
  EXPECT_EQ(::pipe(ready), 0);
  pid_t child = ::fork();
  if (child == 0) {
    ::close(ready[0]);
    if (holder_line.empty()) {
      RunLock lock(dir);
      (void)!::write(ready[1], "x", 1);
      ::usleep(static_cast<useconds_t>(hold_ms) * 1000);
    } else {
      int fd = ::open(RunLock::pathIn(dir).c_str(), O_RDWR | O_CREAT, 0644);
      if (fd < 0 || ::flock(fd, LOCK_EX) != 0)
        ::_exit(3);
      (void)!::ftruncate(fd, 0);
      (void)!::pwrite(fd, holder_line.data(), holder_line.size(), 0);
      (void)!::write(ready[1], "x", 1);
      ::usleep(static_cast<useconds_t>(hold_ms) * 1000);
    }
    ::_exit(0);
  }
  ::close(ready[1]);
  char byte = 0;
  EXPECT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  return child;
}

// a wait that records what the run would print
struct Recorder {
  std::vector<std::string> said;
  RunLockWait wait(double seconds, double running_here_seconds = 10) {
    RunLockWait w;
    w.seconds = seconds;
    w.running_here_seconds = running_here_seconds;
    w.say = [this](const std::string& line) { said.push_back(line); };
    return w;
  }
};

TEST(RunLock, ALiveHolderOnThisHostIsRefusedNamingIt) {
  std::string dir = tempDir("live");
  pid_t holder = holdLock(dir, "", 60'000);
  Recorder recorder;
  try {
    RunLock second(dir, recorder.wait(30, 0.2));
    ADD_FAILURE() << "a second lock was granted while the holder lives";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::output_file);
    std::string message = e.what();
    EXPECT_NE(message.find("another cambrian evolve is writing this directory"), std::string::npos)
        << message;
    EXPECT_NE(message.find("pid " + std::to_string(holder) + ", alive on this host"),
              std::string::npos)
        << message;
  }
  ASSERT_EQ(recorder.said.size(), 1u);
  EXPECT_NE(recorder.said[0].find("waiting up to 0.2 s"), std::string::npos) << recorder.said[0];
  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);
}

TEST(RunLock, AHolderThatEndsIsWaitedForAndTheLockThenNamesThisProcess) {
  std::string dir = tempDir("ends");
  pid_t holder = holdLock(dir, "", 300);
  Recorder recorder;
  {
    RunLock lock(dir, recorder.wait(60));
    ASSERT_FALSE(recorder.said.empty());
    EXPECT_NE(recorder.said[0].find("pid " + std::to_string(holder)), std::string::npos)
        << recorder.said[0];
    RunLockHolder now = RunLockHolder::parse([&] {
      std::ifstream file(RunLock::pathIn(dir));
      return std::string(std::istreambuf_iterator<char>(file), {});
    }());
    EXPECT_EQ(now.pid, ::getpid());
    EXPECT_EQ(now.state, RunLockHolder::State::running_here);
  }
  ::waitpid(holder, nullptr, 0);
}

TEST(RunLock, AHolderWhosePidIsGoneIsDescribedAsEndedAndWaitedFor) {
  std::string dir = tempDir("gone");
  pid_t gone = endedPid();
  // the lock outlives the pid its file names (a rank still dying, a forked child)
  pid_t holder = holdLock(dir, "host " + thisHost() + " pid " + std::to_string(gone) + "\n", 300);
  Recorder recorder;
  RunLock lock(dir, recorder.wait(60, 0));
  ASSERT_FALSE(recorder.said.empty());
  EXPECT_NE(recorder.said[0].find("which has ended on this host"), std::string::npos)
      << recorder.said[0];
  EXPECT_NE(recorder.said[0].find("waiting up to 60 s"), std::string::npos) << recorder.said[0];
  ::waitpid(holder, nullptr, 0);
}

TEST(RunLock, AHolderOnAnotherHostIsSaidSoAndRefusedAfterTheBound) {
  std::string dir = tempDir("elsewhere");
  pid_t holder = holdLock(dir, "host node-elsewhere-017 pid 4242\n", 60'000);
  Recorder recorder;
  try {
    RunLock second(dir, recorder.wait(0.2));
    ADD_FAILURE() << "a second lock was granted while the holder lives";
  } catch (const Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("host node-elsewhere-017 pid 4242, on another host"), std::string::npos)
        << message;
    EXPECT_NE(message.find("run.lock_wait"), std::string::npos) << message;
  }
  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);

  // its end frees the directory
  RunLock lock(dir, recorder.wait(60));
}

TEST(RunLock, NoWaitRefusesAtOnce) {
  std::string dir = tempDir("no_wait");
  pid_t holder = holdLock(dir, "", 60'000);
  EXPECT_THROW(RunLock(dir, RunLockWait{0, 0, {}}), Error);
  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);
}

TEST(RunLockHolder, ReadsTheHolderLineAndTellsWhatItCan) {
  RunLockHolder self =
      RunLockHolder::parse("host " + thisHost() + " pid " + std::to_string(::getpid()) + "\n");
  EXPECT_EQ(self.state, RunLockHolder::State::running_here);
  EXPECT_EQ(self.pid, ::getpid());
  EXPECT_EQ(RunLockHolder::parse("host " + thisHost() + " pid " + std::to_string(endedPid())).state,
            RunLockHolder::State::ended_here);
  EXPECT_EQ(RunLockHolder::parse("host elsewhere pid 1").state, RunLockHolder::State::elsewhere);
  for (const char* garbage : {"", "nobody", "host", "host x pid", "host x pid y", "pid 3 host x"})
    EXPECT_EQ(RunLockHolder::parse(garbage).state, RunLockHolder::State::unknown) << garbage;
  EXPECT_EQ(RunLockHolder::parse("").describe(), "a holder that has not named itself yet");
}

}  // namespace
}  // namespace cambrian
