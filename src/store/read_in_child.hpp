// cambrian: a file's read tried first in a child process, so that libhdf5's own faults on a
// damaged file (HDF5 1.10 crashes and loops forever on some damaged global heaps) end that child,
// never the reading process. Private to src/store.
#pragma once

#include "cambrian/error.hpp"

#include <functional>
#include <string>

namespace cambrian {

/// Runs `read` (every HDF5 call a reader makes on `path`) in a forked child first. Returns when
/// the child's read ended, normally or by throwing cambrian::Error: the caller then reads for
/// real and meets the same result. Throws Error(`code`) naming the file when the child was
/// killed by a signal, ended without reporting, or did not end within the bound: 20 s plus one
/// second per 4 MiB of file (a healthy file reads far faster). The environment variable
/// CAMBRIAN_READ_SECONDS replaces the 20 s (tests); 0 reads in this process only (a debugger, the
/// fuzz targets, which look for faults in this very code). Where fork fails, reads here only.
void readInChildFirst(const std::string& path, ExitCode code, const std::function<void()>& read);

/// The bound readInChildFirst puts on a read of `path`, in seconds (0: no child).
unsigned childReadSeconds(const std::string& path);

}  // namespace cambrian
