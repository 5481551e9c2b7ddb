// cambrian: process CPU time from getrusage.
#include "core/cpu_time.hpp"

#include <sys/resource.h>

namespace cambrian {

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace cambrian
