// cambrian: competitive ranking.
#include "evolution/competitive_ranking.hpp"

#include "cambrian/error.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

RankedMeasure parseRankedMeasure(const std::string& text, const std::string& key) {
  RankedMeasure ranked;
  std::vector<std::string> fields(1);
  for (char c : text) {
    if (c == ':')
      fields.emplace_back();
    else
      fields.back() += c;
  }
  auto fail = [&](const std::string& why) {
    throw ConfigError(key + " = " + text + ": " + why +
                      " (write NAME, NAME:WEIGHT or NAME:WEIGHT:higher|lower)");
  };
  if (fields.size() > 3 || fields[0].empty())
    fail("not a ranked measure");
  ranked.measure = fields[0];
  if (fields.size() >= 2) {
    std::size_t used = 0;
    try {
      ranked.weight = std::stod(fields[1], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (fields[1].empty() || used != fields[1].size() || !std::isfinite(ranked.weight) ||
        ranked.weight < 0)
      fail("the weight '" + fields[1] + "' is not a finite number >= 0");
  }
  if (fields.size() == 3) {
    if (fields[2] != "higher" && fields[2] != "lower")
      fail("the direction '" + fields[2] + "' is neither higher nor lower");
    ranked.higher_is_better = fields[2] == "higher";
  }
  return ranked;
}

void rankCompetitively(std::vector<Individual>& individuals,
                       const std::vector<RankedMeasure>& measures) {
  std::vector<double> scores(individuals.size(), 0.0);
  std::vector<double> values;
  for (const RankedMeasure& ranked : measures) {
    // every ok individual's value, oriented so that larger is better, sorted
    auto oriented = [&](const Individual& individual) {
      const double value = individual.outcome.measure(ranked.measure);
      return ranked.higher_is_better ? value : -value;
    };
    values.clear();
    for (const Individual& individual : individuals) {
      const double value = oriented(individual);
      if (individual.outcome.status == EvalStatus::ok && !std::isnan(value))
        values.push_back(value);
    }
    std::sort(values.begin(), values.end());
    // points: the ok individuals strictly worse
    for (std::size_t i = 0; i < individuals.size(); ++i) {
      const double value = oriented(individuals[i]);
      if (individuals[i].outcome.status != EvalStatus::ok || std::isnan(value))
        continue;
      const auto worse = std::lower_bound(values.begin(), values.end(), value) - values.begin();
      scores[i] += ranked.weight * static_cast<double>(worse);
    }
  }
  for (std::size_t i = 0; i < individuals.size(); ++i) {
    if (individuals[i].outcome.status == EvalStatus::ok)
      individuals[i].outcome.fitness = scores[i];
  }
}

}  // namespace cambrian
