// cambrian: what this process has used (rank 0's cost in the history, memory in the summary).
#pragma once

#include <cstdint>

namespace cambrian {

/// CPU time (user + system) this process has used so far, seconds (getrusage).
double processCpuSeconds();

/// The most resident memory this process has held so far, bytes (getrusage's ru_maxrss).
std::uint64_t processPeakResidentBytes();

}  // namespace cambrian
