#include "evolution/wwd_breeding.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "evolution/breeder.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace cambrian {

WwdPlan planWwd(const EvolutionSettings& settings) {
  const int p = settings.population;
  WwdPlan plan;
  plan.elites = std::clamp(static_cast<int>(std::lround(p * settings.wwd.elite_fraction)), 0,
                           std::max(p - 1, 0));
  plan.breeders = std::clamp(static_cast<int>(std::lround(p * settings.wwd.breeder_fraction)), 0,
                             p - plan.elites);
  plan.children = p - plan.elites;
  return plan;
}

double normalisedDeviation(std::vector<double> fitness) {
  if (fitness.empty())
    return 0;
  // sorted, so the sums never depend on the order the values came in
  std::sort(fitness.begin(), fitness.end(), std::greater<>());
  double scale = 0;
  for (double f : fitness)
    scale = std::max(scale, std::abs(f));
  if (!(scale > 0) || !std::isfinite(scale))
    return 0;
  const auto n = static_cast<double>(fitness.size());
  double sum = 0;
  for (double f : fitness)
    sum += f / scale;
  const double mean = sum / n;
  double squares = 0;
  for (double f : fitness)
    squares += (f / scale - mean) * (f / scale - mean);
  return std::sqrt(squares / n);
}

MutationScale mutationScale(const WwdSettings& settings, const std::vector<double>& fitness) {
  MutationScale scale;
  scale.deviation = normalisedDeviation(fitness);
  if (settings.adaptive_mutation) {
    scale.multiplier = std::clamp(settings.target_deviation / std::max(scale.deviation, 1e-9),
                                  settings.min_multiplier, settings.max_multiplier);
  }
  return scale;
}

MutationScale mutationScale(const EvolutionSettings& settings, const Population& evaluated) {
  std::vector<double> fitness;
  fitness.reserve(evaluated.individuals.size());
  for (const Individual& individual : evaluated.individuals)
    fitness.push_back(individual.fitness());
  MutationScale scale = mutationScale(settings.wwd, fitness);
  if (settings.scheme != BreedingScheme::wwd)
    scale.multiplier = 1;
  return scale;
}

double wwdMutationRate(const Encoding& encoding, const EvolutionSettings& settings,
                       double multiplier) {
  return scaledMutationRate(encoding, settings.mutation_rate, multiplier);
}

void requireWwdOperators(const Encoding& encoding) {
  for (Variation variation : {Variation::crossover, Variation::mutation}) {
    if (!encoding.supports(variation))
      throw ConfigError(std::string("evolution.scheme = wwd: the encoding ") + encoding.name() +
                        " has no " + variationName(variation) +
                        " (every bred child is a crossover of an elite into a breeder, then "
                        "mutated)");
  }
}

Population Breeder::breedWwd(const Population& evaluated) {
  const std::uint64_t g = evaluated.generation + 1;
  const WwdPlan plan = planWwd(settings_);
  const std::vector<std::size_t> ranking = evaluated.ranking();
  if (ranking.size() < static_cast<std::size_t>(plan.elites + plan.breeders))
    throw std::invalid_argument("nextGeneration: generation " +
                                std::to_string(evaluated.generation) + " has " +
                                std::to_string(ranking.size()) + " individuals, fewer than the " +
                                "wwd scheme's elites and breeders");
  auto ranked = [&](std::size_t rank) -> const Individual& {
    return evaluated.individuals[ranking[rank]];
  };
  // the deviation of this generation's fitnesses scales the mutation of every child
  const double rate =
      wwdMutationRate(encoding_, settings_, mutationScale(settings_, evaluated).multiplier);

  Population next;
  next.generation = g;
  next.individuals.reserve(static_cast<std::size_t>(plan.elites + plan.children));

  // the elites stay, with their outcomes (their genome did not change)
  for (int e = 0; e < plan.elites; ++e)
    next.individuals.push_back(eliteCopy(ranked(static_cast<std::size_t>(e)), g));

  // the parents of every child in one stream (seed, selection, g, 0): for each child in turn an
  // elite, then a breeder, each uniformly from its group
  Rng selection(settings_.seed, RngPurpose::selection, g, 0);
  const auto elites = static_cast<std::uint64_t>(plan.elites);
  const auto breeders = static_cast<std::uint64_t>(plan.breeders);
  // child i uses the stream (seed, variation, g, i); redraws (a viability check) keep the parents
  // and take the next draws of that stream
  for (int i = 0; i < plan.children; ++i) {
    const Individual& elite = ranked(static_cast<std::size_t>(selection.below(elites)));
    const Individual& breeder =
        ranked(static_cast<std::size_t>(elites + selection.below(breeders)));
    // the receiver first, as the generational scheme's; the breeder receives a part of the elite,
    // then every child is mutated
    next.individuals.push_back(
        offspring(g, static_cast<std::uint64_t>(i), Origin::crossover, {breeder.id, elite.id},
                  [&encoding = encoding_, mother = breeder.genome, father = elite.genome, rate](
                      Rng& rng, int) {
                    return encoding.mutate(
                        encoding.combine(Variation::crossover, mother, father, rng), rate, rng);
                  }));
  }
  return next;
}

}  // namespace cambrian
