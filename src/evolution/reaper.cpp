#include "evolution/reaper.hpp"

#include "cambrian/error.hpp"

#include "evolution/breeder.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace cambrian {

namespace {

// the variation and origin of each survivor kind but the kept
constexpr Variation kShareVariation[kReaperShares] = {
    Variation::mutation,  // (elites: none)
    Variation::gene_specification, Variation::gene_split,
    Variation::gene_purge,         Variation::branch_specification,
    Variation::grow_stub,          Variation::graft_feature};
constexpr Origin kShareOrigin[kReaperShares] = {
    Origin::elite,        Origin::gene_specification,   Origin::gene_split,
    Origin::gene_purge,   Origin::branch_specification, Origin::grow_stub,
    Origin::graft_feature};

}  // namespace

std::vector<int> apportion(int total, std::span<const double> weights) {
  const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<int> counts(weights.size(), 0);
  std::vector<double> remainder(weights.size(), 0);
  int given = 0;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    const double quota = total * weights[k] / sum;
    counts[k] = static_cast<int>(std::floor(quota));
    remainder[k] = quota - counts[k];
    given += counts[k];
  }
  // the places left go to the largest remainders, the earlier first on a tie
  std::vector<std::size_t> order(weights.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t i = 0; given < total; i = (i + 1) % order.size(), ++given)
    ++counts[order[i]];
  return counts;
}

ReaperPlan planReaper(const EvolutionSettings& settings) {
  const ReaperSettings& r = settings.reaper;
  const int p = settings.population;
  ReaperPlan plan;
  plan.culled = std::min(p - 1, static_cast<int>(std::ceil(p * r.reap_fraction - 1e-9)));
  const std::vector<int> survivors = apportion(p - plan.culled, r.shares);
  std::copy(survivors.begin(), survivors.end(), plan.survivors.begin());
  plan.crossovers = static_cast<int>(std::lround(plan.culled * r.sow_crossover_fraction));
  plan.randoms = plan.culled - plan.crossovers;
  return plan;
}

void requireReaperOperators(const EvolutionSettings& settings, const Encoding& encoding) {
  const ReaperPlan plan = planReaper(settings);
  for (int k = 1; k < kReaperShares; ++k) {
    if (plan.survivors[static_cast<std::size_t>(k)] > 0 && !encoding.supports(kShareVariation[k]))
      throw ConfigError(std::string("evolution.reaper_") +
                        reaperShareName(static_cast<ReaperShare>(k)) + "_share: the encoding " +
                        encoding.name() + " has no such operator; set it to 0");
  }
  if (plan.crossovers > 0 && !encoding.supports(settings.reaper.crossover))
    throw ConfigError("evolution.sow_crossover_fraction: the encoding " + encoding.name() +
                      " has no " + variationName(settings.reaper.crossover) + "; set it to 0");
}

std::size_t reaperPartner(std::size_t count, const ReaperSettings& settings, Rng& rng) {
  if (count == 0)
    throw std::invalid_argument("reaperPartner: no survivors");
  if (!rng.bernoulli(settings.tournament_chance))
    return static_cast<std::size_t>(rng.below(count));
  // the best (lowest index) of the contestants, drawn half-normal from the top
  const double sigma = static_cast<double>(count) / 3;
  std::size_t best = count - 1;
  for (int c = 0; c < settings.tournament_size; ++c) {
    const double draw = std::floor(std::abs(rng.normal()) * sigma);
    best = std::min(best, static_cast<std::size_t>(std::min(draw, static_cast<double>(count - 1))));
  }
  return best;
}

Population Breeder::reap(const Population& evaluated) {
  const std::uint64_t g = evaluated.generation + 1;
  const ReaperSettings& settings = settings_.reaper;
  const ReaperPlan plan = planReaper(settings_);
  const std::vector<std::size_t> ranking = evaluated.ranking();
  const std::size_t survivors = ranking.size() - static_cast<std::size_t>(plan.culled);
  auto survivor = [&](std::size_t rank) -> const Individual& {
    return evaluated.individuals[ranking[rank]];
  };

  Population next;
  next.generation = g;
  next.individuals.reserve(ranking.size());

  // every draw of partners and of who is varied how: one stream (seed, selection, g, 0)
  Rng selection(settings_.seed, RngPurpose::selection, g, 0);

  // the best survivors are kept with their outcomes (not re-evaluated)
  const auto kept = static_cast<std::size_t>(plan.survivors[0]);
  for (std::size_t rank = 0; rank < kept; ++rank)
    next.individuals.push_back(eliteCopy(survivor(rank), g));

  // new individual slot i uses the stream (seed, variation, g, i); redraws as in the generational
  // scheme (same parents, the next draws of the same stream)
  std::uint64_t slot = 0;
  auto add = [&](Origin origin, std::vector<std::uint64_t> parents, auto make) {
    next.individuals.push_back(offspring(g, slot++, origin, std::move(parents), std::move(make)));
  };

  // the other survivors, in a shuffled order, each varied by one operator, in share order
  std::vector<std::size_t> varied(survivors - kept);
  std::iota(varied.begin(), varied.end(), kept);
  for (std::size_t i = varied.size(); i > 1; --i)
    std::swap(varied[i - 1], varied[static_cast<std::size_t>(selection.below(i))]);
  std::size_t next_varied = 0;
  for (int k = 1; k < kReaperShares; ++k) {
    const Variation variation = kShareVariation[k];
    for (int n = 0; n < plan.survivors[static_cast<std::size_t>(k)]; ++n) {
      const Individual& parent = survivor(varied[next_varied++]);
      if (variation == Variation::graft_feature) {
        const Individual& donor = survivor(reaperPartner(survivors, settings, selection));
        add(kShareOrigin[k], {parent.id, donor.id},
            [&encoding = encoding_, variation, receiver = parent.genome, giver = donor.genome](
                Rng& rng, int) { return encoding.combine(variation, receiver, giver, rng); });
      } else {
        add(kShareOrigin[k], {parent.id},
            [&encoding = encoding_, variation, genome = parent.genome](Rng& rng, int) {
              return encoding.vary(variation, genome, rng);
            });
      }
    }
  }

  // sown by crossover: the best survivors in turn, each for its share of the children, with a
  // partner (Minemonics' code: as many parents as survivors x the crossover share)
  const auto parents = static_cast<std::size_t>(std::clamp<long>(
      std::lround(static_cast<double>(survivors) * settings.sow_crossover_fraction), 1,
      static_cast<long>(survivors)));
  const std::size_t per_parent =
      (static_cast<std::size_t>(plan.crossovers) + parents - 1) / parents;
  for (int n = 0; n < plan.crossovers; ++n) {
    const Individual& parent = survivor(static_cast<std::size_t>(n) / per_parent);
    const Individual& partner = survivor(reaperPartner(survivors, settings, selection));
    const Origin origin = settings.crossover == Variation::segment_crossover
                              ? Origin::segment_crossover
                              : Origin::crossover;
    add(origin, {parent.id, partner.id},
        [&encoding = encoding_, crossover = settings.crossover, first = parent.genome,
         second = partner.genome](Rng& rng, int) {
          return encoding.combine(crossover, first, second, rng);
        });
  }

  // sown at random: the streams (seed, random_genome, g * 2^16 + attempt, place in the
  // generation), apart from the first generation's (g = 0, attempt)
  for (int n = 0; n < plan.randoms; ++n) {
    const auto place = static_cast<std::uint64_t>(next.individuals.size());
    add(Origin::random, {},
        [&encoding = encoding_, seed = settings_.seed, g, place](Rng&, int attempt) {
          return encoding.random(seed, (g << 16) + static_cast<std::uint64_t>(attempt), place);
        });
  }
  return next;
}

}  // namespace cambrian
