#include "store/read_in_child.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cambrian {

namespace {

// the child's one-byte report: its read returned or threw cambrian::Error
constexpr char kReadEnded = 'R';

void closeQuietly(int fd) {
  if (fd >= 0)
    ::close(fd);
}

// how a child ended: its report (one byte) and its wait status, or neither by the deadline
struct ChildEnd {
  bool reported = false;
  bool ended = false;
  int status = 0;
};

// watches the report pipe and the child itself until both are done or the deadline passes;
// never blocks past the deadline, whatever the pipe does
ChildEnd awaitChild(pid_t child, int fd, std::chrono::steady_clock::time_point deadline) {
  ChildEnd end;
  bool pipe_open = true;
  for (;;) {
    if (!end.ended) {
      pid_t done = ::waitpid(child, &end.status, WNOHANG);
      end.ended = done == child || (done < 0 && errno == ECHILD);
    }
    if (end.ended && !pipe_open)
      return end;
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      return end;
    int wait_ms = static_cast<int>(std::min<long long>(left.count(), 20));
    if (!pipe_open) {
      ::poll(nullptr, 0, wait_ms);
      continue;
    }
    pollfd watched{fd, POLLIN, 0};
    int ready = ::poll(&watched, 1, wait_ms);
    if (ready <= 0)
      continue;
    // one byte, or the end of the pipe (the child is gone or closed it)
    char byte = 0;
    ssize_t n = ::read(fd, &byte, 1);
    if (n < 0 && (errno == EINTR || errno == EAGAIN))
      continue;
    end.reported = end.reported || (n == 1 && byte == kReadEnded);
    pipe_open = n > 0 && !end.reported;
  }
}

std::string signalName(int number) {
  const char* name = ::strsignal(number);
  return "signal " + std::to_string(number) + (name ? std::string(" (") + name + ")" : "");
}

}  // namespace

unsigned childReadSeconds(const std::string& path) {
  // tests shorten the base, and 0 turns the child off
  unsigned base = 20;
  if (const char* text = std::getenv("CAMBRIAN_READ_SECONDS"); text && *text) {
    int value = std::atoi(text);
    if (value <= 0)
      return 0;
    base = static_cast<unsigned>(value);
  }
  std::error_code error;
  std::uintmax_t size = std::filesystem::file_size(path, error);
  return base + (error ? 0u : static_cast<unsigned>(size / (4u << 20)));
}

void readInChildFirst(const std::string& path, ExitCode code, const std::function<void()>& read) {
  unsigned seconds = childReadSeconds(path);
  if (seconds == 0)
    return;
  int pipe_fds[2] = {-1, -1};
  if (::pipe(pipe_fds) != 0)
    return;
  pid_t child = ::fork();
  if (child < 0) {
    closeQuietly(pipe_fds[0]);
    closeQuietly(pipe_fds[1]);
    return;
  }
  if (child == 0) {
    // the child: read, report, and leave without running the parent's exit handlers
    ::close(pipe_fds[0]);
    try {
      read();
    } catch (const Error&) {
    } catch (...) {
      ::_exit(3);
    }
    [[maybe_unused]] ssize_t n = ::write(pipe_fds[1], &kReadEnded, 1);
    ::_exit(0);
  }

  // the parent: wait for the report and the child within the bound; past it, end the child
  ::close(pipe_fds[1]);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  ChildEnd end = awaitChild(child, pipe_fds[0], deadline);
  ::close(pipe_fds[0]);
  if (!end.ended) {
    ::kill(child, SIGKILL);
    while (::waitpid(child, &end.status, 0) < 0 && errno == EINTR) {
    }
  }
  if (end.reported)
    return;
  if (!end.ended)
    throw Error(code, path + ": reading the file did not end within " + std::to_string(seconds) +
                          " s: a damaged file that sends HDF5 into an endless loop");
  int status = end.status;
  std::string how = WIFSIGNALED(status) ? signalName(WTERMSIG(status))
                                        : "exit status " + std::to_string(WEXITSTATUS(status));
  throw Error(code, path + ": reading the file crashed the HDF5 library (in a child process, " +
                        how + "): the file is damaged");
}

}  // namespace cambrian
