// cambrian: the lock an evolution holds on its output directory, so that two runs never write
// the same history and checkpoint (a second `cambrian evolve` on a busy directory is refused
// after a bounded wait, so that a run restarted at once after a kill finds its directory free).
#pragma once

#include <functional>
#include <string>

namespace cambrian {

/// Who holds a run lock, as its file says ("host NAME pid N"), and what can be told of it.
struct RunLockHolder {
  enum class State {
    running_here,  ///< on this host, and the pid is alive (a live run, or one still dying)
    ended_here,    ///< on this host, and the pid is gone: its lock is about to be released
    elsewhere,     ///< on another host: nothing can be told from here
    unknown,       ///< the file names nobody (a holder that has not written it yet)
  };
  std::string host;
  long pid = -1;
  State state = State::unknown;

  /// Reads the holder's line ("host NAME pid N") and tells its state from this host.
  static RunLockHolder parse(const std::string& text);
  /// "host NAME pid N (running on this host)" and the like, for messages.
  std::string describe() const;
};

/// How long a run waits for a held lock before it gives up.
struct RunLockWait {
  double seconds = 60;               ///< the bound for a holder that has ended or is elsewhere
  double running_here_seconds = 10;  ///< the bound for a live pid on this host (a dying rank
                                     ///< ends well within it; a live run is refused after it)
  std::function<void(const std::string&)> say;  ///< told once per holder that the run waits
};

/// An exclusive lock on DIR/run.lock (flock), held until the object goes away or the process
/// ends (also by SIGKILL: the kernel releases it once every process holding it is gone). The
/// file holds the holder's host and pid.
class RunLock {
 public:
  /// Locks `dir` (which must exist), waiting as `wait` says while another process holds it;
  /// throws Error(output_file) naming the directory and the holder when the wait runs out.
  /// Where the file system has no locks (some cluster file systems), sets `*warning` (when
  /// given) and holds nothing.
  explicit RunLock(const std::string& dir, const RunLockWait& wait = {},
                   std::string* warning = nullptr);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  /// The lock file's path.
  static std::string pathIn(const std::string& dir);

 private:
  int fd_ = -1;
};

}  // namespace cambrian
