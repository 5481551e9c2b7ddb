// Tests of the MPI facade that need a running job, at every rank count CTest gives it
// (mpi_context_np_N): split contexts (the islands' communicators) hold the ranks of one color in
// order, keep their messages to themselves and reduce over their own ranks only; Open MPI does
// not yield the core at each empty probe, also where the ranks outnumber the cores.
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

TEST(MpiContext, OpenMpiDoesNotYieldTheCoreAtEmptyProbes) {
  // the tests run oversubscribed (more ranks than cores), where Open MPI's default is to yield;
  // a value given in the environment (mpiexec --mca) is the user's and stays
  const int value = world->yieldWhenIdle();
  if (value < 0)
    GTEST_SKIP() << "this MPI has no mpi_yield_when_idle";
  const char* given = std::getenv("OMPI_MCA_mpi_yield_when_idle");
  ASSERT_NE(given, nullptr);  // set before MPI_Init where nobody had
  const std::string text = given;
  const bool yes = text == "1" || text == "true" || text == "yes" || text == "enabled" ||
                   text == "t" || text == "y";
  EXPECT_EQ(value, yes ? 1 : 0) << "OMPI_MCA_mpi_yield_when_idle = " << text;
}

}  // namespace
}  // namespace cambrian
