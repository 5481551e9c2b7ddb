// cambrian: epochs.
#include "evolution/epochs.hpp"

#include "cambrian/error.hpp"

#include <cmath>

namespace cambrian {
namespace {

// the parts of `text` between `separator`s
std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == separator)
      parts.emplace_back();
    else
      parts.back() += c;
  }
  return parts;
}

}  // namespace

Epoch parseEpoch(const std::string& text, const std::string& key) {
  auto fail = [&](const std::string& why) {
    throw ConfigError(key + " = " + text + ": " + why +
                      " (write RANKING[@CONDITION]: RANKING as NAME[:WEIGHT[:higher|lower]] "
                      "joined by +, CONDITION as N generations or NAME>=X or NAME<=X)");
  };
  const std::vector<std::string> halves = split(text, '@');
  if (halves.size() > 2)
    fail("more than one '@'");
  Epoch epoch;
  for (const std::string& measure : split(halves[0], '+'))
    epoch.ranking.push_back(parseRankedMeasure(measure, key));
  if (halves.size() == 1)
    return epoch;

  // the condition: a generation count, or a measure's threshold
  const std::string& condition = halves[1];
  if (condition.empty())
    fail("nothing after '@'");
  if (condition.find_first_not_of("0123456789") == std::string::npos) {
    epoch.until = Epoch::Until::generations;
    try {
      epoch.generations = std::stoull(condition);
    } catch (const std::exception&) {
      fail("the generation count '" + condition + "' is too large");
    }
    if (epoch.generations == 0)
      fail("an epoch lasts at least 1 generation");
    return epoch;
  }
  std::size_t at = condition.find(">=");
  epoch.at_least = at != std::string::npos;
  if (!epoch.at_least)
    at = condition.find("<=");
  if (at == std::string::npos || at == 0)
    fail("the condition '" + condition + "' is neither a generation count nor NAME>=X or NAME<=X");
  epoch.until = Epoch::Until::reached;
  epoch.measure = condition.substr(0, at);
  const std::string value = condition.substr(at + 2);
  std::size_t used = 0;
  try {
    epoch.threshold = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || !std::isfinite(epoch.threshold))
    fail("the threshold '" + value + "' is not a finite number");
  return epoch;
}

std::vector<Epoch> parseEpochs(const std::vector<std::string>& texts, const std::string& key) {
  std::vector<Epoch> epochs;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    epochs.push_back(parseEpoch(texts[i], key));
    const bool last = i + 1 == texts.size();
    if (!last && epochs.back().until == Epoch::Until::end) {
      throw ConfigError(key + ": epoch " + std::to_string(i + 1) + " (" + texts[i] +
                        ") has no condition, so the epochs after it would never come (end it "
                        "with @N or @NAME>=X)");
    }
    if (last && epochs.back().until != Epoch::Until::end) {
      throw ConfigError(key + ": the last epoch (" + texts[i] +
                        ") has a condition, but no epoch follows it (leave the condition out)");
    }
  }
  return epochs;
}

EpochPlace nextEpochPlace(const std::vector<Epoch>& epochs, EpochPlace place,
                          const Population& population) {
  if (place.epoch >= epochs.size())
    return place;
  const Epoch& epoch = epochs[place.epoch];
  bool over = false;
  if (epoch.until == Epoch::Until::generations) {
    over = population.generation + 1 - place.first_generation >= epoch.generations;
  } else if (epoch.until == Epoch::Until::reached) {
    for (const Individual& individual : population.individuals) {
      const double value = individual.outcome.measure(epoch.measure);
      if (individual.outcome.status == EvalStatus::ok && !std::isnan(value) &&
          (epoch.at_least ? value >= epoch.threshold : value <= epoch.threshold))
        over = true;
    }
  }
  if (!over)
    return place;
  return EpochPlace{place.epoch + 1, population.generation + 1};
}

}  // namespace cambrian
