// Tests of what the process has used: the peak resident memory covers what was touched.
#include "core/process_usage.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace cambrian {
namespace {

TEST(ProcessUsage, PeakResidentMemoryCoversWhatWasTouched) {
  const std::uint64_t before = processPeakResidentBytes();
  EXPECT_GT(before, 0u);
  constexpr std::size_t kTouched = 64 << 20;
  auto block = std::make_unique<char[]>(kTouched);
  std::memset(block.get(), 1, kTouched);
  volatile char keep = block[kTouched - 1];
  (void)keep;
  EXPECT_GE(processPeakResidentBytes(), kTouched);
  EXPECT_GE(processPeakResidentBytes(), before);
}

}  // namespace
}  // namespace cambrian
