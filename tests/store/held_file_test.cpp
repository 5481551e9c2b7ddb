// Tests of the file a writer holds open: its path checked against it (same, deleted, replaced)
// and its contents copied back from the descriptor.
#include "store/held_file.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace cambrian {
namespace {

std::string tempDir(const std::string& name) {
  std::string dir = testing::TempDir() + "/cambrian_held_file_test_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string contents(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

TEST(HeldFile, TellsTheSameFileADeletedOneAndAReplacedOne) {
  std::string dir = tempDir("state");
  std::string path = dir + "/history.h5";
  std::ofstream(path) << "rows";
  int fd = ::open(path.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  EXPECT_EQ(pathStateOf(fd, path), PathState::same);
  std::filesystem::rename(path, dir + "/moved.h5");
  EXPECT_EQ(pathStateOf(fd, path), PathState::missing);
  std::ofstream(path) << "another file";
  EXPECT_EQ(pathStateOf(fd, path), PathState::replaced);
  ::close(fd);
}

TEST(HeldFile, ADeletedFileIsCopiedBackWholeFromItsDescriptor) {
  std::string dir = tempDir("copy");
  std::string path = dir + "/history.h5";
  std::string bytes(3 << 20, '\0');  // more than one buffer of the copy
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>(i * 131 % 251);
  std::ofstream(path, std::ios::binary) << bytes;
  int fd = ::open(path.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  std::filesystem::remove(path);
  copyOpenFileTo(fd, path);
  EXPECT_EQ(contents(path), bytes);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

  // nowhere to write: an error naming the path and the reason, nothing left behind
  try {
    copyOpenFileTo(fd, dir + "/gone/history.h5");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::output_file);
    std::string message = e.what();
    EXPECT_NE(message.find(dir + "/gone/history.h5: cannot create"), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  ::close(fd);
}

}  // namespace
}  // namespace cambrian
