// cambrian: the small MPI facade. The only header whose implementation includes <mpi.h>;
// everything else in the project speaks to MPI through it.
#pragma once

#include "cambrian/error.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

/// Message tags of the evolve protocol.
enum class Tag : int {
  request = 1,   ///< rank 0 -> worker: an EvalRequest
  result = 2,    ///< worker -> rank 0: an EvalResult
  stop = 3,      ///< rank 0 -> worker: no more work, leave the loop
  migrants = 4,  ///< breeding rank -> breeding rank (islands): a batch of emigrants
  needed = 5,    ///< breeding rank -> breeding rank (islands): the first migration its checkpoint
                 ///< still needs
};

/// A received message.
struct Message {
  int source = -1;
  Tag tag = Tag::request;
  std::vector<std::uint8_t> bytes;
};

/// Whether Open MPI's mpi_yield_when_idle is turned off for a job with `local_ranks` ranks on a
/// node where this process may use `cores` cores: where every worker has a core of its own and
/// rank 0, which mostly sleeps, at most shares one (local_ranks <= cores + 1). Open MPI turns it
/// on there (the ranks outnumber the cores by rank 0), and then each probe of rank 0 that found
/// nothing handed its core to a computing worker for a whole time slice: rank 0 fell
/// milliseconds behind and the workers' queues ran dry. With many more ranks than cores
/// (sleeping synthetic workers) yielding lets the rank with a message run sooner, so Open MPI's
/// own choice stays.
bool keepCoreWhenIdle(int local_ranks, int cores);

/// Cores this process may run on: its CPU affinity (the job's share of the node where the
/// launcher did not bind it to one), else the machine's.
int usableCores();

/// Initialises MPI for the life of the object (MPI_Init / MPI_Finalize) and wraps the few calls
/// evolve needs. Waiting never busy-polls: it probes without blocking and sleeps adaptively
/// (50 us growing to 1 ms), so rank 0 can share a core with a worker. On Linux the process'
/// timer slack is set to 1 us, so that those sleeps end when they are due. Open MPI's
/// mpi_yield_when_idle is off where every worker has a core (keepCoreWhenIdle) unless the user
/// sets it.
class MpiContext {
 public:
  /// Calls MPI_Init unless MPI is already initialised.
  MpiContext(int* argc, char*** argv);
  /// Calls MPI_Finalize when this object initialised MPI (a split context frees its
  /// communicator instead).
  ~MpiContext();
  MpiContext(const MpiContext&) = delete;
  MpiContext& operator=(const MpiContext&) = delete;

  /// This process' rank in this context's communicator (MPI_COMM_WORLD unless split).
  int rank() const { return rank_; }
  /// Number of ranks in this context's communicator.
  int size() const { return size_; }
  /// Open MPI's mpi_yield_when_idle as this process runs with it (1: each probe that finds
  /// nothing yields the core), -1 where the MPI has no such setting.
  int yieldWhenIdle() const;
  /// The ranks of this context that give the same `color` (>= 0), ordered as here, as a context
  /// of their own; null for a negative color (the rank joins none). Collective: every rank of
  /// this context calls it. Messages in one context never match receives in another.
  std::unique_ptr<MpiContext> split(int color) const;

  /// Sends `bytes` to `destination` with `tag` (standard-mode send).
  void send(int destination, Tag tag, const std::vector<std::uint8_t>& bytes);
  /// Starts sending `bytes` to `destination` and returns at once (MPI_Isend); the bytes are
  /// kept until the send completes, so a message to a busy rank never blocks or spins the sender.
  void post(int destination, Tag tag, std::vector<std::uint8_t> bytes);
  /// Frees the posted sends that have completed; returns how many are still under way.
  std::size_t completePosted();
  /// Waits (test + adaptive sleep) until every posted send has completed.
  void waitPosted();
  /// Receives a waiting message with `tag` from any rank into `out`; false when none is waiting.
  bool tryReceive(Tag tag, Message& out);
  /// Receives a waiting message of any tag from `source` (any rank when -1); false when none.
  bool tryReceiveAny(int source, Message& out);
  /// How long a wait counts as urgent (receiveAny's `urgent_micros`).
  static constexpr long kUrgentForMicros = 20000;
  /// Waits (probe + adaptive sleep, no spinning, sleeps of at most `longest_sleep_micros`) for a
  /// message of any tag from `source`; with `urgent_micros` > 0, sleeps of at most that for the
  /// first kUrgentForMicros of the wait (a message due soon is taken up soon).
  Message receiveAny(int source, long longest_sleep_micros = 1000, long urgent_micros = 0);
  /// Waits for a message with `tag` from any rank (probe + adaptive sleep).
  Message receive(Tag tag);
  /// The maximum of `value` over all ranks (collective).
  int allReduceMax(int value);
  /// The maximum of `value` over all ranks (collective).
  std::uint64_t allReduceMax(std::uint64_t value);
  /// Every rank's `value`, in rank order (collective).
  std::vector<std::uint64_t> allGather(std::uint64_t value);

  /// Prints "cambrian evolve: rank R: message" to stderr and calls MPI_Abort with `code`, which
  /// ends every rank of the job (of every context) with that exit code. Never returns.
  [[noreturn]] void abort(ExitCode code, const std::string& message) const;

 private:
  struct PostedSends;
  struct Communicator;
  explicit MpiContext(std::unique_ptr<Communicator> communicator);
  int rank_ = 0;
  int size_ = 1;
  bool owns_ = false;
  std::unique_ptr<Communicator> communicator_;
  std::unique_ptr<PostedSends> posted_;
};

/// Sleeps for an adaptively growing interval: call wait() while nothing has arrived and reset()
/// when something did. Starts at 50 us and doubles up to 1 ms, unless given another range.
class Backoff {
 public:
  static constexpr long kMin = 50, kMax = 1000;
  /// The longest sleep while a message is likely on its way (rank 0 waiting on a worker that
  /// holds one creature, a worker waiting for its next).
  static constexpr long kUrgent = 100;
  /// Sleeps for the current interval and grows it.
  void wait();
  /// The longest sleep for a wait that should end within a quarter of `seconds` (an expected
  /// evaluation): from kMin to kMax; kMax when `seconds` is not positive.
  static long quarterOf(double seconds) {
    return seconds > 0 ? std::clamp(static_cast<long>(seconds * 1e6 / 4), kMin, kMax) : kMax;
  }
  /// Back to the shortest interval.
  void reset() { micros_ = floor_; }
  /// Sleeps from `floor` growing to `ceiling` microseconds (equal: the same sleep every time);
  /// the floor is at least 1 us and the ceiling at least the floor.
  void range(long floor, long ceiling) {
    floor_ = std::max(1L, floor);
    ceiling_ = std::max(floor_, ceiling);
    micros_ = std::clamp(micros_, floor_, ceiling_);
  }

 private:
  long floor_ = kMin, ceiling_ = kMax;
  long micros_ = kMin;
};

}  // namespace cambrian
