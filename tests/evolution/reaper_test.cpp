// Tests of Minemonics' reaper: the apportioned plan, partners, and generations bred by it — the
// culled never breed, the kept are the best, every kind in its share over many generations,
// determinism.
#include "evolution/reaper.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "evolution/breeder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace cambrian {
namespace {

const graph::DirectedGraphEncoding kEncoding;

EvolutionSettings reaperRun(int population) {
  EvolutionSettings s;
  s.scheme = BreedingScheme::reaper;
  s.population = population;
  s.seed = 21;
  return s;
}

// a deterministic stand-in for evaluation: the genome's summed box length, ties by id
void evaluate(Population& population) {
  for (Individual& individual : population.individuals) {
    if (individual.evaluated)
      continue;
    double side = 0;
    for (const graph::PartGene& node : graph::graphGenome(individual.genome).nodes)
      side += node.dimensions.x;
    individual.outcome.fitness = side + 0.001 * static_cast<double>(individual.id % 7);
    individual.evaluated = true;
  }
}

TEST(Apportion, SplitsByLargestRemaindersAndSums) {
  const std::vector<double> seven(7, 1.0);
  EXPECT_EQ(apportion(70, seven), std::vector<int>(7, 10));
  EXPECT_EQ(apportion(10, seven), (std::vector<int>{2, 2, 2, 1, 1, 1, 1}));
  EXPECT_EQ(apportion(3, std::vector<double>{0, 2, 1}), (std::vector<int>{0, 2, 1}));
  EXPECT_EQ(apportion(0, seven), std::vector<int>(7, 0));
  for (int total = 0; total < 60; ++total) {
    const std::vector<int> counts = apportion(total, std::vector<double>{0.3, 1, 0, 2.5});
    EXPECT_EQ(counts[2], 0);
    int sum = 0;
    for (int c : counts)
      sum += c;
    EXPECT_EQ(sum, total);
  }
}

// the thesis' numbers: 30 % culled, the rest in sevenths, the culled sown half by crossover
TEST(ReaperPlan, CullsVariesAndSowsByTheShares) {
  ReaperPlan hundred = planReaper(reaperRun(100));
  EXPECT_EQ(hundred.culled, 30);
  EXPECT_EQ(std::vector<int>(hundred.survivors.begin(), hundred.survivors.end()),
            std::vector<int>(7, 10));
  EXPECT_EQ(hundred.crossovers, 15);
  EXPECT_EQ(hundred.randoms, 15);
  ReaperPlan ten = planReaper(reaperRun(10));
  EXPECT_EQ(ten.culled, 3);
  EXPECT_EQ(std::vector<int>(ten.survivors.begin(), ten.survivors.end()), std::vector<int>(7, 1));
  EXPECT_EQ(ten.crossovers + ten.randoms, 3);
  // rounded up, as Minemonics' code does, but one always survives
  EXPECT_EQ(planReaper(reaperRun(11)).culled, 4);
  EvolutionSettings almost_all = reaperRun(2);
  almost_all.reaper.reap_fraction = 0.99;
  EXPECT_EQ(planReaper(almost_all).culled, 1);
}

// partners: with tournaments they come from the top, never past the last; without, uniformly
TEST(ReaperPartner, TournamentsFavourTheTopAndUniformDrawsDoNot) {
  ReaperSettings settings;
  settings.tournament_chance = 1;
  Rng rng(22, RngPurpose::test);
  std::vector<int> hits(70, 0);
  for (int i = 0; i < 20000; ++i) {
    std::size_t partner = reaperPartner(70, settings, rng);
    ASSERT_LT(partner, 70u);
    ++hits[partner];
  }
  // ten half-normal contestants with sigma 70/3: the best is mostly among the first few
  EXPECT_GT(hits[0], 20000 / 4);
  int top_ten = 0;
  for (int k = 0; k < 10; ++k)
    top_ten += hits[static_cast<std::size_t>(k)];
  EXPECT_GT(top_ten, 20000 * 9 / 10);
  settings.tournament_chance = 0;
  std::fill(hits.begin(), hits.end(), 0);
  for (int i = 0; i < 70000; ++i)
    ++hits[reaperPartner(70, settings, rng)];
  for (int h : hits) {
    EXPECT_GT(h, 800);
    EXPECT_LT(h, 1200);
  }
  EXPECT_EQ(reaperPartner(1, settings, rng), 0u);
}

// evolution.reaper_crossover = segment_crossover sows by Minemonics' crossover, recorded as such
TEST(Reaper, SowsBySegmentCrossoverWhenChosen) {
  EvolutionSettings settings = reaperRun(40);
  settings.reaper.crossover = Variation::segment_crossover;
  const ReaperPlan plan = planReaper(settings);
  Breeder breeder(settings, kEncoding);
  Population population = breeder.initialPopulation();
  evaluate(population);
  const Population next = breeder.nextGeneration(population);
  int segments = 0, crossovers = 0;
  for (const Individual& child : next.individuals) {
    segments += child.origin == Origin::segment_crossover;
    crossovers += child.origin == Origin::crossover;
    if (child.origin == Origin::segment_crossover) {
      EXPECT_EQ(child.parents.size(), 2u);
    }
    ASSERT_NO_THROW(kEncoding.validate(child.genome));
  }
  EXPECT_EQ(segments, plan.crossovers);
  EXPECT_EQ(crossovers, 0);
  EXPECT_STREQ(originName(Origin::segment_crossover), "segment_crossover");
}

// over many generations: every generation has the plan's kinds in their counts, the kept are
// the best survivors with their outcomes, no culled individual is a parent, and every genome is
// valid
TEST(Reaper, EveryGenerationHasItsSharesAndTheCulledNeverBreed) {
  const EvolutionSettings settings = reaperRun(40);
  const ReaperPlan plan = planReaper(settings);
  Breeder breeder(settings, kEncoding);
  Population population = breeder.initialPopulation();
  std::map<Origin, int> totals;
  for (int generation = 1; generation <= 25; ++generation) {
    evaluate(population);
    const std::vector<std::size_t> ranking = population.ranking();
    std::set<std::uint64_t> culled, survivors;
    for (std::size_t r = 0; r < ranking.size(); ++r) {
      const std::uint64_t id = population.individuals[ranking[r]].id;
      (r < ranking.size() - static_cast<std::size_t>(plan.culled) ? survivors : culled).insert(id);
    }
    Population next = breeder.nextGeneration(population);
    ASSERT_EQ(next.individuals.size(), 40u);
    std::map<Origin, int> counts;
    for (std::size_t i = 0; i < next.individuals.size(); ++i) {
      const Individual& child = next.individuals[i];
      ++counts[child.origin];
      ++totals[child.origin];
      for (std::uint64_t parent : child.parents) {
        EXPECT_TRUE(survivors.count(parent)) << "generation " << generation << " child " << i;
        EXPECT_FALSE(culled.count(parent));
      }
      ASSERT_NO_THROW(kEncoding.validate(child.genome));
      // the kept come first: the best survivors, in rank order, with their outcomes
      if (i < static_cast<std::size_t>(plan.survivors[0])) {
        const Individual& best = population.individuals[ranking[i]];
        EXPECT_EQ(child.origin, Origin::elite);
        EXPECT_EQ(child.parents, std::vector<std::uint64_t>{best.id});
        EXPECT_TRUE(child.evaluated);
        EXPECT_EQ(child.outcome.fitness, best.outcome.fitness);
      } else {
        EXPECT_FALSE(child.evaluated);
      }
    }
    EXPECT_EQ(counts[Origin::elite], plan.survivors[0]);
    EXPECT_EQ(counts[Origin::gene_specification], plan.survivors[1]);
    EXPECT_EQ(counts[Origin::gene_split], plan.survivors[2]);
    EXPECT_EQ(counts[Origin::gene_purge], plan.survivors[3]);
    EXPECT_EQ(counts[Origin::branch_specification], plan.survivors[4]);
    EXPECT_EQ(counts[Origin::grow_stub], plan.survivors[5]);
    EXPECT_EQ(counts[Origin::graft_feature], plan.survivors[6]);
    EXPECT_EQ(counts[Origin::crossover], plan.crossovers);
    EXPECT_EQ(counts[Origin::random], plan.randoms);
    population = std::move(next);
  }
  // the thesis' shares of the whole run: 70 % survivors in sevenths (4 each of 40 here), 30 %
  // sown half and half
  EXPECT_EQ(totals[Origin::gene_split], 25 * 4);
  EXPECT_EQ(totals[Origin::crossover] + totals[Origin::random], 25 * 12);
}

// the varied survivors are varied: most differ from their parent (a gene split or purge with
// nothing to act on may leave one unchanged)
TEST(Reaper, VariedSurvivorsMostlyDifferFromTheirParents) {
  Breeder breeder(reaperRun(70), kEncoding);
  Population population = breeder.initialPopulation();
  evaluate(population);
  std::map<std::uint64_t, const Individual*> by_id;
  for (const Individual& individual : population.individuals)
    by_id[individual.id] = &individual;
  Population next = breeder.nextGeneration(population);
  int varied = 0, changed = 0;
  for (const Individual& child : next.individuals) {
    if (child.origin == Origin::elite || child.origin == Origin::random ||
        child.origin == Origin::crossover)
      continue;
    ++varied;
    changed += !(child.genome == by_id.at(child.parents[0])->genome);
  }
  // 70 - 21 culled = 49 survivors, 7 kept and 6 x 7 varied
  EXPECT_EQ(varied, 42);
  EXPECT_GT(changed, varied / 2);
}

// same settings, same generations: the reaper is a pure function of the last generation
TEST(Reaper, IsDeterministic) {
  auto run = [] {
    Breeder breeder(reaperRun(30), kEncoding);
    Population population = breeder.initialPopulation();
    for (int g = 0; g < 5; ++g) {
      evaluate(population);
      population = breeder.nextGeneration(population);
    }
    std::vector<std::vector<std::uint8_t>> bytes;
    for (const Individual& individual : population.individuals)
      bytes.push_back(individual.genome.bytes());
    return bytes;
  };
  EXPECT_EQ(run(), run());
}

// an encoding without one of the reaper's operators cannot breed a plan that uses it
class NoSplit : public graph::DirectedGraphEncoding {
 public:
  bool supports(Variation variation) const override { return variation != Variation::gene_split; }
};

TEST(Reaper, RefusesAPlanTheEncodingCannotBreed) {
  NoSplit encoding;
  try {
    Breeder breeder(reaperRun(20), encoding);
    FAIL() << "a plan with gene splits was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("evolution.reaper_gene_split_share"), std::string::npos)
        << e.what();
  }
  EvolutionSettings no_splits = reaperRun(20);
  no_splits.reaper.shares[static_cast<std::size_t>(ReaperShare::gene_split)] = 0;
  EXPECT_NO_THROW(Breeder(no_splits, encoding));
}

}  // namespace
}  // namespace cambrian
