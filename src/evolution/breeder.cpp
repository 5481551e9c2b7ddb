#include "evolution/breeder.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "evolution/reaper.hpp"
#include "evolution/selection.hpp"
#include "evolution/wwd_breeding.hpp"

#include <cmath>
#include <stdexcept>

namespace cambrian {

SelectionMethod selectionMethodFor(MutationSelection choice) {
  switch (choice) {
    case MutationSelection::truncation:
      return SelectionMethod::truncation;
    case MutationSelection::tournament:
      return SelectionMethod::tournament;
    case MutationSelection::roulette:
      return SelectionMethod::roulette;
    case MutationSelection::sus:
      return SelectionMethod::sus;
    case MutationSelection::rank:
    case MutationSelection::same:
      break;
  }
  return SelectionMethod::rank;
}

BreedingPlan planBreeding(const EvolutionSettings& s) {
  // elites first, then the offspring shares of the rest
  BreedingPlan plan;
  plan.elites = static_cast<int>(std::lround(s.population * s.elite_fraction));
  plan.elites = std::min(plan.elites, s.population - 1);
  int rest = s.population - plan.elites;
  plan.mutations = std::min(rest, static_cast<int>(std::lround(rest * s.mutation_fraction)));
  plan.crossovers =
      std::min(rest - plan.mutations, static_cast<int>(std::lround(rest * s.crossover_fraction)));
  plan.grafts = rest - plan.mutations - plan.crossovers;
  return plan;
}

Breeder::Breeder(const EvolutionSettings& settings, const Encoding& encoding)
    : settings_(settings), encoding_(encoding), plan_(planBreeding(settings)) {
  if (settings.scheme == BreedingScheme::reaper) {
    requireReaperOperators(settings, encoding);
    return;
  }
  if (settings.scheme == BreedingScheme::wwd) {
    requireWwdOperators(encoding);
    return;
  }
  // every operator the plan uses must exist for the encoding
  const std::pair<int, Variation> needs[] = {{plan_.mutations, Variation::mutation},
                                             {plan_.crossovers, Variation::crossover},
                                             {plan_.grafts, Variation::graft}};
  static constexpr const char* kKeys[] = {
      "evolution.mutation_fraction", "evolution.crossover_fraction", "evolution.graft_fraction"};
  for (const auto& [count, variation] : needs) {
    if (count > 0 && !encoding_.supports(variation))
      throw ConfigError(std::string(kKeys[static_cast<int>(variation)]) + ": the encoding " +
                        encoding_.name() + " has no such operator; set it to 0");
  }
}

Individual Breeder::eliteCopy(const Individual& parent, std::uint64_t generation) {
  Individual copy;
  copy.id = next_id_++;
  copy.generation = generation;
  copy.parents = {parent.id};
  copy.origin = Origin::elite;
  copy.genome = parent.genome;
  copy.outcome = parent.outcome;
  copy.evaluated = true;
  return copy;
}

double scaledMutationRate(const Encoding& encoding, double rate, double multiplier) {
  return encoding.scalesOwnMutation() ? multiplier : std::min(1.0, rate * multiplier);
}

Individual Breeder::offspring(std::uint64_t g, std::uint64_t slot, Origin origin,
                              std::vector<std::uint64_t> parents,
                              std::function<Genotype(Rng&, int attempt)> make) {
  Individual child;
  child.id = next_id_++;
  child.generation = g;
  child.origin = origin;
  child.parents = std::move(parents);
  // made when first read (a pure function of the slot's stream, so whenever that is)
  child.genome = Genotype::deferred(
      encoding_, [&encoding = encoding_, seed = settings_.seed, g, slot, make = std::move(make),
                  viable = viable_, max_attempts = max_attempts_] {
        Rng rng(seed, RngPurpose::variation, g, slot);
        for (int attempt = 0;; ++attempt) {
          Genotype genome = encoding.tidy(make(rng, attempt));
          if (acceptable(viable, max_attempts, genome, attempt))
            return genome;
        }
      });
  return child;
}

Population Breeder::initialPopulation(const std::vector<Genotype>& seeds) {
  Population population;
  population.generation = 0;
  population.individuals.reserve(static_cast<std::size_t>(settings_.population));
  std::uint64_t first_id = next_id_;
  // the mutated copies' rate: evolution.mutation_rate, or 1 x an encoding's own chance
  const double seed_rate = scaledMutationRate(encoding_, settings_.mutation_rate, 1);

  for (int i = 0; i < settings_.population; ++i) {
    Individual individual;
    individual.id = next_id_++;
    individual.generation = 0;
    auto slot = static_cast<std::size_t>(i);
    if (seeds.empty()) {
      // a random creature from the stream (seed, random_genome, 0, i); redraws use the
      // streams (seed, random_genome, attempt, i)
      individual.origin = Origin::random;
      for (int attempt = 0;; ++attempt) {
        individual.genome = encoding_.random(settings_.seed, attempt, slot);
        if (acceptable(individual.genome, attempt))
          break;
      }
    } else if (slot < seeds.size()) {
      // the seed itself
      individual.origin = Origin::seed;
      individual.genome = seeds[slot];
    } else {
      // a mutated copy of a seed, round robin
      std::size_t source = slot % seeds.size();
      Rng rng(settings_.seed, RngPurpose::initial_population, 0, slot);
      individual.origin = Origin::mutation;
      individual.parents = {first_id + source};
      for (int attempt = 0;; ++attempt) {
        individual.genome = encoding_.tidy(encoding_.mutate(seeds[source], seed_rate, rng));
        if (acceptable(individual.genome, attempt))
          break;
      }
    }
    population.individuals.push_back(std::move(individual));
  }
  return population;
}

Population Breeder::restartFromBest(const Population& evaluated) {
  // "the new population would be created solely from the best creature" (none ok: the top of
  // the ranking)
  const std::uint64_t g = evaluated.generation + 1;
  const Individual* best = bestOk(evaluated.individuals);
  if (!best)
    best = &evaluated.individuals[evaluated.ranking().front()];
  const double seed_rate = scaledMutationRate(encoding_, settings_.mutation_rate, 1);
  Population next;
  next.generation = g;
  next.individuals.reserve(static_cast<std::size_t>(settings_.population));
  next.individuals.push_back(eliteCopy(*best, g));
  for (int slot = 1; slot < settings_.population; ++slot)
    next.individuals.push_back(
        offspring(g, static_cast<std::uint64_t>(slot), Origin::mutation, {best->id},
                  [&encoding = encoding_, genome = best->genome, seed_rate](Rng& rng, int) {
                    return encoding.mutate(genome, seed_rate, rng);
                  }));
  return next;
}

Population Breeder::nextGeneration(const Population& evaluated) {
  if (!evaluated.allEvaluated()) {
    throw std::invalid_argument("nextGeneration: generation " +
                                std::to_string(evaluated.generation) + " is not fully evaluated");
  }
  if (settings_.batch_generations > 0 &&
      (evaluated.generation + 1) % static_cast<std::uint64_t>(settings_.batch_generations) == 0)
    return restartFromBest(evaluated);
  if (settings_.scheme == BreedingScheme::reaper)
    return reap(evaluated);
  if (settings_.scheme == BreedingScheme::wwd)
    return breedWwd(evaluated);
  std::uint64_t g = evaluated.generation + 1;
  std::vector<std::size_t> ranking = evaluated.ranking();
  std::vector<double> ranked_fitness;
  ranked_fitness.reserve(ranking.size());
  for (std::size_t index : ranking)
    ranked_fitness.push_back(evaluated.individuals[index].fitness());

  Population next;
  next.generation = g;
  next.individuals.reserve(static_cast<std::size_t>(plan_.total()));

  // elites: copies of the best with their outcomes (their genome did not change)
  for (int e = 0; e < plan_.elites && e < static_cast<int>(ranking.size()); ++e)
    next.individuals.push_back(
        eliteCopy(evaluated.individuals[ranking[static_cast<std::size_t>(e)]], g));

  // every parent pick of the generation in one stream: (seed, selection, g, 0); with a method
  // of their own the mutation parents are drawn first from (seed, selection, g, 1)
  const auto mutation_picks = static_cast<std::size_t>(plan_.mutations);
  const auto sexual_picks = static_cast<std::size_t>(2 * plan_.crossovers + 2 * plan_.grafts);
  std::vector<std::size_t> picks;
  if (settings_.mutation_selection == MutationSelection::same) {
    Rng selection_rng(settings_.seed, RngPurpose::selection, g, 0);
    picks = selectParents(ranked_fitness, mutation_picks + sexual_picks, settings_.selection,
                          selection_rng);
  } else {
    SelectionSettings own = settings_.selection;
    own.method = selectionMethodFor(settings_.mutation_selection);
    Rng mutation_rng(settings_.seed, RngPurpose::selection, g, 1);
    picks = selectParents(ranked_fitness, mutation_picks, own, mutation_rng);
    Rng sexual_rng(settings_.seed, RngPurpose::selection, g, 0);
    const std::vector<std::size_t> sexual =
        selectParents(ranked_fitness, sexual_picks, settings_.selection, sexual_rng);
    picks.insert(picks.end(), sexual.begin(), sexual.end());
  }
  std::size_t next_pick = 0;
  auto pickParent = [&]() -> const Individual& {
    return evaluated.individuals[ranking[picks[next_pick++]]];
  };

  // offspring slot i uses the stream (seed, variation, g, i)
  const int bred = plan_.mutations + plan_.crossovers + plan_.grafts;
  for (int i = 0; i < bred; ++i) {
    const Individual* a = &pickParent();
    const Individual* b = i < plan_.mutations ? nullptr : &pickParent();
    std::vector<std::uint64_t> parents =
        b ? std::vector<std::uint64_t>{a->id, b->id} : std::vector<std::uint64_t>{a->id};
    const Origin origin = i < plan_.mutations                      ? Origin::mutation
                          : i < plan_.mutations + plan_.crossovers ? Origin::crossover
                                                                   : Origin::graft;
    next.individuals.push_back(
        offspring(g, static_cast<std::uint64_t>(i), origin, std::move(parents),
                  varyParents(origin, a->genome, b ? b->genome : Genotype{})));
  }
  return next;
}

std::function<Genotype(Rng&, int)> Breeder::varyParents(Origin origin, Genotype first,
                                                        Genotype second) const {
  const double mutation_rate = scaledMutationRate(encoding_, settings_.mutation_rate, 1);
  const double post_chance = settings_.post_crossover_mutation_chance;
  const double post_rate = scaledMutationRate(encoding_, settings_.post_crossover_mutation_rate, 1);
  return [&encoding = encoding_, origin, first = std::move(first), second = std::move(second),
          mutation_rate, post_chance, post_rate](Rng& rng, int) {
    // asexual: copy and mutate each parameter with mutation_rate (or the encoding's own)
    if (origin == Origin::mutation)
      return encoding.mutate(first, mutation_rate, rng);
    // sexual: crossover or graft, then maybe the weaker mutation (Chaumont 5.7)
    const Variation variation =
        origin == Origin::crossover ? Variation::crossover : Variation::graft;
    Genotype child = encoding.combine(variation, first, second, rng);
    if (rng.bernoulli(post_chance))
      child = encoding.mutate(child, post_rate, rng);
    return child;
  };
}

}  // namespace cambrian
