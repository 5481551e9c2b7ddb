// cambrian: a file a writer holds open across generations, checked against its path: deleted or
// replaced under the writer (a user's rm, a cleanup script), its contents are saved from the
// open descriptor instead of being written on into a file nobody can reach.
#pragma once

#include <string>

namespace cambrian {

/// What `path` is to the open file `fd`.
enum class PathState {
  same,      ///< `path` names the open file
  missing,   ///< nothing at `path` (the file was deleted)
  replaced,  ///< another file at `path`
};

/// What `path` is to the open file `fd`; `same` when either cannot be examined.
PathState pathStateOf(int fd, const std::string& path);

/// Copies everything of the open file `fd` to `path` (a temporary file beside it, synced, then
/// renamed into place). Throws Error(output_file) naming `path` and the system's reason.
void copyOpenFileTo(int fd, const std::string& path);

}  // namespace cambrian
