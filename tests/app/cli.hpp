// test helper: run the cambrian executable and capture what it prints and returns
#pragma once

#include "cambrian/error.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace cambrian::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

/// Runs `cambrian <arguments>` from the build tree (a shell command line; quote as needed).
inline CommandResult runCambrian(const std::string& arguments) {
  std::string command =
      std::string(CAMBRIAN_BINARY_DIR) + "/src/app/cambrian " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
    return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), n);
  }
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// An exit code as the process returns it.
inline int code(ExitCode c) {
  return static_cast<int>(c);
}

/// The line of `output` that starts with `key`, or "".
inline std::string lineStartingWith(const std::string& output, const std::string& key) {
  std::size_t at = output.find("\n" + key);
  if (output.compare(0, key.size(), key) == 0)
    at = 0;
  else if (at == std::string::npos)
    return "";
  else
    at += 1;
  return output.substr(at, output.find('\n', at) - at);
}

/// The number after `key` on its line of `output` (a `simulate` summary), or -1 without one.
inline double valueAfter(const std::string& output, const std::string& key) {
  const std::string line = lineStartingWith(output, key);
  return line.empty() ? -1.0 : std::stod(line.substr(key.size()));
}

}  // namespace cambrian::test
