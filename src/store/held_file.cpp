#include "store/held_file.hpp"

#include "cambrian/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace cambrian {

PathState pathStateOf(int fd, const std::string& path) {
  struct stat held {};
  struct stat named {};
  if (::fstat(fd, &held) != 0)
    return PathState::same;
  if (::stat(path.c_str(), &named) != 0)
    return errno == ENOENT ? PathState::missing : PathState::same;
  return named.st_dev == held.st_dev && named.st_ino == held.st_ino ? PathState::same
                                                                    : PathState::replaced;
}

void copyOpenFileTo(int fd, const std::string& path) {
  std::string temporary = path + ".tmp";
  auto fail = [&](const std::string& what) {
    std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw Error(ExitCode::output_file, path + ": " + what + ": " + reason);
  };
  int out = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0)
    fail("cannot create " + temporary);

  // every byte, read by offset (the writer's own file position is left alone)
  std::vector<char> buffer(1 << 20);
  off_t offset = 0;
  for (;;) {
    ssize_t n = ::pread(fd, buffer.data(), buffer.size(), offset);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0) {
      ::close(out);
      fail("cannot read the open file");
    }
    if (n == 0)
      break;
    for (ssize_t written = 0; written < n;) {
      ssize_t w = ::write(out, buffer.data() + written, static_cast<std::size_t>(n - written));
      if (w < 0 && errno == EINTR)
        continue;
      if (w < 0) {
        ::close(out);
        fail("cannot write " + temporary);
      }
      written += w;
    }
    offset += n;
  }
  if (::fsync(out) != 0) {
    ::close(out);
    fail("cannot sync " + temporary);
  }
  if (::close(out) != 0)
    fail("cannot close " + temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    fail("cannot rename " + temporary + " into place");
}

}  // namespace cambrian
