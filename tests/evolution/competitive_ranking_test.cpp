// Tests of Minemonics' competitive ranking on hand-made tables, and of its setting's syntax.
#include "evolution/competitive_ranking.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cambrian {
namespace {

// an individual of status ok with measures a and b (NaN: absent)
Individual individual(std::uint64_t id, double a, double b, EvalStatus status = EvalStatus::ok) {
  Individual i;
  i.id = id;
  i.evaluated = true;
  i.outcome.status = status;
  i.outcome.fitness = status == EvalStatus::ok ? 99 : kWorstFitness;
  if (!std::isnan(a))
    i.outcome.measures.push_back({"a", a});
  if (!std::isnan(b))
    i.outcome.measures.push_back({"b", b});
  return i;
}

std::vector<double> fitnesses(const std::vector<Individual>& individuals) {
  std::vector<double> f;
  for (const Individual& i : individuals)
    f.push_back(i.outcome.fitness);
  return f;
}

// the thesis' rule by hand: points are the individuals that did worse, weighted and summed
TEST(CompetitiveRanking, PointsAreTheIndividualsThatDidWorseWeighted) {
  // a (higher better, weight 1): 3, 1, 2, 2 -> individuals worse: 3, 0, 1, 1
  // b (lower better, weight 0.5): 5, 1, 9, 1 -> individuals worse: 1, 2, 0, 2 (ties score alike)
  std::vector<Individual> table = {individual(1, 3, 5), individual(2, 1, 1), individual(3, 2, 9),
                                   individual(4, 2, 1)};
  rankCompetitively(table, {{"a", 1, true}, {"b", 0.5, false}});
  EXPECT_EQ(fitnesses(table),
            (std::vector<double>{3 + 0.5 * 1, 0 + 0.5 * 2, 1 + 0.5 * 0, 1 + 0.5 * 2}));
}

// failed individuals keep the worst fitness and are nobody's points; a missing measure scores
// nothing on it and is worse than every value
TEST(CompetitiveRanking, FailuresAndMissingMeasures) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  std::vector<Individual> table = {individual(1, 3, none),
                                   individual(2, 100, 1, EvalStatus::exploded), individual(3, 1, 2),
                                   individual(4, none, 3)};
  rankCompetitively(table, {{"a", 1, true}, {"b", 1, true}});
  // a: 3 beats 1 (1 point); 1 beats none; b: 3 beats 2 (1 point)
  EXPECT_EQ(fitnesses(table), (std::vector<double>{1, kWorstFitness, 0, 1}));
}

// the result depends on the measures only, not on the order of the individuals
TEST(CompetitiveRanking, OrderDoesNotMatter) {
  std::vector<Individual> table;
  for (int i = 0; i < 12; ++i)
    table.push_back(individual(i, std::fmod(i * 7.3, 5.0), std::fmod(i * 3.1, 4.0)));
  std::vector<Individual> reversed(table.rbegin(), table.rend());
  const std::vector<RankedMeasure> ranking = {{"a", 2, true}, {"b", 1, false}};
  rankCompetitively(table, ranking);
  rankCompetitively(reversed, ranking);
  for (const Individual& i : table) {
    auto same = std::find_if(reversed.begin(), reversed.end(),
                             [&](const Individual& r) { return r.id == i.id; });
    EXPECT_EQ(same->outcome.fitness, i.outcome.fitness) << i.id;
  }
  // the best on both measures scores the most points possible: weights x (12 - 1) at most
  for (const Individual& i : table)
    EXPECT_LE(i.outcome.fitness, 3 * 11);
}

TEST(CompetitiveRanking, TheSettingsSyntax) {
  RankedMeasure plain = parseRankedMeasure("average_velocity", "evolution.ranking");
  EXPECT_EQ(plain.measure, "average_velocity");
  EXPECT_EQ(plain.weight, 1);
  EXPECT_TRUE(plain.higher_is_better);
  RankedMeasure full = parseRankedMeasure("ground_contact_ratio:0.25:lower", "k");
  EXPECT_EQ(full.measure, "ground_contact_ratio");
  EXPECT_EQ(full.weight, 0.25);
  EXPECT_FALSE(full.higher_is_better);
  for (const char* bad : {"", "a:", "a:x", "a:-1", "a:1:up", "a:1:lower:more", "a:inf", ":1"}) {
    try {
      parseRankedMeasure(bad, "evolution.ranking");
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("evolution.ranking"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace cambrian
