#include "parallel/expected_arrivals.hpp"

#include <algorithm>

namespace cambrian {

ExpectedArrivals::ExpectedArrivals(int ranks)
    : began_(static_cast<std::size_t>(std::max(ranks, 1))), last_empty_look_(Clock::now()) {}

void ExpectedArrivals::handed(int worker, int held_before, Clock::time_point now) {
  // an idle worker begins once the request is there; a busy one when its creatures before end
  if (held_before == 0)
    began_.at(static_cast<std::size_t>(worker)) = now;
}

void ExpectedArrivals::resultCame(int worker, int held_after, double seconds) {
  // its next creature began when this one ended: after the last look that did not see it, and
  // no sooner than this one's earliest beginning and its own time
  if (held_after > 0) {
    Clock::time_point& began = began_.at(static_cast<std::size_t>(worker));
    began = std::max(last_empty_look_,
                     began + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(std::max(0.0, seconds))));
  }
  recent_[seen_ % kWindow] = seconds;
  ++seen_;
  if (seen_ < kLeast)
    return;
  // the low quantile of the window (or of what there is of it)
  std::size_t known = std::min(seen_, kWindow);
  std::array<double, kWindow> sorted = recent_;
  std::size_t rank = kQuantile * known / kWindow;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank),
                   sorted.begin() + static_cast<std::ptrdiff_t>(known));
  shortest_ = std::max(0.0, sorted[rank]);
}

long ExpectedArrivals::microsToEarliest(const std::vector<int>& held, Clock::time_point now) const {
  if (shortest_ <= 0)
    return 0;
  auto shortest =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(shortest_));
  auto earliest = Clock::time_point::max();
  for (std::size_t worker = 1; worker < held.size() && worker < began_.size(); ++worker) {
    if (held[worker] > 0)
      earliest = std::min(earliest, began_[worker] + shortest);
  }
  if (earliest == Clock::time_point::max() || earliest <= now)
    return 0;
  return static_cast<long>(
      std::chrono::duration_cast<std::chrono::microseconds>(earliest - now).count());
}

}  // namespace cambrian
