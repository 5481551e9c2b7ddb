#include "evolution/selection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cambrian {

namespace {

// how many of the best are eligible under truncation
std::size_t truncationCount(std::size_t n, double fraction) {
  auto eligible = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(n) - 1e-9));
  return std::clamp<std::size_t>(eligible, 1, n);
}

// linear ranking weight of position i of n (best = pressure, worst = 2 - pressure)
double rankWeight(std::size_t i, std::size_t n, double pressure) {
  if (n == 1)
    return 1;
  return pressure - (2 * pressure - 2) * static_cast<double>(i) / static_cast<double>(n - 1);
}

// index of the first prefix sum greater than x
std::size_t pickFromPrefix(const std::vector<double>& prefix, double x) {
  auto it = std::upper_bound(prefix.begin(), prefix.end(), x);
  if (it == prefix.end())
    --it;
  return static_cast<std::size_t>(it - prefix.begin());
}

// selection weights of roulette, sus and rank; uniform when every fitness is 0
std::vector<double> weights(const std::vector<double>& fitness, const SelectionSettings& s) {
  std::size_t n = fitness.size();
  std::vector<double> w(n, 1.0);
  if (s.method == SelectionMethod::rank) {
    for (std::size_t i = 0; i < n; ++i)
      w[i] = rankWeight(i, n, s.rank_pressure);
    return w;
  }
  double total = 0;
  for (double f : fitness)
    total += std::max(0.0, f);
  if (total <= 0 || !std::isfinite(total))
    return w;
  for (std::size_t i = 0; i < n; ++i)
    w[i] = std::max(0.0, fitness[i]);
  return w;
}

// running sums of the weights
std::vector<double> prefixSums(const std::vector<double>& w) {
  std::vector<double> prefix(w.size());
  double sum = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    prefix[i] = sum += w[i];
  return prefix;
}

}  // namespace

std::vector<std::size_t> selectParents(const std::vector<double>& fitness, std::size_t count,
                                       const SelectionSettings& s, Rng& rng) {
  std::size_t n = fitness.size();
  if (n == 0)
    throw std::invalid_argument("selectParents: empty population");
  std::vector<std::size_t> picks;
  picks.reserve(count);

  switch (s.method) {
    case SelectionMethod::truncation: {
      // uniform among the best
      std::size_t eligible = truncationCount(n, s.truncation_fraction);
      for (std::size_t k = 0; k < count; ++k)
        picks.push_back(rng.below(eligible));
      break;
    }
    case SelectionMethod::tournament: {
      // the best-ranked of k uniform draws wins (ranking already breaks ties by id)
      for (std::size_t k = 0; k < count; ++k) {
        std::size_t best = n;
        for (int t = 0; t < std::max(1, s.tournament_size); ++t)
          best = std::min(best, rng.below(n));
        picks.push_back(best);
      }
      break;
    }
    case SelectionMethod::roulette:
    case SelectionMethod::rank: {
      // independent spins of a weighted wheel
      std::vector<double> prefix = prefixSums(weights(fitness, s));
      double total = prefix.back();
      for (std::size_t k = 0; k < count; ++k)
        picks.push_back(pickFromPrefix(prefix, rng.uniform() * total));
      break;
    }
    case SelectionMethod::sus: {
      // one spin, `count` equally spaced pointers, then shuffled so pairs are not rank-sorted
      std::vector<double> prefix = prefixSums(weights(fitness, s));
      double total = prefix.back();
      if (count == 0)
        break;
      double step = total / static_cast<double>(count);
      double start = rng.uniform() * step;
      for (std::size_t k = 0; k < count; ++k) {
        picks.push_back(pickFromPrefix(prefix, start + static_cast<double>(k) * step));
      }
      for (std::size_t k = count; k > 1; --k)
        std::swap(picks[k - 1], picks[rng.below(k)]);
      break;
    }
  }
  return picks;
}

std::vector<double> selectionProbabilities(const std::vector<double>& fitness,
                                           const SelectionSettings& s) {
  std::size_t n = fitness.size();
  std::vector<double> p(n, 0.0);
  if (n == 0)
    return p;

  switch (s.method) {
    case SelectionMethod::truncation: {
      // uniform over the eligible best
      std::size_t eligible = truncationCount(n, s.truncation_fraction);
      for (std::size_t i = 0; i < eligible; ++i)
        p[i] = 1.0 / static_cast<double>(eligible);
      break;
    }
    case SelectionMethod::tournament: {
      // position i wins when the best of k draws is i: ((n-i)^k - (n-i-1)^k) / n^k
      double k = std::max(1, s.tournament_size), nn = static_cast<double>(n);
      for (std::size_t i = 0; i < n; ++i) {
        double above = static_cast<double>(n - i), below = above - 1;
        p[i] = (std::pow(above / nn, k) - std::pow(below / nn, k));
      }
      break;
    }
    case SelectionMethod::roulette:
    case SelectionMethod::sus:
    case SelectionMethod::rank: {
      // normalised weights
      std::vector<double> w = weights(fitness, s);
      double total = 0;
      for (double x : w)
        total += x;
      for (std::size_t i = 0; i < n; ++i)
        p[i] = w[i] / total;
      break;
    }
  }
  return p;
}

}  // namespace cambrian
