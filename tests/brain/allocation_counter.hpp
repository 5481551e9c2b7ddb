// Test helper: counts the heap allocations of the test binary it is linked into.
#pragma once

/// Number of calls to the global operator new so far (replaced in allocation_counter.cpp).
long allocationCount();
