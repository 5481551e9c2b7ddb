// cambrian: when rank 0 can next expect a worker's result, so that it sleeps until then rather
// than looking again and again before any result can be there.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <vector>

namespace cambrian {

/// The earliest time a result can come in. A worker's creature began when its previous one ended:
/// no earlier than rank 0's last look that found nothing before that result came in, nor than
/// the previous one's own earliest beginning plus its evaluation time; or, when the worker was
/// idle, no earlier than its hand-out. No evaluation ends sooner than
/// a low quantile (kQuantile) of the last kWindow evaluations. Rank 0 sleeps at least until the
/// earliest of those over the workers holding creatures. A pure bookkeeper: it sends nothing.
class ExpectedArrivals {
 public:
  using Clock = std::chrono::steady_clock;
  /// Evaluations the shortest is taken over, and their rank taken as "no sooner than" (the 4th
  /// shortest of 64: about the 5th percentile).
  static constexpr std::size_t kWindow = 64, kQuantile = 3;
  /// Evaluations seen before any estimate is given.
  static constexpr std::size_t kLeast = 16;

  /// For ranks 0 .. `ranks` - 1 (rank 0 holds nothing).
  explicit ExpectedArrivals(int ranks);
  /// Rank 0 looked at `now` and found no result.
  void foundNothing(Clock::time_point now) { last_empty_look_ = now; }
  /// `worker`, which held `held_before` creatures, was handed one at `now`.
  void handed(int worker, int held_before, Clock::time_point now);
  /// A result of `worker` came in after an evaluation of `seconds`; it now holds `held_after`.
  void resultCame(int worker, int held_after, double seconds);
  /// Microseconds from `now` to the earliest a result can come from a worker that holds
  /// creatures (`held` by rank); 0 when one may be there already or too little is known.
  long microsToEarliest(const std::vector<int>& held, Clock::time_point now) const;
  /// The low quantile of the recent evaluations, seconds (0 while fewer than kLeast are known).
  double shortestSeconds() const { return shortest_; }

 private:
  std::vector<Clock::time_point> began_;  // the earliest its current creature began, by rank
  Clock::time_point last_empty_look_;
  std::array<double, kWindow> recent_{};  // the last evaluations' seconds, a ring
  std::size_t seen_ = 0;
  double shortest_ = 0;
};

}  // namespace cambrian
