#include "evolution/selection.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian {
namespace {

const std::vector<double> kFitness = {8, 4, 2, 1, 1, 0};  // best first

// empirical pick shares of `draws` picks in batches of 10
std::vector<double> shares(const SelectionSettings& s, int draws) {
  std::vector<double> counts(kFitness.size(), 0);
  for (int batch = 0; batch < draws / 10; ++batch) {
    Rng rng(5, RngPurpose::test, 0, static_cast<std::uint64_t>(batch));
    for (std::size_t pick : selectParents(kFitness, 10, s, rng))
      counts[pick] += 1;
  }
  for (double& c : counts)
    c /= draws;
  return counts;
}

class SelectionStatistics : public ::testing::TestWithParam<SelectionMethod> {};

TEST_P(SelectionStatistics, EmpiricalSharesMatchTheProbabilities) {
  SelectionSettings s;
  s.method = GetParam();
  s.truncation_fraction = 0.5;
  std::vector<double> expected = selectionProbabilities(kFitness, s);
  double total = 0;
  for (double p : expected)
    total += p;
  EXPECT_NEAR(total, 1, 1e-12);
  std::vector<double> observed = shares(s, 40000);
  for (std::size_t i = 0; i < kFitness.size(); ++i) {
    EXPECT_NEAR(observed[i], expected[i], 0.015) << selectionMethodName(s.method) << " at " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, SelectionStatistics,
                         ::testing::Values(SelectionMethod::truncation, SelectionMethod::tournament,
                                           SelectionMethod::roulette, SelectionMethod::sus,
                                           SelectionMethod::rank));

TEST(Selection, ExactProbabilities) {
  SelectionSettings s;
  s.method = SelectionMethod::roulette;
  EXPECT_DOUBLE_EQ(selectionProbabilities(kFitness, s)[0], 8.0 / 16);
  s.method = SelectionMethod::truncation;
  s.truncation_fraction = 0.5;
  EXPECT_EQ(selectionProbabilities(kFitness, s),
            (std::vector<double>{1. / 3, 1. / 3, 1. / 3, 0, 0, 0}));
  s.method = SelectionMethod::tournament;
  s.tournament_size = 2;
  EXPECT_DOUBLE_EQ(selectionProbabilities(kFitness, s)[0], 11.0 / 36);
  s.method = SelectionMethod::rank;
  s.rank_pressure = 2;
  EXPECT_DOUBLE_EQ(selectionProbabilities(kFitness, s).back(), 0.0);
}

TEST(Selection, SusPicksEachIndividualWithinOneOfItsExpectation) {
  SelectionSettings s;
  s.method = SelectionMethod::sus;
  for (std::uint64_t trial = 0; trial < 20; ++trial) {
    Rng rng(1, RngPurpose::test, 0, trial);
    std::vector<int> counts(kFitness.size(), 0);
    for (std::size_t pick : selectParents(kFitness, 16, s, rng))
      ++counts[pick];
    for (std::size_t i = 0; i < kFitness.size(); ++i) {
      EXPECT_LE(std::fabs(counts[i] - kFitness[i]), 1.0) << "position " << i;
    }
  }
}

TEST(Selection, AllZeroFitnessFallsBackToUniform) {
  SelectionSettings s;
  s.method = SelectionMethod::roulette;
  std::vector<double> p = selectionProbabilities({0, 0, 0, 0}, s);
  for (double x : p)
    EXPECT_DOUBLE_EQ(x, 0.25);
}

TEST(Selection, SameStreamSamePicks) {
  SelectionSettings s;
  s.method = SelectionMethod::tournament;
  Rng a(3, RngPurpose::selection, 2, 0), b(3, RngPurpose::selection, 2, 0);
  EXPECT_EQ(selectParents(kFitness, 50, s, a), selectParents(kFitness, 50, s, b));
  Rng c(3, RngPurpose::selection, 2, 0);
  EXPECT_THROW(selectParents({}, 1, s, c), std::invalid_argument);
}

}  // namespace
}  // namespace cambrian
