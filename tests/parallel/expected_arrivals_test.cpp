#include "parallel/expected_arrivals.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

namespace cambrian {
namespace {

using Clock = ExpectedArrivals::Clock;
using std::chrono::microseconds;

// `count` results of `seconds` each from worker 1, which keeps one creature held
void feed(ExpectedArrivals& arrivals, int count, double seconds) {
  for (int i = 0; i < count; ++i)
    arrivals.resultCame(1, 1, seconds);
}

TEST(ExpectedArrivals, GivesNothingUntilEnoughEvaluationsAreKnown) {
  ExpectedArrivals arrivals(3);
  auto now = Clock::now();
  arrivals.handed(1, 0, now);
  feed(arrivals, static_cast<int>(ExpectedArrivals::kLeast) - 1, 0.01);
  EXPECT_EQ(arrivals.shortestSeconds(), 0);
  EXPECT_EQ(arrivals.microsToEarliest({0, 1, 0}, now), 0);
}

TEST(ExpectedArrivals, AnIdleWorkerHandedACreatureAnswersNoSoonerThanTheShortest) {
  ExpectedArrivals arrivals(3);
  feed(arrivals, 64, 0.01);
  EXPECT_DOUBLE_EQ(arrivals.shortestSeconds(), 0.01);
  auto now = Clock::now();
  arrivals.handed(2, 0, now);
  // worker 1's creature began at the last empty look (construction): it sets no later bound
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 1}, now), 10000);
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 1}, now + microseconds(4000)), 6000);
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 1}, now + microseconds(12000)), 0);
  // nobody holding anything: nothing is expected
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 0}, now), 0);
}

TEST(ExpectedArrivals, AQueuedCreatureBeganWhenTheOneBeforeEndedAtTheEarliest) {
  ExpectedArrivals arrivals(2);
  // 10 ms evaluations known; the worker handed two creatures while idle, at t0
  for (int i = 0; i < 64; ++i)
    arrivals.resultCame(1, 0, 0.01);
  auto t0 = Clock::now();
  arrivals.handed(1, 0, t0);
  arrivals.handed(1, 1, t0);
  EXPECT_EQ(arrivals.microsToEarliest({0, 2}, t0), 10000);
  // the first came in after a look at 2 ms: the second began when the first ended, at 10 ms
  arrivals.foundNothing(t0 + microseconds(2000));
  arrivals.resultCame(1, 1, 0.01);
  EXPECT_EQ(arrivals.microsToEarliest({0, 1}, t0 + microseconds(10000)), 10000);
  // handed a third; the second came in after a look at 25 ms, later than its 20 ms end: the
  // third began after that look
  arrivals.handed(1, 1, t0 + microseconds(12000));
  arrivals.foundNothing(t0 + microseconds(25000));
  arrivals.resultCame(1, 1, 0.01);
  EXPECT_EQ(arrivals.microsToEarliest({0, 1}, t0 + microseconds(25000)), 10000);
  // a worker whose creatures are all back begins nothing; a later hand-out to it, idle, counts
  arrivals.resultCame(1, 0, 0.01);
  arrivals.handed(1, 0, t0 + microseconds(50000));
  EXPECT_EQ(arrivals.microsToEarliest({0, 1}, t0 + microseconds(50000)), 10000);
}

TEST(ExpectedArrivals, TheEarliestWorkerDecides) {
  ExpectedArrivals arrivals(4);
  feed(arrivals, 64, 0.002);
  auto now = Clock::now();
  arrivals.handed(2, 0, now);
  arrivals.handed(3, 0, now + microseconds(500));
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 1, 1}, now), 2000);
  EXPECT_EQ(arrivals.microsToEarliest({0, 0, 0, 1}, now), 2500);
}

TEST(ExpectedArrivals, TheShortestIsALowQuantileSoOneQuickFailureDoesNotDecide) {
  ExpectedArrivals arrivals(2);
  feed(arrivals, 63, 0.01);
  arrivals.resultCame(1, 1, 0.0);
  EXPECT_DOUBLE_EQ(arrivals.shortestSeconds(), 0.01);
  // but a few in the window do: then it looks as early as they end
  for (int i = 0; i < 3; ++i)
    arrivals.resultCame(1, 1, 0.001);
  EXPECT_DOUBLE_EQ(arrivals.shortestSeconds(), 0.001);
  // and the window forgets them
  feed(arrivals, 64, 0.01);
  EXPECT_DOUBLE_EQ(arrivals.shortestSeconds(), 0.01);
}

}  // namespace
}  // namespace cambrian
