// cambrian: the CPU time this process has used (for rank 0's cost in the history).
#pragma once

namespace cambrian {

/// CPU time (user + system) this process has used so far, seconds (getrusage).
double processCpuSeconds();

}  // namespace cambrian
