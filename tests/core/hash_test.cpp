// Tests of the one hash function: FNV-1a 64 reference values, continuation, words.
#include "core/hash.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian {
namespace {

TEST(Fnv1a, ReferenceValues) {
  // the published FNV-1a 64 test vectors
  EXPECT_EQ(Fnv1a().value(), 0xcbf29ce484222325ULL);
  Fnv1a a;
  a.add("a", 1);
  EXPECT_EQ(a.value(), 0xaf63dc4c8601ec8cULL);
  Fnv1a foobar;
  foobar.add("foobar", 6);
  EXPECT_EQ(foobar.value(), 0x85944171f73967e8ULL);
  EXPECT_EQ(hashText("foobar"), "85944171f73967e8");
}

TEST(Fnv1a, ContinuesFromASavedValueAndFeedsWordsLittleEndian) {
  Fnv1a whole;
  whole.add("foobar", 6);
  Fnv1a first;
  first.add("foo", 3);
  Fnv1a rest(first.value());
  rest.add("bar", 3);
  EXPECT_EQ(rest.value(), whole.value());

  Fnv1a word, bytes;
  word.addWord(0x0102030405060708ULL);
  const unsigned char le[8] = {8, 7, 6, 5, 4, 3, 2, 1};
  bytes.add(le, 8);
  EXPECT_EQ(word.value(), bytes.value());
  EXPECT_EQ(hex16(0xabc), "0000000000000abc");
}

}  // namespace
}  // namespace cambrian
