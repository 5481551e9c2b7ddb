// Test helper: replaces the global operator new so a test can show a code path does not
// allocate. Kept in its own file so the compiler never sees new and free side by side.
#include "brain/allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
// calls to operator new in this process
std::atomic<long> allocation_count{0};
}  // namespace

long allocationCount() {
  return allocation_count.load(std::memory_order_relaxed);
}

void* operator new(std::size_t size) {
  // count, then allocate like the default
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* memory = std::malloc(size == 0 ? 1 : size)) {
    return memory;
  }
  throw std::bad_alloc();
}

void operator delete(void* memory) noexcept {
  std::free(memory);
}

void operator delete(void* memory, std::size_t) noexcept {
  std::free(memory);
}
