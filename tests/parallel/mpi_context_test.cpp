// Tests of the MPI facade that need a running job, at every rank count CTest gives it
// (mpi_context_np_N): split contexts (the islands' communicators) hold the ranks of one color in
// order, keep their messages to themselves and reduce over their own ranks only; Open MPI does
// not yield the core at each empty probe where every worker has a core of its own.
#include "parallel/mpi_context.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace cambrian {

extern MpiContext* world;  // the job's context (mpi_test_main.cpp)

namespace {

TEST(MpiContext, SplitHoldsTheRanksOfOneColorInOrder) {
  const int color = world->rank() % 2;
  std::unique_ptr<MpiContext> half = world->split(color);
  ASSERT_TRUE(half);
  EXPECT_EQ(half->rank(), world->rank() / 2);
  EXPECT_EQ(half->size(), (world->size() - color + 1) / 2);
  // a rank that gives no color joins none
  std::unique_ptr<MpiContext> roots = world->split(world->rank() == 0 ? 0 : -1);
  EXPECT_EQ(static_cast<bool>(roots), world->rank() == 0);
  if (roots) {
    EXPECT_EQ(roots->size(), 1);
  }
}

TEST(MpiContext, MessagesAndReductionsStayInTheirContext) {
  const int color = world->rank() % 2;
  std::unique_ptr<MpiContext> half = world->split(color);
  ASSERT_TRUE(half);
  // each half's last rank sends its color to its first; the first receives only that
  if (half->size() > 1 && half->rank() == half->size() - 1)
    half->send(0, Tag::result, {static_cast<std::uint8_t>(color)});
  if (half->size() > 1 && half->rank() == 0) {
    Message message = half->receiveAny(-1);
    EXPECT_EQ(message.source, half->size() - 1);
    EXPECT_EQ(message.tag, Tag::result);
    EXPECT_EQ(message.bytes, std::vector<std::uint8_t>{static_cast<std::uint8_t>(color)});
  }
  // the largest world rank of each half
  const int largest = half->allReduceMax(world->rank());
  const int expected = world->size() - 1 - ((world->size() - 1) % 2 == color ? 0 : 1);
  EXPECT_EQ(largest, expected);
  // the world context saw none of it
  Message stray;
  EXPECT_FALSE(world->tryReceiveAny(-1, stray));
  EXPECT_EQ(world->allReduceMax(world->rank()), world->size() - 1);
}

TEST(MpiContext, TheCoreIsKeptWhereEveryWorkerHasOne) {
  // rank 0 and a worker per core, or fewer: kept
  EXPECT_TRUE(keepCoreWhenIdle(1, 1));
  EXPECT_TRUE(keepCoreWhenIdle(2, 2));
  EXPECT_TRUE(keepCoreWhenIdle(3, 2));
  EXPECT_TRUE(keepCoreWhenIdle(17, 16));
  // more workers than cores, or nothing known: Open MPI's choice
  EXPECT_FALSE(keepCoreWhenIdle(4, 2));
  EXPECT_FALSE(keepCoreWhenIdle(129, 2));
  EXPECT_FALSE(keepCoreWhenIdle(0, 2));
  EXPECT_FALSE(keepCoreWhenIdle(3, 0));
  EXPECT_GE(usableCores(), 1);
}

TEST(MpiContext, OpenMpiKeepsTheCoreWhereEveryWorkerHasOne) {
  // the tests run at 1 to 4 ranks with --oversubscribe, where Open MPI's default is to yield
  // once the ranks outnumber the cores
  const int value = world->yieldWhenIdle();
  if (value < 0)
    GTEST_SKIP() << "this MPI has no mpi_yield_when_idle";
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (local == nullptr)
    GTEST_SKIP() << "not started by Open MPI's mpiexec";
  const char* given = std::getenv("OMPI_MCA_mpi_yield_when_idle");
  if (given == nullptr) {
    // left to Open MPI only where the ranks outnumber the cores by more than rank 0
    EXPECT_FALSE(keepCoreWhenIdle(std::atoi(local), usableCores()))
        << local << " ranks on " << usableCores() << " cores";
    return;
  }
  // ours ("0") or the user's (mpiexec --mca), as Open MPI reads it
  const std::string text = given;
  const bool yes = text == "1" || text == "true" || text == "yes" || text == "enabled" ||
                   text == "t" || text == "y";
  EXPECT_EQ(value, yes ? 1 : 0) << "OMPI_MCA_mpi_yield_when_idle = " << text;
}

}  // namespace
}  // namespace cambrian
