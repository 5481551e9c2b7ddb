// Tests of the Sims / Chaumont breeding scheme over an encoding: the plan, the initial
// population, elites, viability redraws, independence from arrival order, ids.
#include "evolution/breeder.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace cambrian {
namespace {

// the encoding the breeder varies: the directed graph at its defaults
const graph::DirectedGraphEncoding kEncoding;

// a deterministic stand-in for evaluation: fitness from the genome's size and id
Outcome fakeOutcome(const Individual& individual) {
  Outcome outcome;
  double side = 0;
  for (const graph::PartGene& node : graph::graphGenome(individual.genome).nodes)
    side += node.dimensions.x;
  outcome.fitness = side + 0.001 * static_cast<double>(individual.id % 7);
  return outcome;
}

// fills every missing outcome, in the given order of indices
void fill(Population& population, const std::vector<std::size_t>& order) {
  for (std::size_t index : order) {
    Individual& individual = population.individuals[index];
    if (individual.evaluated)
      continue;
    individual.outcome = fakeOutcome(individual);
    individual.evaluated = true;
  }
}

// indices 0..n-1, forwards or backwards
std::vector<std::size_t> indices(std::size_t n, bool reverse) {
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = reverse ? n - 1 - i : i;
  return order;
}

EvolutionSettings smallRun() {
  EvolutionSettings s;
  s.population = 20;
  s.generations = 4;
  s.seed = 11;
  return s;
}

TEST(BreedingPlan, SplitsByTheFractionsAndSumsToThePopulation) {
  EvolutionSettings s;
  s.population = 100;
  BreedingPlan plan = planBreeding(s);
  EXPECT_EQ(plan.elites, 20);
  EXPECT_EQ(plan.mutations, 32);
  EXPECT_EQ(plan.crossovers, 24);
  EXPECT_EQ(plan.grafts, 24);
  for (int p = 2; p <= 301; p += 7) {
    s.population = p;
    EXPECT_EQ(planBreeding(s).total(), p) << "population " << p;
    EXPECT_GE(planBreeding(s).grafts, 0);
  }
  s.population = 10;
  s.elite_fraction = 0;
  s.mutation_fraction = 1;
  s.crossover_fraction = s.graft_fraction = 0;
  plan = planBreeding(s);
  EXPECT_EQ(plan.elites, 0);
  EXPECT_EQ(plan.mutations, 10);
}

TEST(Breeder, InitialPopulationIsRandomWithIncreasingIds) {
  Breeder breeder(smallRun(), kEncoding);
  Population p = breeder.initialPopulation();
  ASSERT_EQ(p.individuals.size(), 20u);
  for (std::size_t i = 0; i < p.individuals.size(); ++i) {
    EXPECT_EQ(p.individuals[i].id, i);
    EXPECT_EQ(p.individuals[i].origin, Origin::random);
    EXPECT_FALSE(p.individuals[i].evaluated);
  }
  EXPECT_EQ(breeder.nextId(), 20u);
}

TEST(Breeder, SeededPopulationStartsWithTheSeedsThenMutatedCopies) {
  Genotype seed = kEncoding.random(99, 0, 0);
  Breeder breeder(smallRun(), kEncoding);
  Population p = breeder.initialPopulation({seed});
  EXPECT_EQ(p.individuals[0].origin, Origin::seed);
  EXPECT_EQ(p.individuals[0].genome, seed);
  for (std::size_t i = 1; i < p.individuals.size(); ++i) {
    EXPECT_EQ(p.individuals[i].origin, Origin::mutation);
    EXPECT_EQ(p.individuals[i].parents, (std::vector<std::uint64_t>{0}));
  }
}

TEST(Breeder, ElitesAreTheBestCopiedWithTheirOutcomesAndNotReEvaluated) {
  Breeder breeder(smallRun(), kEncoding);
  Population first = breeder.initialPopulation();
  fill(first, indices(first.individuals.size(), false));
  std::vector<std::size_t> ranking = first.ranking();
  Population second = breeder.nextGeneration(first);
  ASSERT_EQ(second.individuals.size(), 20u);
  int elites = breeder.plan().elites;
  ASSERT_EQ(elites, 4);
  for (int e = 0; e < elites; ++e) {
    const Individual& copy = second.individuals[static_cast<std::size_t>(e)];
    const Individual& original = first.individuals[ranking[static_cast<std::size_t>(e)]];
    EXPECT_EQ(copy.origin, Origin::elite);
    EXPECT_EQ(copy.parents, (std::vector<std::uint64_t>{original.id}));
    EXPECT_EQ(copy.genome, original.genome);
    EXPECT_TRUE(copy.evaluated);
    EXPECT_EQ(copy.outcome.fitness, original.outcome.fitness);
    EXPECT_EQ(copy.worker_rank, -1);
  }
  // offspring wait for evaluation, in plan order
  for (std::size_t i = static_cast<std::size_t>(elites); i < second.individuals.size(); ++i) {
    EXPECT_FALSE(second.individuals[i].evaluated);
  }
  EXPECT_EQ(second.individuals[4].origin, Origin::mutation);
  EXPECT_EQ(second.individuals.back().origin, Origin::graft);
  EXPECT_EQ(second.individuals.back().parents.size(), 2u);
}

// short batches (evolution.batch_generations = 2): generations 1 and 3 are bred as usual,
// generations 2 and 4 start again from the best (status ok) of the generation before: it first,
// with its outcome, then mutated copies of it alone; the same under every scheme
TEST(Breeder, AShortBatchStartsAgainFromTheBestCreatureAlone) {
  for (BreedingScheme scheme : {BreedingScheme::generational, BreedingScheme::wwd}) {
    SCOPED_TRACE(static_cast<int>(scheme));
    EvolutionSettings settings = smallRun();
    settings.scheme = scheme;
    settings.batch_generations = 2;
    Breeder breeder(settings, kEncoding);
    Population generation = breeder.initialPopulation();
    for (int g = 1; g <= 4; ++g) {
      fill(generation, indices(generation.individuals.size(), false));
      // the best ok individual: make the top of the ranking fail so that the rule shows
      std::vector<std::size_t> ranking = generation.ranking();
      generation.individuals[ranking[0]].outcome.status = EvalStatus::unstable;
      const Individual& best = generation.individuals[ranking[1]];
      Population next = breeder.nextGeneration(generation);
      ASSERT_EQ(next.individuals.size(), 20u);
      const bool restart = g % 2 == 0;
      std::set<std::uint64_t> parents;
      for (std::size_t i = 1; i < next.individuals.size(); ++i) {
        for (std::uint64_t parent : next.individuals[i].parents)
          parents.insert(parent);
      }
      if (restart) {
        EXPECT_EQ(next.individuals[0].genome, best.genome) << "generation " << g;
        EXPECT_EQ(next.individuals[0].origin, Origin::elite);
        EXPECT_TRUE(next.individuals[0].evaluated);
        EXPECT_EQ(next.individuals[0].outcome.fitness, best.outcome.fitness);
        EXPECT_EQ(parents, (std::set<std::uint64_t>{best.id})) << "generation " << g;
        for (std::size_t i = 1; i < next.individuals.size(); ++i) {
          EXPECT_EQ(next.individuals[i].origin, Origin::mutation);
          EXPECT_FALSE(next.individuals[i].evaluated);
        }
      } else {
        EXPECT_GT(parents.size(), 1u) << "generation " << g;
      }
      generation = std::move(next);
    }
  }
}

TEST(Breeder, EveryIndividualsGenomeBytesAreItsSerializedGenome) {
  // the bytes rank 0 sends, digests and stores are computed once per individual, and elites
  // inherit their parent's
  Breeder breeder(smallRun(), kEncoding);
  Population first = breeder.initialPopulation();
  fill(first, indices(first.individuals.size(), false));
  for (const Individual& individual : first.individuals)
    ASSERT_EQ(individual.genomeBytes(),
              graph::serializeGenome(graph::graphGenome(individual.genome)))
        << individual.id;
  Population second = breeder.nextGeneration(first);
  for (const Individual& individual : second.individuals) {
    EXPECT_EQ(individual.genomeBytes(),
              graph::serializeGenome(graph::graphGenome(individual.genome)))
        << individual.id;
    // an elite shares its parent's genome and bytes
    if (individual.origin == Origin::elite) {
      const Individual& parent = first.individuals[first.indexOf(individual.parents[0])];
      EXPECT_EQ(&individual.genomeBytes(), &parent.genomeBytes()) << individual.id;
    }
  }
}

TEST(Breeder, BestFitnessNeverDrops) {
  Breeder breeder(smallRun(), kEncoding);
  Population p = breeder.initialPopulation();
  double best = -1;
  for (int g = 0; g < 6; ++g) {
    fill(p, indices(p.individuals.size(), false));
    double now = p.individuals[p.ranking().front()].fitness();
    EXPECT_GE(now, best);
    best = now;
    p = breeder.nextGeneration(p);
  }
}

// new individuals that fail the birth test are redrawn; the redraws are deterministic
TEST(Breeder, ViabilityCheckRedrawsNewIndividuals) {
  // an arbitrary test half of all genomes pass: even byte sum of the serialized form
  auto small = [](const Genotype& genome) {
    unsigned sum = 0;
    for (std::uint8_t byte : genome.bytes())
      sum += byte;
    return sum % 2 == 0;
  };
  Breeder first(smallRun(), kEncoding), second(smallRun(), kEncoding);
  first.setViabilityCheck(small);
  second.setViabilityCheck(small);
  Population a = first.initialPopulation(), b = second.initialPopulation();
  for (int g = 0; g < 3; ++g) {
    for (const Individual& individual : a.individuals) {
      if (individual.origin != Origin::elite) {
        EXPECT_TRUE(small(individual.genome));
      }
    }
    fill(a, indices(a.individuals.size(), false));
    fill(b, indices(b.individuals.size(), false));
    a = first.nextGeneration(a);
    b = second.nextGeneration(b);
    for (std::size_t i = 0; i < a.individuals.size(); ++i) {
      EXPECT_TRUE(a.individuals[i].genome == b.individuals[i].genome);
    }
  }
}

// a check nothing passes still ends: the last attempt is kept
TEST(Breeder, ImpossibleViabilityCheckStillBreeds) {
  Breeder breeder(smallRun(), kEncoding);
  breeder.setViabilityCheck([](const Genotype&) { return false; }, 3);
  Population p = breeder.initialPopulation();
  EXPECT_EQ(p.individuals.size(), 20u);
  fill(p, indices(p.individuals.size(), false));
  EXPECT_EQ(breeder.nextGeneration(p).individuals.size(), 20u);
}

TEST(Breeder, GenerationsDoNotDependOnTheOrderOutcomesArrive) {
  Breeder forward(smallRun(), kEncoding), backward(smallRun(), kEncoding);
  Population a = forward.initialPopulation(), b = backward.initialPopulation();
  for (int g = 0; g < 3; ++g) {
    fill(a, indices(a.individuals.size(), false));
    fill(b, indices(b.individuals.size(), true));
    a = forward.nextGeneration(a);
    b = backward.nextGeneration(b);
    ASSERT_EQ(a.individuals.size(), b.individuals.size());
    for (std::size_t i = 0; i < a.individuals.size(); ++i) {
      EXPECT_EQ(a.individuals[i].id, b.individuals[i].id);
      EXPECT_EQ(a.individuals[i].parents, b.individuals[i].parents);
      EXPECT_TRUE(a.individuals[i].genome == b.individuals[i].genome);
    }
  }
}

// bred genomes are made when first read: in any order, after the breeder is gone, the same
TEST(Breeder, BredGenomesAreMadeWhenFirstReadTheSameInAnyOrder) {
  Breeder eager(smallRun(), kEncoding);
  Population first = eager.initialPopulation();
  fill(first, indices(first.individuals.size(), false));
  Population expected = eager.nextGeneration(first);
  for (const Individual& individual : expected.individuals)
    individual.genome.bytes();

  Population lazy;
  {
    Breeder breeder(smallRun(), kEncoding);
    breeder.initialPopulation();
    lazy = breeder.nextGeneration(first);
  }
  int deferred = 0;
  for (const Individual& individual : lazy.individuals)
    deferred += individual.origin != Origin::elite && !individual.genome.made() ? 1 : 0;
  EXPECT_EQ(deferred, eager.plan().mutations + eager.plan().crossovers + eager.plan().grafts);
  for (std::size_t i = lazy.individuals.size(); i-- > 0;)
    EXPECT_EQ(lazy.individuals[i].genome.bytes(), expected.individuals[i].genome.bytes());
}

TEST(Breeder, ADifferentSeedBreedsDifferently) {
  EvolutionSettings other = smallRun();
  other.seed = 12;
  Breeder a(smallRun(), kEncoding), b(other, kEncoding);
  Population pa = a.initialPopulation(), pb = b.initialPopulation();
  bool differs = false;
  for (std::size_t i = 0; i < pa.individuals.size(); ++i) {
    differs = differs || !(pa.individuals[i].genome == pb.individuals[i].genome);
  }
  EXPECT_TRUE(differs);
}

TEST(Breeder, IdsAreUniqueAndIncreaseAcrossTheRun) {
  Breeder breeder(smallRun(), kEncoding);
  Population p = breeder.initialPopulation();
  std::set<std::uint64_t> seen;
  std::uint64_t last = 0;
  bool first = true;
  for (int g = 0; g < 4; ++g) {
    for (const Individual& individual : p.individuals) {
      EXPECT_TRUE(seen.insert(individual.id).second) << "id " << individual.id;
      if (!first) {
        EXPECT_GT(individual.id, last);
      }
      last = individual.id;
      first = false;
      EXPECT_EQ(individual.generation, static_cast<std::uint64_t>(g));
    }
    fill(p, indices(p.individuals.size(), false));
    p = breeder.nextGeneration(p);
  }
}

// Algorithm 3.1 of the springy organisms: the mutation parents by a method of their own. Here
// crossover and graft parents come from the best 20 % (truncation) and the mutation parents by
// roulette, so some mutation parent ranks below the best 20 %; `same` draws them all at once
TEST(Breeder, MutationParentsCanHaveASelectionOfTheirOwn) {
  EvolutionSettings s = smallRun();
  s.population = 50;
  s.mutation_selection = MutationSelection::roulette;
  Breeder breeder(s, kEncoding);
  Population first = breeder.initialPopulation();
  fill(first, indices(first.individuals.size(), false));
  const std::vector<std::size_t> ranking = first.ranking();
  std::set<std::uint64_t> best;
  for (std::size_t r = 0; r < 10; ++r)
    best.insert(first.individuals[ranking[r]].id);
  Population second = breeder.nextGeneration(first);
  int mutation_parents_below = 0;
  for (const Individual& child : second.individuals) {
    if (child.origin == Origin::crossover || child.origin == Origin::graft) {
      for (std::uint64_t parent : child.parents)
        EXPECT_TRUE(best.count(parent)) << "a sexual parent outside the best 20 %";
    } else if (child.origin == Origin::mutation) {
      mutation_parents_below += best.count(child.parents[0]) == 0;
    }
  }
  EXPECT_GT(mutation_parents_below, 0);
  // `same` (the default) and a method of their own breed differently, each reproducibly
  EvolutionSettings same = s;
  same.mutation_selection = MutationSelection::same;
  Breeder again(s, kEncoding), other(same, kEncoding);
  Population a = again.initialPopulation(), b = other.initialPopulation();
  fill(a, indices(a.individuals.size(), false));
  fill(b, indices(b.individuals.size(), false));
  const Population next_a = again.nextGeneration(a), next_b = other.nextGeneration(b);
  EXPECT_EQ(next_a.individuals.size(), second.individuals.size());
  bool all_same = true;
  for (std::size_t i = 0; i < next_a.individuals.size(); ++i) {
    EXPECT_EQ(next_a.individuals[i].genome, second.individuals[i].genome);
    all_same = all_same && next_a.individuals[i].parents == next_b.individuals[i].parents;
  }
  EXPECT_FALSE(all_same);
}

TEST(Breeder, RefusesAPartlyEvaluatedGeneration) {
  Breeder breeder(smallRun(), kEncoding);
  Population p = breeder.initialPopulation();
  EXPECT_THROW(breeder.nextGeneration(p), std::invalid_argument);
}

// an encoding without grafting cannot breed a plan that grafts
class NoGraft : public graph::DirectedGraphEncoding {
 public:
  bool supports(Variation variation) const override { return variation != Variation::graft; }
};

TEST(Breeder, RefusesAPlanTheEncodingCannotBreed) {
  NoGraft encoding;
  try {
    Breeder breeder(smallRun(), encoding);
    FAIL() << "a grafting plan was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("evolution.graft_fraction"), std::string::npos)
        << e.what();
  }
  EvolutionSettings no_grafts = smallRun();
  no_grafts.mutation_fraction = 0.7;
  no_grafts.graft_fraction = 0;
  EXPECT_NO_THROW(Breeder(no_grafts, encoding));
}

}  // namespace
}  // namespace cambrian
