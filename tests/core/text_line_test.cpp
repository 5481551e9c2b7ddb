// Tests of the line-oriented text forms' reader: tokens, strict numbers, and the statement frame
// (header and version, `end`, nothing after it, nothing left on a line).
#include "core/text_line.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cambrian {
namespace {

// the message readStatements throws for `text` (a form "demo 2" of `value` statements), or ""
std::string failure(const std::string& text, std::vector<double>* values = nullptr) {
  try {
    readStatements(text, "demo.txt", "demo", 2, "value, end",
                   [&](const std::string& keyword, TextLine& line) {
                     if (keyword != "value")
                       return false;
                     const double value = line.number("value");
                     if (values)
                       values->push_back(value);
                     return true;
                   });
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TextLine, TokensStopAtAComment) {
  const std::vector<std::string_view> tokens = tokenizeLine("  node a\t1.5 # a comment");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0], "node");
  EXPECT_EQ(tokens[2], "1.5");
}

TEST(TextLine, StatementsBetweenTheHeaderAndEndAreRead) {
  std::vector<double> values;
  EXPECT_EQ(failure("# comment\n\ndemo 2\nvalue 1.5\nvalue -2 # note\nend\n", &values), "");
  EXPECT_EQ(values, (std::vector<double>{1.5, -2}));
  // an older version is read too
  EXPECT_EQ(failure("demo 1\nend"), "");
}

TEST(TextLine, EachBrokenFrameIsNamedWithItsLine) {
  EXPECT_EQ(failure(""), "demo.txt: empty (expected the header 'demo 2')");
  EXPECT_EQ(failure("value 1\n"), "demo.txt:1: expected the header 'demo 2', got 'value'");
  EXPECT_EQ(failure("demo 3\nend\n"),
            "demo.txt:1: format version 3 is newer than this cambrian (2)");
  EXPECT_EQ(failure("demo 0\nend\n"), "demo.txt:1: format version 0 does not exist");
  EXPECT_EQ(failure("demo 2\nvalue 1\n"), "demo.txt: no `end` line: the file is cut short");
  EXPECT_EQ(failure("demo 2\nend\nvalue 1\n"), "demo.txt:3: unexpected 'value' after `end`");
  EXPECT_EQ(failure("demo 2\nsize 1\nend\n"),
            "demo.txt:2: unknown statement 'size' (one of: value, end)");
  EXPECT_EQ(failure("demo 2\nvalue 1 2\nend\n"),
            "demo.txt:2: unexpected '2' at the end of the line");
  EXPECT_EQ(failure("demo 2 extra\nend\n"),
            "demo.txt:1: unexpected 'extra' at the end of the line");
}

}  // namespace
}  // namespace cambrian
