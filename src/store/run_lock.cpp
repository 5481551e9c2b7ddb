#include "store/run_lock.hpp"

#include "cambrian/error.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

namespace cambrian {

namespace {

std::string thisHost() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return host;
}

// alive: kill(pid, 0) finds it and /proc does not call it a zombie (a zombie holds no files)
bool processAlive(long pid) {
  if (pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH))
    return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line))
    return true;  // no /proc: kill said it exists
  std::size_t close = line.rfind(')');
  return close == std::string::npos || close + 2 >= line.size() || line[close + 2] != 'Z';
}

std::string readHolder(int fd) {
  char text[256] = {};
  ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  return n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
}

std::string secondsText(double seconds) {
  std::ostringstream text;
  text << seconds << " s";
  return text.str();
}

}  // namespace

RunLockHolder RunLockHolder::parse(const std::string& text) {
  RunLockHolder holder;
  std::istringstream words(text);
  std::string host_word, pid_word;
  if (!(words >> host_word >> holder.host >> pid_word >> holder.pid) || host_word != "host" ||
      pid_word != "pid") {
    holder = RunLockHolder{};
    return holder;
  }
  if (holder.host != thisHost())
    holder.state = State::elsewhere;
  else
    holder.state = processAlive(holder.pid) ? State::running_here : State::ended_here;
  return holder;
}

std::string RunLockHolder::describe() const {
  std::string who = "host " + host + " pid " + std::to_string(pid);
  switch (state) {
    case State::running_here:
      return who + ", alive on this host";
    case State::ended_here:
      return who + ", which has ended on this host; its lock is still being released";
    case State::elsewhere:
      return who + ", on another host: whether it still runs cannot be told from here";
    case State::unknown:
      break;
  }
  return "a holder that has not named itself yet";
}

std::string RunLock::pathIn(const std::string& dir) {
  return dir + "/run.lock";
}

RunLock::RunLock(const std::string& dir, const RunLockWait& wait, std::string* warning) {
  std::string path = pathIn(dir);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(ExitCode::output_file,
                path + ": cannot create the run lock: " + std::strerror(errno));

  // the lock, waiting while its holder may still let go of it
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  std::string announced;
  while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    int error = errno;
    if (error == EINTR)
      continue;
    if (error != EWOULDBLOCK) {
      // no locks on this file system: go on unprotected, and say so
      if (warning)
        *warning = path + ": cannot lock (" + std::strerror(error) +
                   "): nothing stops a second run from writing this directory at the same time";
      ::close(fd_);
      fd_ = -1;
      return;
    }
    RunLockHolder holder = RunLockHolder::parse(readHolder(fd_));
    double bound = holder.state == RunLockHolder::State::running_here
                       ? std::min(wait.seconds, wait.running_here_seconds)
                       : wait.seconds;
    double waited = std::chrono::duration<double>(Clock::now() - start).count();
    if (waited >= bound) {
      ::close(fd_);
      fd_ = -1;
      throw Error(ExitCode::output_file,
                  dir + ": another cambrian evolve is writing this directory (" +
                      holder.describe() + "; " + path + "), still after " + secondsText(bound) +
                      "; wait for it to end, give this run another --out, or raise "
                      "run.lock_wait if its lock outlives it (cluster file systems)");
    }
    std::string description = holder.describe();
    if (wait.say && description != announced) {
      wait.say(dir + " is locked by " + description + " (" + path + "); waiting up to " +
               secondsText(bound) + " for it");
      announced = description;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }

  // who holds it, for the message a second run prints
  std::string holder = "host " + thisHost() + " pid " + std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, holder.data(), holder.size(), 0) < 0) {
    // the holder's name is a courtesy: the lock itself is what counts
  }
}

RunLock::~RunLock() {
  if (fd_ >= 0)
    ::close(fd_);  // releases the lock
}

}  // namespace cambrian
