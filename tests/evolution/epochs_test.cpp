// Tests of Minemonics' epochs: the setting's syntax, and when an epoch ends on hand-made
// generations.
#include "evolution/epochs.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cambrian {
namespace {

// generation g of individuals with measure "a" of these values (status ok unless failed)
Population generation(std::uint64_t g, std::vector<double> values, bool failed = false) {
  Population population;
  population.generation = g;
  for (std::size_t i = 0; i < values.size(); ++i) {
    Individual individual;
    individual.id = i;
    individual.evaluated = true;
    individual.outcome.status = failed ? EvalStatus::exploded : EvalStatus::ok;
    individual.outcome.measures.push_back({"a", values[i]});
    population.individuals.push_back(individual);
  }
  return population;
}

// the message of the ConfigError parsing `texts` throws, or ""
std::string refusal(const std::vector<std::string>& texts) {
  try {
    parseEpochs(texts, "evolution.epochs");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Epochs, ParseRankingsAndConditions) {
  const std::vector<Epoch> epochs =
      parseEpochs({"a:1:higher+b:0.5:lower@10", "b@a>=2.5", "c@a<=-1", "a"}, "evolution.epochs");
  ASSERT_EQ(epochs.size(), 4u);
  ASSERT_EQ(epochs[0].ranking.size(), 2u);
  EXPECT_EQ(epochs[0].ranking[1].measure, "b");
  EXPECT_EQ(epochs[0].ranking[1].weight, 0.5);
  EXPECT_FALSE(epochs[0].ranking[1].higher_is_better);
  EXPECT_EQ(epochs[0].until, Epoch::Until::generations);
  EXPECT_EQ(epochs[0].generations, 10u);
  EXPECT_EQ(epochs[1].until, Epoch::Until::reached);
  EXPECT_EQ(epochs[1].measure, "a");
  EXPECT_EQ(epochs[1].threshold, 2.5);
  EXPECT_TRUE(epochs[1].at_least);
  EXPECT_FALSE(epochs[2].at_least);
  EXPECT_EQ(epochs[2].threshold, -1);
  EXPECT_EQ(epochs[3].until, Epoch::Until::end);
  EXPECT_TRUE(parseEpochs({}, "evolution.epochs").empty());
}

// every refusal names the key, the text and what is wrong
TEST(Epochs, BadEpochsAreRefusedSayingWhy) {
  EXPECT_NE(refusal({"a@5"}).find("the last epoch (a@5) has a condition"), std::string::npos);
  EXPECT_NE(refusal({"a", "b"}).find("epoch 1 (a) has no condition"), std::string::npos);
  EXPECT_NE(refusal({"a@0", "b"}).find("evolution.epochs = a@0: an epoch lasts at least 1"),
            std::string::npos);
  EXPECT_NE(refusal({"a@", "b"}).find("nothing after '@'"), std::string::npos);
  EXPECT_NE(refusal({"a@1@2", "b"}).find("more than one '@'"), std::string::npos);
  EXPECT_NE(refusal({"a@b=3", "b"}).find("neither a generation count nor NAME>=X"),
            std::string::npos);
  EXPECT_NE(refusal({"a@b>=x", "b"}).find("the threshold 'x' is not a finite number"),
            std::string::npos);
  EXPECT_NE(refusal({"a:w@3", "b"}).find("the weight 'w'"), std::string::npos);
  EXPECT_NE(refusal({"a++b"}).find("not a ranked measure"), std::string::npos);
  EXPECT_EQ(refusal({"a@3", "b"}), "");
}

// after N generations of the epoch, counted from its first generation
TEST(Epochs, AnEpochOfNGenerationsEndsAfterItsNth) {
  const std::vector<Epoch> epochs = parseEpochs({"a@3", "a@2", "a"}, "evolution.epochs");
  EpochPlace place;
  std::vector<std::size_t> epoch_of;
  for (std::uint64_t g = 0; g < 8; ++g) {
    epoch_of.push_back(place.epoch);
    place = nextEpochPlace(epochs, place, generation(g, {0.0}));
  }
  EXPECT_EQ(epoch_of, (std::vector<std::size_t>{0, 0, 0, 1, 1, 2, 2, 2}));
  EXPECT_EQ(place, (EpochPlace{2, 5}));
}

// when the best of a generation reaches the value (at least, or at most); failed individuals and
// the last epoch never end one
TEST(Epochs, AnEpochEndsWhenAValueIsReached) {
  const std::vector<Epoch> up = parseEpochs({"a@a>=2", "a"}, "evolution.epochs");
  EXPECT_EQ(nextEpochPlace(up, {}, generation(4, {1.0, 1.9})), (EpochPlace{0, 0}));
  EXPECT_EQ(nextEpochPlace(up, {}, generation(4, {1.0, 2.0})), (EpochPlace{1, 5}));
  EXPECT_EQ(nextEpochPlace(up, {}, generation(4, {3.0}, true)), (EpochPlace{0, 0}));
  EXPECT_EQ(nextEpochPlace(up, {1, 5}, generation(9, {9.0})), (EpochPlace{1, 5}));
  const std::vector<Epoch> down = parseEpochs({"a@a<=-1", "a"}, "evolution.epochs");
  EXPECT_EQ(nextEpochPlace(down, {}, generation(0, {0.0, -0.5})), (EpochPlace{0, 0}));
  EXPECT_EQ(nextEpochPlace(down, {}, generation(0, {0.0, -1.5})), (EpochPlace{1, 1}));
}

}  // namespace
}  // namespace cambrian
