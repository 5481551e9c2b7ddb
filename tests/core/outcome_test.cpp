// Tests of outcomes: names, lookups by measure name, and the one byte form.
#include "cambrian/outcome.hpp"

#include "cambrian/error.hpp"

#include "core/outcome_bytes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace cambrian {
namespace {

Outcome sample() {
  Outcome o;
  o.status = EvalStatus::exploded;
  o.fitness = -0.0;
  o.steps = 1234;
  o.wall_seconds = 0.5;
  o.parts = 3;
  o.joints = 2;
  o.neurons = 11;
  o.message = "part 2 moved at 60 m/s";
  o.measures = {{"distance", 1.0 / 3.0}, {"height", std::nan("")}};
  return o;
}

TEST(Outcome, MeasuresByName) {
  Outcome o = sample();
  EXPECT_EQ(o.measure("distance"), 1.0 / 3.0);
  EXPECT_TRUE(std::isnan(o.measure("absent")));
  EXPECT_STREQ(statusName(EvalStatus::self_penetration), "self_penetration");
  EXPECT_STREQ(statusName(static_cast<EvalStatus>(99)), "unknown");
}

// every status has a name of its own; the count ends the list
TEST(Outcome, EveryStatusHasItsOwnName) {
  std::vector<std::string> names;
  for (int i = 0; i < kEvalStatusKinds; ++i) {
    const std::string name = statusName(static_cast<EvalStatus>(i));
    EXPECT_NE(name, "unknown") << i;
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 0) << name;
    names.push_back(name);
  }
  EXPECT_EQ(names.back(), "dismembered");
  EXPECT_STREQ(statusName(static_cast<EvalStatus>(kEvalStatusKinds)), "unknown");
}

TEST(Outcome, ByteFormRoundTripsEveryFieldBitForBit) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  writeOutcome(w, sample());
  ByteReader r(bytes.data(), bytes.size(), "outcome");
  Outcome back = readOutcome(r);
  r.expectEnd();
  Outcome o = sample();
  EXPECT_EQ(back.status, o.status);
  EXPECT_TRUE(std::signbit(back.fitness));
  EXPECT_EQ(back.steps, o.steps);
  EXPECT_EQ(back.wall_seconds, o.wall_seconds);
  EXPECT_EQ(back.parts, 3);
  EXPECT_EQ(back.joints, 2);
  EXPECT_EQ(back.neurons, 11);
  EXPECT_EQ(back.message, o.message);
  ASSERT_EQ(back.measures.size(), 2u);
  EXPECT_EQ(back.measures[0], o.measures[0]);
  EXPECT_EQ(back.measures[1].name, "height");
  EXPECT_TRUE(std::isnan(back.measures[1].value));
}

TEST(Outcome, BadBytesAreRefused) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  writeOutcome(w, sample());
  // every truncation
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    ByteReader r(bytes.data(), size, "outcome");
    EXPECT_THROW(
        {
          readOutcome(r);
          r.expectEnd();
        },
        InputError)
        << size;
  }
  // an unknown status
  std::vector<std::uint8_t> bad = bytes;
  bad[0] = 200;
  ByteReader r(bad.data(), bad.size(), "outcome");
  EXPECT_THROW(readOutcome(r), InputError);
}

// a body count beyond an int is refused, not cut to 32 bits (found by fuzzing: such a result
// was accepted and written back to other bytes)
TEST(Outcome, BodyCountsBeyondAnIntAreRefused) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  writeOutcome(w, sample());
  // parts, joints, neurons follow status, fitness, steps and wall_seconds (8 bytes each)
  for (std::size_t field = 0; field < 3; ++field) {
    std::vector<std::uint8_t> bad = bytes;
    bad[32 + 8 * field + 4] = 1;  // 2^32 more
    ByteReader r(bad.data(), bad.size(), "outcome");
    EXPECT_THROW(readOutcome(r), InputError) << field;
  }
}

}  // namespace
}  // namespace cambrian
