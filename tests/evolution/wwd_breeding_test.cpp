// Tests of Walking with Dinosaurs' breeding (evolution.scheme = wwd): the plan's counts, the elites
// kept with their outcomes, every child a crossover of an elite into a breeder then mutated, the
// diversity-adaptive mutation multiplier on hand-made fitness lists, the first generation from a
// starting creature, determinism, and the settings refused.
#include "evolution/wwd_breeding.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/wwd/encoding.hpp"
#include "evolution/breeder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace cambrian {
namespace {

// the wwd encoding at its defaults, noting every combine and mutate it is asked for
class TracedWwd : public wwd::WwdEncoding {
 public:
  struct Combined {
    Genotype receiver, donor, child;
  };
  struct Mutated {
    Genotype parent, child;
    double rate = 0;
  };
  Genotype combine(Variation variation, const Genotype& a, const Genotype& b,
                   Rng& rng) const override {
    EXPECT_EQ(variation, Variation::crossover);
    Genotype child = WwdEncoding::combine(variation, a, b, rng);
    combined.push_back({a, b, child});
    return child;
  }
  Genotype mutate(const Genotype& parent, double rate, Rng& rng) const override {
    Genotype child = WwdEncoding::mutate(parent, rate, rng);
    mutated.push_back({parent, child, rate});
    return child;
  }
  void clear() const {
    combined.clear();
    mutated.clear();
  }
  mutable std::vector<Combined> combined;
  mutable std::vector<Mutated> mutated;
};

// the directed graph noting the rate of each mutation
class TracedGraph : public graph::DirectedGraphEncoding {
 public:
  Genotype mutate(const Genotype& parent, double rate, Rng& rng) const override {
    rates.push_back(rate);
    return DirectedGraphEncoding::mutate(parent, rate, rng);
  }
  mutable std::vector<double> rates;
};

EvolutionSettings wwdRun(int population) {
  EvolutionSettings s;
  s.scheme = BreedingScheme::wwd;
  s.population = population;
  s.seed = 31;
  return s;
}

// `population` with every genome made now (bred genomes are made when first read)
Population madeNow(Population population) {
  for (const Individual& individual : population.individuals)
    individual.genome.data();
  return population;
}

// the message of the ConfigError `settings` raise, or "" when valid
std::string problem(const EvolutionSettings& settings) {
  try {
    validateEvolutionSettings(settings);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// a deterministic stand-in for evaluation from the DNA (>= 0), ties by id; in the order given
void evaluate(Population& population, bool reverse = false) {
  std::vector<std::size_t> order(population.individuals.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = reverse ? order.size() - 1 - i : i;
  for (std::size_t index : order) {
    Individual& individual = population.individuals[index];
    if (individual.evaluated)
      continue;
    double sum = 0;
    const wwd::Dna& dna = wwd::dnaOf(individual.genome);
    for (std::size_t i = 0; i < std::min<std::size_t>(dna.size(), 40); ++i)
      sum += dna[i] % 97;
    individual.outcome.fitness = sum / 100 + 0.001 * static_cast<double>(individual.id % 7);
    individual.evaluated = true;
  }
}

std::vector<std::vector<std::uint8_t>> genomeBytes(const Population& population) {
  std::vector<std::vector<std::uint8_t>> bytes;
  for (const Individual& individual : population.individuals)
    bytes.push_back(individual.genome.bytes());
  return bytes;
}

// the seed's numbers: elites 20 %, breeders 30 %, every place but the elites' bred
TEST(WwdPlan, ElitesBreedersAndChildrenByTheSeedsShares) {
  WwdPlan ten = planWwd(wwdRun(10));
  EXPECT_EQ(ten.elites, 2);
  EXPECT_EQ(ten.breeders, 3);
  EXPECT_EQ(ten.children, 8);
  WwdPlan three_hundred = planWwd(wwdRun(300));
  EXPECT_EQ(three_hundred.elites, 60);
  EXPECT_EQ(three_hundred.breeders, 90);
  EXPECT_EQ(three_hundred.children, 240);
  for (int p = 4; p <= 301; p += 9) {
    const WwdPlan plan = planWwd(wwdRun(p));
    EXPECT_EQ(plan.elites + plan.children, p);
    EXPECT_GE(plan.elites, 1);
    EXPECT_GE(plan.breeders, 1);
    EXPECT_LE(plan.elites + plan.breeders, p);
  }
  // rounding both up never makes more elites and breeders than the population
  EvolutionSettings halves = wwdRun(10);
  halves.wwd.elite_fraction = 0.25;
  halves.wwd.breeder_fraction = 0.75;
  const WwdPlan plan = planWwd(halves);
  EXPECT_EQ(plan.elites, 3);
  EXPECT_EQ(plan.breeders, 7);
}

TEST(WwdSettings, TheSeedsNumbersAreTheDefaultsAndBadOnesAreRefusedByKey) {
  EvolutionSettings s = wwdRun(100);
  EXPECT_EQ(problem(s), "");
  EXPECT_DOUBLE_EQ(s.wwd.elite_fraction, 0.2);
  EXPECT_DOUBLE_EQ(s.wwd.breeder_fraction, 0.3);
  EXPECT_TRUE(s.wwd.adaptive_mutation);

  auto refused = [](EvolutionSettings settings, const std::string& text) {
    const std::string message = problem(settings);
    EXPECT_NE(message.find(text), std::string::npos)
        << "'" << message << "' lacks '" << text << "'";
  };
  s = wwdRun(100);
  s.wwd.elite_fraction = 0;
  refused(s, "evolution.wwd_elite_fraction = 0: must be in (0, 1)");
  s = wwdRun(100);
  s.wwd.elite_fraction = 1;
  refused(s, "evolution.wwd_elite_fraction = 1: must be in (0, 1)");
  s = wwdRun(100);
  s.wwd.breeder_fraction = 1.5;
  refused(s, "evolution.wwd_breeder_fraction = 1.5: must be in (0, 1)");
  s = wwdRun(100);
  s.wwd.elite_fraction = 0.6;
  s.wwd.breeder_fraction = 0.5;
  refused(s,
          "evolution.wwd_elite_fraction + evolution.wwd_breeder_fraction = 1.1: must be at "
          "most 1");
  // too small a population for an elite, or for a breeder after the elites
  s = wwdRun(2);
  s.selection.tournament_size = 2;
  refused(s, "evolution.wwd_elite_fraction = 0.2: no elite in evolution.population = 2");
  s = wwdRun(3);
  s.wwd.breeder_fraction = 0.1;
  refused(s, "evolution.wwd_breeder_fraction = 0.1: no breeder in evolution.population = 3");
  s = wwdRun(100);
  s.wwd.min_multiplier = 5;
  refused(s, "evolution.wwd_min_multiplier = 5 is above evolution.wwd_max_multiplier = 4");
  s = wwdRun(100);
  s.wwd.target_deviation = 0;
  refused(s, "evolution.wwd_target_deviation = 0");
  // under another scheme the population need not hold an elite of the wwd scheme
  s = wwdRun(2);
  s.selection.tournament_size = 2;
  s.scheme = BreedingScheme::generational;
  EXPECT_EQ(problem(s), "");
  s = wwdRun(5);
  s.seed_genomes = {"a", "b", "c", "d", "e"};
  s.seed_history = "run/history.h5";
  refused(s, "evolution.seed_history = run/history.h5: more seed genomes");
}

// the seed's Deviation: less spread, more mutation; on the normalised fitnesses, so any scale of
// the same fitnesses gives the same multiplier
TEST(WwdMutationScale, TheLessTheFitnessesSpreadTheMoreItMutates) {
  const WwdSettings settings;  // target 0.25, multipliers 0.5 .. 4
  // all equal (and all failed): no spread, the most mutation
  EXPECT_EQ(mutationScale(settings, {3, 3, 3, 3}).deviation, 0);
  EXPECT_EQ(mutationScale(settings, {3, 3, 3, 3}).multiplier, 4);
  EXPECT_EQ(mutationScale(settings, {0, 0, 0}).deviation, 0);
  EXPECT_EQ(mutationScale(settings, {0, 0, 0}).multiplier, 4);
  EXPECT_EQ(mutationScale(settings, {}).multiplier, 4);
  // half the best, half failed: the widest normalised spread (0.5), the least mutation
  EXPECT_DOUBLE_EQ(mutationScale(settings, {8, 0, 8, 0}).deviation, 0.5);
  EXPECT_EQ(mutationScale(settings, {8, 0, 8, 0}).multiplier, 0.5);
  // by hand: {4, 2, 2, 0} / 4 = {1, .5, .5, 0}, mean .5, variance (.25 + 0 + 0 + .25) / 4 =
  // .125, s = .35355, m = .25 / .35355 = 1 / sqrt(2)
  const MutationScale spread = mutationScale(settings, {4, 2, 2, 0});
  EXPECT_NEAR(spread.deviation, std::sqrt(0.125), 1e-15);
  EXPECT_NEAR(spread.multiplier, 1 / std::sqrt(2.0), 1e-15);
  // by hand: {10, 9, 8, 7} / 10, mean .85, variance (.0225 + .0025 + .0025 + .0225) / 4 = .0125,
  // m = .25 / sqrt(.0125) = sqrt(5)
  EXPECT_NEAR(mutationScale(settings, {10, 9, 8, 7}).multiplier, std::sqrt(5.0), 1e-12);
  // the scale of the fitnesses does not matter, nor their order (to the bit)
  EXPECT_NEAR(mutationScale(settings, {4000, 2000, 2000, 0}).multiplier, spread.multiplier, 1e-15);
  EXPECT_EQ(mutationScale(settings, {2, 0, 4, 2}).multiplier, spread.multiplier);
  EXPECT_EQ(mutationScale(settings, {0.1, 0.7, 0.3, 0.2, 0.9}).deviation,
            mutationScale(settings, {0.9, 0.2, 0.1, 0.3, 0.7}).deviation);
  // the settings: the target and the bounds; off, no scaling (the deviation still)
  WwdSettings other;
  other.target_deviation = 0.1;
  other.min_multiplier = 0.8;
  EXPECT_EQ(mutationScale(other, {8, 0, 8, 0}).multiplier, 0.8);
  EXPECT_NEAR(mutationScale(other, {10, 9, 8, 7}).multiplier, 0.1 / std::sqrt(0.0125), 1e-12);
  other.adaptive_mutation = false;
  EXPECT_EQ(mutationScale(other, {3, 3, 3}).multiplier, 1);
  EXPECT_DOUBLE_EQ(mutationScale(other, {8, 0, 8, 0}).deviation, 0.5);
}

TEST(WwdMutationScale, OfAPopulationUnderEachScheme) {
  Population population;
  for (std::uint64_t id = 0; id < 4; ++id) {
    Individual individual;
    individual.id = id;
    individual.outcome.fitness = id == 3 ? NAN : 2.0 * static_cast<double>(id);  // 0, 2, 4, NaN
    individual.evaluated = true;
    population.individuals.push_back(individual);
  }
  // the NaN counts as a failure (0): {0, 2, 4, 0} / 4
  EvolutionSettings settings = wwdRun(4);
  const MutationScale scale = mutationScale(settings, population);
  EXPECT_EQ(scale.multiplier, mutationScale(settings.wwd, {0, 2, 4, 0}).multiplier);
  EXPECT_GT(scale.multiplier, 0.5);
  EXPECT_LT(scale.multiplier, 4);
  settings.scheme = BreedingScheme::reaper;
  EXPECT_EQ(mutationScale(settings, population).multiplier, 1);
  EXPECT_EQ(mutationScale(settings, population).deviation, scale.deviation);
}

// the elites are the best, kept with their outcomes (not evaluated again); every other place is a
// crossover of an elite into a breeder, then mutated at the multiplier; over several generations
TEST(WwdBreeding, ElitesStayAndEveryChildIsAnEliteCrossedIntoABreederThenMutated) {
  const TracedWwd encoding;
  const EvolutionSettings settings = wwdRun(10);
  Breeder breeder(settings, encoding);
  Population population = breeder.initialPopulation();
  std::set<std::uint64_t> elite_parents, breeder_parents;
  for (int generation = 1; generation <= 6; ++generation) {
    evaluate(population);
    const std::vector<std::size_t> ranking = population.ranking();
    std::map<std::uint64_t, const Individual*> by_id;
    for (const Individual& individual : population.individuals)
      by_id[individual.id] = &individual;
    std::set<std::uint64_t> elites, breeders;
    for (std::size_t r = 0; r < 5; ++r)
      (r < 2 ? elites : breeders).insert(population.individuals[ranking[r]].id);
    const double multiplier = mutationScale(settings, population).multiplier;

    encoding.clear();
    const Population next = madeNow(breeder.nextGeneration(population));
    ASSERT_EQ(next.individuals.size(), 10u);
    EXPECT_EQ(next.generation, population.generation + 1);
    ASSERT_EQ(encoding.combined.size(), 8u);
    ASSERT_EQ(encoding.mutated.size(), 8u);
    for (std::size_t i = 0; i < next.individuals.size(); ++i) {
      const Individual& child = next.individuals[i];
      if (i < 2) {
        // the elites: the best two in rank order, with their outcomes
        const Individual& best = population.individuals[ranking[i]];
        EXPECT_EQ(child.origin, Origin::elite);
        EXPECT_EQ(child.parents, std::vector<std::uint64_t>{best.id});
        EXPECT_EQ(child.genome, best.genome);
        EXPECT_TRUE(child.evaluated);
        EXPECT_EQ(child.outcome.fitness, best.outcome.fitness);
        EXPECT_EQ(child.worker_rank, -1);
        continue;
      }
      // a breeder (the receiver, first) and an elite
      EXPECT_EQ(child.origin, Origin::crossover);
      EXPECT_FALSE(child.evaluated);
      ASSERT_EQ(child.parents.size(), 2u);
      EXPECT_TRUE(breeders.count(child.parents[0]))
          << "generation " << generation << " child " << i;
      EXPECT_TRUE(elites.count(child.parents[1])) << "generation " << generation << " child " << i;
      breeder_parents.insert(child.parents[0]);
      elite_parents.insert(child.parents[1]);
      // the breeder received a part of the elite, then the child was mutated
      const TracedWwd::Combined& combined = encoding.combined[i - 2];
      const TracedWwd::Mutated& mutated = encoding.mutated[i - 2];
      EXPECT_EQ(combined.receiver, by_id.at(child.parents[0])->genome);
      EXPECT_EQ(combined.donor, by_id.at(child.parents[1])->genome);
      EXPECT_EQ(mutated.parent, combined.child);
      EXPECT_EQ(mutated.rate, multiplier);
      EXPECT_EQ(child.genome, mutated.child);
      ASSERT_NO_THROW(encoding.validate(child.genome));
    }
    for (std::size_t i = 1; i < next.individuals.size(); ++i)
      EXPECT_GT(next.individuals[i].id, next.individuals[i - 1].id);
    population = next;
  }
  // drawn from the whole of each group
  EXPECT_GE(elite_parents.size(), 6u);
  EXPECT_GE(breeder_parents.size(), 10u);
}

// the groups by rank: with a population of 300, 60 elites kept and 240 children of the next 90
TEST(WwdBreeding, ThreeHundredKeepSixtyAndBreedTwoHundredAndFortyFromTheNextNinety) {
  const wwd::WwdEncoding encoding;
  Breeder breeder(wwdRun(300), encoding);
  Population population = breeder.initialPopulation();
  evaluate(population);
  const std::vector<std::size_t> ranking = population.ranking();
  std::map<std::uint64_t, std::size_t> rank_of;
  for (std::size_t r = 0; r < ranking.size(); ++r)
    rank_of[population.individuals[ranking[r]].id] = r;
  const Population next = breeder.nextGeneration(population);
  std::map<Origin, int> counts;
  std::set<std::uint64_t> elite_parents, breeder_parents;
  for (const Individual& child : next.individuals) {
    ++counts[child.origin];
    if (child.origin == Origin::elite) {
      EXPECT_LT(rank_of.at(child.parents[0]), 60u);
      continue;
    }
    EXPECT_GE(rank_of.at(child.parents[0]), 60u);
    EXPECT_LT(rank_of.at(child.parents[0]), 150u);
    EXPECT_LT(rank_of.at(child.parents[1]), 60u);
    breeder_parents.insert(child.parents[0]);
    elite_parents.insert(child.parents[1]);
  }
  EXPECT_EQ(counts[Origin::elite], 60);
  EXPECT_EQ(counts[Origin::crossover], 240);
  EXPECT_EQ(next.individuals.size(), 300u);
  // 240 uniform draws among 60 and among 90: most of each group breeds
  EXPECT_GT(elite_parents.size(), 45u);
  EXPECT_GT(breeder_parents.size(), 60u);
}

// another encoding mutates at evolution.mutation_rate x the multiplier (at most 1): a
// generation of equals mutates 4 times as much
TEST(WwdBreeding, AnotherEncodingMutatesAtTheMutationRateTimesTheMultiplier) {
  const TracedGraph encoding;
  EvolutionSettings settings = wwdRun(10);
  settings.mutation_rate = 0.1;
  Breeder breeder(settings, encoding);
  Population population = breeder.initialPopulation();
  for (Individual& individual : population.individuals) {
    individual.outcome.fitness = 2;
    individual.evaluated = true;
  }
  encoding.rates.clear();
  madeNow(breeder.nextGeneration(population));
  ASSERT_EQ(encoding.rates.size(), 8u);
  for (double rate : encoding.rates)
    EXPECT_DOUBLE_EQ(rate, 0.4);
  EXPECT_EQ(wwdMutationRate(encoding, settings, 2.5), 0.25);
  settings.mutation_rate = 0.5;
  EXPECT_EQ(wwdMutationRate(encoding, settings, 4), 1);
  EXPECT_EQ(wwdMutationRate(wwd::WwdEncoding(), settings, 4), 4);
}

// the seed's framework: the starting creature, then the population filled with mutated copies
// of it (as a bred child is mutated at multiplier 1: the wwd encoding at its own chance per gene)
TEST(WwdBreeding, TheFirstGenerationIsTheStartingCreatureAndMutatedCopiesOfIt) {
  const TracedWwd encoding;
  const Genotype start = encoding.random(5, 0, 0);
  Breeder breeder(wwdRun(20), encoding);
  const Population first = breeder.initialPopulation({start});
  ASSERT_EQ(first.individuals.size(), 20u);
  EXPECT_EQ(first.individuals[0].origin, Origin::seed);
  EXPECT_EQ(first.individuals[0].genome, start);
  int changed = 0;
  for (std::size_t i = 1; i < first.individuals.size(); ++i) {
    EXPECT_EQ(first.individuals[i].origin, Origin::mutation);
    EXPECT_EQ(first.individuals[i].parents, std::vector<std::uint64_t>{0});
    changed += !(first.individuals[i].genome == start);
  }
  ASSERT_EQ(encoding.mutated.size(), 19u);
  for (const TracedWwd::Mutated& mutated : encoding.mutated) {
    EXPECT_EQ(mutated.parent, start);
    EXPECT_EQ(mutated.rate, 1);
  }
  // about one gene in n each: most copies differ a little
  EXPECT_GT(changed, 5);
}

// a generation is a pure function of the last one's genomes and fitnesses: the same run twice,
// or its outcomes filled in in another order, breeds the same bytes
TEST(WwdBreeding, IsDeterministicAndIndependentOfTheOrderOfEvaluation) {
  auto run = [](bool reverse) {
    const wwd::WwdEncoding encoding;
    Breeder breeder(wwdRun(16), encoding);
    Population population = breeder.initialPopulation();
    std::vector<std::uint64_t> ids;
    for (int g = 0; g < 5; ++g) {
      evaluate(population, reverse);
      population = breeder.nextGeneration(population);
    }
    for (const Individual& individual : population.individuals) {
      ids.push_back(individual.id);
      for (std::uint64_t parent : individual.parents)
        ids.push_back(parent);
    }
    return std::make_pair(genomeBytes(population), ids);
  };
  const auto once = run(false);
  EXPECT_EQ(once, run(false));
  EXPECT_EQ(once, run(true));
  // another run seed breeds otherwise
  const wwd::WwdEncoding encoding;
  EvolutionSettings other = wwdRun(16);
  other.seed = 32;
  Breeder breeder(other, encoding);
  Population population = breeder.initialPopulation();
  for (int g = 0; g < 5; ++g) {
    evaluate(population);
    population = breeder.nextGeneration(population);
  }
  EXPECT_NE(genomeBytes(population), once.first);
}

// an encoding without crossover cannot breed the wwd scheme
class NoCrossover : public graph::DirectedGraphEncoding {
 public:
  bool supports(Variation variation) const override { return variation != Variation::crossover; }
};

TEST(WwdBreeding, RefusesAnEncodingWithoutCrossover) {
  NoCrossover encoding;
  try {
    Breeder breeder(wwdRun(10), encoding);
    FAIL() << "an encoding without crossover was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("evolution.scheme = wwd"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no crossover"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(Breeder(wwdRun(10), graph::DirectedGraphEncoding()));
}

}  // namespace
}  // namespace cambrian
