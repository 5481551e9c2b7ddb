// The main of the tests that need a running MPI job (mpi_context_test, archipelago_test): every
// rank runs every test, and a failure on any rank fails the job.
#include "parallel/mpi_context.hpp"

#include <gtest/gtest.h>

namespace cambrian {
MpiContext* world = nullptr;  // the job's context, for the tests
}  // namespace cambrian

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  cambrian::MpiContext world(&argc, &argv);
  cambrian::world = &world;
  int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  return world.allReduceMax(failed);
}
