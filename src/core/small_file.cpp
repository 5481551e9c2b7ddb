// cambrian: reading a small input file whole, bounded.
#include "core/small_file.hpp"

#include <filesystem>
#include <fstream>

namespace cambrian {

SmallFile readSmallFile(const std::string& path, std::size_t limit) {
  SmallFile file;
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error) {
    file.problem = "cannot be opened (" + error.message() + ")";
    return file;
  }
  if (std::filesystem::is_directory(status)) {
    file.problem = "is a directory, not a file";
    return file;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    file.problem = "cannot be opened";
    return file;
  }
  // in blocks, so that a device or a pipe stops at the bound
  char block[65536];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    file.bytes.append(block, static_cast<std::size_t>(in.gcount()));
    if (file.bytes.size() > limit) {
      file.bytes.clear();
      file.problem = "is larger than " + std::to_string(limit) + " bytes (or never ends)";
      return file;
    }
  }
  if (in.bad()) {
    file.bytes.clear();
    file.problem = "cannot be read";
  }
  return file;
}

}  // namespace cambrian
