// Tests of the byte writer and reader: little-endian layout, exact doubles, bounds and messages.
#include "core/bytes.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cambrian {
namespace {

TEST(Bytes, LittleEndianLayout) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.u8(0xab);
  w.u16(0x0102);
  w.u32(0x03040506);
  w.u64(0x0708090a0b0c0d0eULL);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0xab, 0x02, 0x01, 0x06, 0x05, 0x04, 0x03, 0x0e, 0x0d,
                                            0x0c, 0x0b, 0x0a, 0x09, 0x08, 0x07}));
}

TEST(Bytes, RoundTripKeepsEveryBit) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  w.f64(-0.0);
  w.f64(nan);
  w.f64(1.0 / 3.0);
  w.vec3(Vec3{1, -2, 3.5});
  w.i64(-5);
  w.text("héllo");
  w.blob(nullptr, 0);
  ByteReader r(out.data(), out.size(), "test bytes");
  double zero = r.f64();
  EXPECT_TRUE(std::signbit(zero));
  EXPECT_TRUE(std::isnan(r.f64()));
  EXPECT_EQ(r.f64(), 1.0 / 3.0);
  EXPECT_EQ(r.vec3(), (Vec3{1, -2, 3.5}));
  EXPECT_EQ(r.i64(), -5);
  EXPECT_EQ(r.text(), "héllo");
  EXPECT_TRUE(r.blob().empty());
  EXPECT_NO_THROW(r.expectEnd());
}

TEST(Bytes, TruncationNamesTheFormTheContextAndTheOffset) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.u32(7);
  ByteReader r(out.data(), 3, "genome bytes");
  r.context("node 2 neurons");
  try {
    r.u32();
    FAIL() << "read past the end";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "genome bytes: truncated in node 2 neurons (offset 0 of 3)");
  }
}

TEST(Bytes, CountsFlagsAndTrailingBytesAreChecked) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.u32(1000);  // a count of 1000 elements of 8 bytes, with 2 bytes left
  w.u8(0);
  w.u8(2);
  ByteReader counts(out.data(), out.size(), "x");
  EXPECT_THROW(counts.count(8), InputError);
  ByteReader flags(out.data() + 4, 2, "x");
  EXPECT_FALSE(flags.flag("first"));
  EXPECT_THROW(flags.flag("second"), InputError);
  ByteReader trailing(out.data(), out.size(), "x");
  trailing.u32();
  EXPECT_THROW(trailing.expectEnd(), InputError);
  EXPECT_THROW(ByteReader(nullptr, 4, "x"), InputError);
}

}  // namespace
}  // namespace cambrian
