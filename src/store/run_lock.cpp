#include "store/run_lock.hpp"

#include "cambrian/error.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace cambrian {

std::string RunLock::pathIn(const std::string& dir) {
  return dir + "/run.lock";
}

RunLock::RunLock(const std::string& dir, std::string* warning) {
  std::string path = pathIn(dir);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(ExitCode::output_file,
                path + ": cannot create the run lock: " + std::strerror(errno));

  // the lock, or who holds it
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    int error = errno;
    if (error == EWOULDBLOCK) {
      char holder[256] = {};
      ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
      std::string who = n > 0 ? std::string(holder, static_cast<std::size_t>(n)) : "unknown";
      while (!who.empty() && (who.back() == '\n' || who.back() == ' '))
        who.pop_back();
      ::close(fd_);
      fd_ = -1;
      throw Error(ExitCode::output_file,
                  dir + ": another cambrian evolve is writing this directory (" + who + ", " +
                      path + "); wait for it to end, or give this run another --out");
    }
    // no locks on this file system: go on unprotected, and say so
    if (warning)
      *warning = path + ": cannot lock (" + std::strerror(error) +
                 "): nothing stops a second run from writing this directory at the same time";
    ::close(fd_);
    fd_ = -1;
    return;
  }

  // who holds it, for the message a second run prints
  char host[128] = {};
  ::gethostname(host, sizeof host - 1);
  std::string holder = "host " + std::string(host) + " pid " + std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, holder.data(), holder.size(), 0) < 0) {
    // the holder's name is a courtesy: the lock itself is what counts
  }
}

RunLock::~RunLock() {
  if (fd_ >= 0)
    ::close(fd_);  // releases the lock
}

}  // namespace cambrian
