#include "evolution/evolution_settings.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"

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
  EXPECT_DOUBLE_EQ(s.mutation_rate, 0.10);
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

TEST(EvolutionSettings, ASteadyStateRefusesWhatNeedsWholeGenerations) {
  EvolutionSettings s;
  s.mode = EvolutionMode::steady_state;
  EXPECT_EQ(problem(s), "");
  s.replacement_tournament = 0;
  EXPECT_NE(problem(s).find("evolution.replacement_tournament = 0"), std::string::npos);
  s.replacement_tournament = s.population + 1;
  EXPECT_NE(problem(s).find("evolution.replacement_tournament"), std::string::npos);
  s.replacement_tournament = 2;
  s.scheme = BreedingScheme::reaper;
  EXPECT_NE(problem(s).find("evolution.mode = steady_state: evolution.scheme = reaper"),
            std::string::npos)
      << problem(s);
  s.scheme = BreedingScheme::wwd;
  EXPECT_NE(problem(s).find("evolution.scheme = wwd"), std::string::npos);
  s.scheme = BreedingScheme::generational;
  s.batch_generations = 5;
  EXPECT_NE(problem(s).find("evolution.batch_generations = 5"), std::string::npos);
  s.batch_generations = 0;
  s.ranking = {"distance"};
  EXPECT_NE(problem(s).find("evolution.ranking"), std::string::npos);
  // the generational mode takes them all
  s.mode = EvolutionMode::generational;
  EXPECT_EQ(problem(s), "");
  SettingsSchema schema;
  s.declareSettings(schema);
  schema.set("evolution.mode", "steady_state");
  EXPECT_EQ(s.mode, EvolutionMode::steady_state);
  EXPECT_THROW(schema.set("evolution.mode", "asynchronous"), ConfigError);
}

TEST(EvolutionSettings, SelectionNamesRoundTripThroughTheKey) {
  EvolutionSettings s;
  SettingsSchema schema;
  s.declareSettings(schema);
  for (SelectionMethod m :
       {SelectionMethod::truncation, SelectionMethod::tournament, SelectionMethod::roulette,
        SelectionMethod::sus, SelectionMethod::rank}) {
    schema.set("evolution.selection", selectionMethodName(m));
    EXPECT_EQ(s.selection.method, m);
    EXPECT_EQ(schema.find("evolution.selection")->text(), selectionMethodName(m));
  }
  EXPECT_THROW(schema.set("evolution.selection", "lottery"), ConfigError);
}

TEST(EvolutionSettings, GenerationsAreRunOnlyAndTheSeedIsASeed) {
  EvolutionSettings s;
  SettingsSchema schema;
  s.declareSettings(schema);
  EXPECT_EQ(schema.runOnlyKeys(), (std::set<std::string>{"evolution.generations"}));
  EXPECT_THROW(schema.set("run.seed", "-3"), SettingTypeError);
  schema.set("run.seed", "18446744073709551615");
  EXPECT_EQ(s.seed, UINT64_MAX);
}

}  // namespace
}  // namespace cambrian
