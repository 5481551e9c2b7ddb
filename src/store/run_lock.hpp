// cambrian: the lock an evolution holds on its output directory, so that two runs never write
// the same history and checkpoint (a second `cambrian evolve` on a busy directory is refused).
#pragma once

#include <string>

namespace cambrian {

/// An exclusive lock on DIR/run.lock (flock), held until the object goes away or the process
/// ends (also by SIGKILL: the kernel releases it). The file holds the holder's host and pid.
class RunLock {
 public:
  /// Locks `dir` (which must exist). Throws Error(output_file) naming the directory and the
  /// holder when another process holds the lock; where the file system has no locks (some
  /// cluster file systems), sets `*warning` (when given) and holds nothing.
  explicit RunLock(const std::string& dir, std::string* warning = nullptr);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  /// The lock file's path.
  static std::string pathIn(const std::string& dir);

 private:
  int fd_ = -1;
};

}  // namespace cambrian
