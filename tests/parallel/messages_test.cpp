#include "parallel/messages.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian {
namespace {

TEST(Messages, RequestRoundTrips) {
  EvalRequest request{42, 0xfeedfacecafebeefULL, {1, 2, 3, 250}};
  EXPECT_EQ(decodeRequest(encodeRequest(request)), request);
}

TEST(Messages, ResultRoundTripsBitExactly) {
  EvalResult result;
  result.id = 7;
  result.outcome.status = EvalStatus::exploded;
  result.outcome.fitness = 0.1 + 0.2;
  result.outcome.steps = 12345;
  result.outcome.wall_seconds = 1.5;
  result.outcome.parts = 3;
  result.outcome.joints = 2;
  result.outcome.neurons = 9;
  result.outcome.message = "part 2 too fast";
  result.outcome.measures = {{"distance", -0.0}, {"height", std::nan("")}};
  EvalResult back = decodeResult(encodeResult(result));
  EXPECT_EQ(back.id, 7u);
  EXPECT_EQ(back.outcome.status, EvalStatus::exploded);
  EXPECT_EQ(back.outcome.fitness, 0.1 + 0.2);
  EXPECT_EQ(back.outcome.steps, 12345u);
  EXPECT_EQ(back.outcome.message, "part 2 too fast");
  EXPECT_EQ(back.outcome.joints, 2);
  ASSERT_EQ(back.outcome.measures.size(), 2u);
  EXPECT_TRUE(std::signbit(back.outcome.measures[0].value));
  EXPECT_TRUE(std::isnan(back.outcome.measures[1].value));
}

TEST(Messages, TruncatedOrBadBytesAreNamedErrors) {
  std::vector<std::uint8_t> bytes = encodeRequest(EvalRequest{1, 2, {9, 9}});
  bytes.pop_back();
  try {
    decodeRequest(bytes);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("genome"), std::string::npos);
  }
  std::vector<std::uint8_t> result = encodeResult(EvalResult{});
  result[8] = 200;  // status
  EXPECT_THROW(decodeResult(result), InputError);
  result = encodeResult(EvalResult{});
  result.push_back(0);
  EXPECT_THROW(decodeResult(result), InputError);
}

}  // namespace
}  // namespace cambrian
