// cambrian: reading a small input file whole (a genome, an experiment file), bounded: a
// directory, a device that never ends (/dev/zero) or a file past the bound is refused with the
// reason, never read into memory without limit.
#pragma once

#include <cstddef>
#include <string>

namespace cambrian {

/// A file's bytes, or why they could not be read.
struct SmallFile {
  std::string bytes;
  std::string problem;  ///< empty when `bytes` holds the whole file; else why not ("is a directory,
                        ///< not a file")
};

/// Reads `path` whole when it holds at most `limit` bytes. A pipe or a device is read up to the
/// bound, so a process substitution works and /dev/zero is refused.
SmallFile readSmallFile(const std::string& path, std::size_t limit);

}  // namespace cambrian
