// Fuzz targets: the fuzzer's bytes as a file, for the readers that take a path (genome files,
// experiment files, checkpoint and history files). One file per process and target, rewritten on
// every input and removed at exit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace cambrian::fuzz {

class FuzzFile {
 public:
  /// A path in the temporary folder ($TMPDIR) named after `name` and the process.
  explicit FuzzFile(const std::string& name)
      : path_((std::filesystem::temp_directory_path() /
               ("cambrian-fuzz-" + std::to_string(::getpid()) + "-" + name))
                  .string()) {}
  ~FuzzFile() { std::remove(path_.c_str()); }
  FuzzFile(const FuzzFile&) = delete;
  FuzzFile& operator=(const FuzzFile&) = delete;

  /// Replaces the file's content by `size` bytes at `data`; returns the path.
  const std::string& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out)
      throw std::runtime_error(path_ + ": the fuzz target cannot write its input file");
    return path_;
  }

 private:
  std::string path_;
};

}  // namespace cambrian::fuzz
