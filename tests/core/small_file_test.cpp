// Tests of the bounded file reader: a file read whole, a directory, a missing file, a file past
// the bound and an endless device refused with the reason.
#include "core/small_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cambrian {
namespace {

TEST(SmallFile, ReadsAFileWhole) {
  std::string path = testing::TempDir() + "/cambrian_small_file.txt";
  std::string text(100000, 'x');
  text += "\nend\n";
  std::ofstream(path, std::ios::binary) << text;
  SmallFile file = readSmallFile(path, 1 << 20);
  EXPECT_EQ(file.problem, "");
  EXPECT_EQ(file.bytes, text);
  // one byte over the bound
  SmallFile over = readSmallFile(path, text.size() - 1);
  EXPECT_NE(over.problem.find("larger than"), std::string::npos) << over.problem;
  EXPECT_TRUE(over.bytes.empty());
  EXPECT_EQ(readSmallFile(path, text.size()).bytes.size(), text.size());
  std::filesystem::remove(path);
}

TEST(SmallFile, RefusesWhatIsNotASmallFile) {
  EXPECT_EQ(readSmallFile(testing::TempDir(), 1 << 20).problem, "is a directory, not a file");
  SmallFile missing = readSmallFile("/nonexistent/cambrian.ini", 1 << 20);
  EXPECT_NE(missing.problem.find("cannot be opened"), std::string::npos) << missing.problem;
  // an endless device stops at the bound
  SmallFile endless = readSmallFile("/dev/zero", 1 << 16);
  EXPECT_NE(endless.problem.find("never ends"), std::string::npos) << endless.problem;
  EXPECT_TRUE(endless.bytes.empty());
}

}  // namespace
}  // namespace cambrian
