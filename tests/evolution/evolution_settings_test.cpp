#include "evolution/evolution_settings.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

namespace cambrian {
namespace {

// the message of the ConfigError `settings` raises, or "" when valid
std::string problem(const EvolutionSettings& settings) {
  try {
    validateEvolutionSettings(settings);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(EvolutionSettings, DefaultsAreSimsAndChaumont) {
  EvolutionSettings s;
  EXPECT_EQ(problem(s), "");
  EXPECT_DOUBLE_EQ(s.elite_fraction, 0.2);
  EXPECT_DOUBLE_EQ(s.mutation_fraction, 0.4);
  EXPECT_DOUBLE_EQ(s.crossover_fraction, 0.3);
  EXPECT_DOUBLE_EQ(s.graft_fraction, 0.3);
  EXPECT_DOUBLE_EQ(s.mutation.parameter_rate, 0.10);
  EXPECT_DOUBLE_EQ(s.post_crossover_mutation_chance, 0.1);
  EXPECT_DOUBLE_EQ(s.post_crossover_mutation_rate, 0.05);
}

TEST(EvolutionSettings, ImpossibleValuesNameTheKeyAndValue) {
  EvolutionSettings s;
  s.population = 0;
  EXPECT_NE(problem(s).find("evolution.population = 0"), std::string::npos);
  s = {};
  s.elite_fraction = 1.2;
  EXPECT_NE(problem(s).find("evolution.elite_fraction = 1.2"), std::string::npos);
  s = {};
  s.graft_fraction = 0.5;
  EXPECT_NE(problem(s).find("sum to 1"), std::string::npos);
  s = {};
  s.selection.tournament_size = 0;
  EXPECT_NE(problem(s).find("evolution.tournament_size"), std::string::npos);
}

TEST(EvolutionSettings, SelectionNamesRoundTrip) {
  for (SelectionMethod m :
       {SelectionMethod::truncation, SelectionMethod::tournament, SelectionMethod::roulette,
        SelectionMethod::sus, SelectionMethod::rank}) {
    EXPECT_EQ(selectionMethodFromName(selectionMethodName(m)), m);
  }
  EXPECT_THROW(selectionMethodFromName("lottery"), ConfigError);
}

}  // namespace
}  // namespace cambrian
