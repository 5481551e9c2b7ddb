// Tests of reading a steady-state run's recorded order of results: the order and bred_after of
// its rows, and the records that are refused (another run's, a generational run's, no file).
#include "run/arrival_order.hpp"

#include "cambrian/error.hpp"

#include "run/evolution_run.hpp"
#include "run/small_synthetic_run.hpp"
#include "store/history.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace cambrian {
namespace {

// a run of `mode` writing DIR/history.h5; returns the attributes its history holds
HistoryAttributes runIn(const std::string& dir, EvolutionMode mode, std::uint64_t seed = 4) {
  std::ostringstream out;
  RunSettings run;
  run.quiet = true;
  smallSyntheticRun(mode, dir, out, true, 6, 2, run, seed);
  return HistoryReader(dir + "/history.h5").attributes();
}

// the code and message of readArrivalRecord's error
std::pair<ExitCode, std::string> refusal(const std::string& path, const HistoryAttributes& run) {
  try {
    readArrivalRecord(path, run);
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  return {ExitCode::ok, ""};
}

TEST(ArrivalOrder, ReadsTheOrderTakenInAndWhenEachWasBred) {
  const std::string dir = testing::TempDir() + "/cambrian_arrival_order_steady";
  const HistoryAttributes attributes = runIn(dir, EvolutionMode::steady_state);
  ArrivalRecord record = readArrivalRecord(dir + "/history.h5", attributes);
  const std::vector<Individual> rows = HistoryReader(dir + "/history.h5").individuals();
  ASSERT_EQ(record.order.size(), 12u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    std::uint64_t id = 0, after = 0;
    ASSERT_TRUE(record.idAt(k, id));
    EXPECT_EQ(id, rows[k].id);
    ASSERT_TRUE(record.bredAfter(id, after));
    EXPECT_EQ(after, rows[k].bred_after);
  }
  std::uint64_t id = 0, after = 0;
  EXPECT_FALSE(record.idAt(12, id));
  EXPECT_FALSE(record.bredAfter(999, after));
}

TEST(ArrivalOrder, RefusesAnotherRunsRecordAGenerationalOneAndNoFile) {
  const std::string steady = testing::TempDir() + "/cambrian_arrival_order_mine";
  const HistoryAttributes mine = runIn(steady, EvolutionMode::steady_state);
  // another seed
  const std::string other = testing::TempDir() + "/cambrian_arrival_order_other";
  runIn(other, EvolutionMode::steady_state, 5);
  auto [code, message] = refusal(other + "/history.h5", mine);
  EXPECT_EQ(code, ExitCode::config);
  EXPECT_NE(message.find("run.arrival_order = " + other + "/history.h5"), std::string::npos)
      << message;
  EXPECT_NE(message.find("other settings"), std::string::npos) << message;
  // a generational run
  const std::string generational = testing::TempDir() + "/cambrian_arrival_order_generational";
  runIn(generational, EvolutionMode::generational);
  std::tie(code, message) = refusal(generational + "/history.h5", mine);
  EXPECT_EQ(code, ExitCode::config);
  EXPECT_NE(message.find("not a steady-state run"), std::string::npos) << message;
  // no file
  std::tie(code, message) = refusal(steady + "/missing.h5", mine);
  EXPECT_EQ(code, ExitCode::input_file);
  EXPECT_NE(message.find("missing.h5"), std::string::npos) << message;
}

}  // namespace
}  // namespace cambrian
