#include "evolution/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty())
    return 0;
  // linear interpolation between the closest ranks
  double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  auto below = static_cast<std::size_t>(std::floor(position));
  std::size_t above = std::min(below + 1, sorted.size() - 1);
  double t = position - static_cast<double>(below);
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

FitnessStats computeStats(const Population& population) {
  FitnessStats stats;
  stats.count = population.individuals.size();
  if (stats.count == 0)
    return stats;

  // sums in id order, so the result never depends on evaluation order
  std::vector<double> values;
  values.reserve(stats.count);
  double sum = 0;
  for (const Individual& individual : population.individuals) {
    values.push_back(individual.fitness());
    sum += individual.fitness();
    if (individual.outcome.status != EvalStatus::ok)
      ++stats.failed;
  }
  stats.mean = sum / static_cast<double>(stats.count);
  double squares = 0;
  for (double v : values)
    squares += (v - stats.mean) * (v - stats.mean);
  stats.stddev = std::sqrt(squares / static_cast<double>(stats.count));

  // order statistics
  std::vector<std::size_t> ranking = population.ranking();
  stats.best_id = population.individuals[ranking.front()].id;
  std::sort(values.begin(), values.end());
  stats.best = values.back();
  stats.worst = values.front();
  stats.q25 = quantile(values, 0.25);
  stats.median = quantile(values, 0.5);
  stats.q75 = quantile(values, 0.75);
  return stats;
}

}  // namespace cambrian
