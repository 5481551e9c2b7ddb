// cambrian: steady-state evolution — a child bred from the members as they are now, and the
// reverse tournament a result taken in meets.
#include "evolution/steady_state.hpp"

#include "cambrian/rng.hpp"

#include "evolution/breeder.hpp"
#include "evolution/selection.hpp"

#include <algorithm>
#include <stdexcept>

namespace cambrian {

bool takeIntoMembers(Population& members, Individual individual,
                     const EvolutionSettings& settings) {
  auto place = [&] {
    return std::lower_bound(members.individuals.begin(), members.individuals.end(), individual.id,
                            [](const Individual& i, std::uint64_t id) { return i.id < id; });
  };
  // room left: it joins
  if (members.individuals.size() < static_cast<std::size_t>(settings.population)) {
    members.individuals.insert(place(), std::move(individual));
    return true;
  }
  // the worst of a reverse tournament gives way to it when it is at least as fit
  Rng rng(settings.seed, RngPurpose::selection, individual.id, kSteadyStream + 1);
  const std::size_t count = members.individuals.size();
  std::size_t loser = rng.below(count);
  for (int k = 1; k < settings.replacement_tournament; ++k) {
    std::size_t contestant = rng.below(count);
    const Individual& a = members.individuals[contestant];
    const Individual& b = members.individuals[loser];
    if (a.fitness() < b.fitness() || (a.fitness() == b.fitness() && a.id < b.id))
      loser = contestant;
  }
  if (individual.fitness() < members.individuals[loser].fitness())
    return false;
  members.individuals.erase(members.individuals.begin() + static_cast<std::ptrdiff_t>(loser));
  members.individuals.insert(place(), std::move(individual));
  return true;
}

Individual Breeder::steadyChild(const Population& members, std::uint64_t bred_after) {
  if (members.individuals.empty())
    throw std::invalid_argument("steadyChild: no members to breed from");
  const std::uint64_t id = next_id_;
  Rng rng(settings_.seed, RngPurpose::selection, id, kSteadyStream);

  // the operator, in the offspring shares
  const double u = rng.uniform();
  const Origin origin = u < settings_.mutation_fraction ? Origin::mutation
                        : u < settings_.mutation_fraction + settings_.crossover_fraction
                            ? Origin::crossover
                            : Origin::graft;

  // the parents, from the members ranked (one for mutation, two otherwise)
  std::vector<std::size_t> ranking = members.ranking();
  std::vector<double> ranked_fitness;
  ranked_fitness.reserve(ranking.size());
  for (std::size_t index : ranking)
    ranked_fitness.push_back(members.individuals[index].fitness());
  SelectionSettings selection = settings_.selection;
  if (origin == Origin::mutation && settings_.mutation_selection != MutationSelection::same)
    selection.method = selectionMethodFor(settings_.mutation_selection);
  const std::vector<std::size_t> picks =
      selectParents(ranked_fitness, origin == Origin::mutation ? 1 : 2, selection, rng);
  const Individual& a = members.individuals[ranking[picks[0]]];
  const Individual* b = picks.size() > 1 ? &members.individuals[ranking[picks[1]]] : nullptr;
  std::vector<std::uint64_t> parents =
      b ? std::vector<std::uint64_t>{a.id, b->id} : std::vector<std::uint64_t>{a.id};

  // made when first read, from the stream (seed, variation, id, kSteadyStream)
  Individual child = offspring(id, kSteadyStream, origin, std::move(parents),
                               varyParents(origin, a.genome, b ? b->genome : Genotype{}));
  child.generation = members.generation;
  child.bred_after = bred_after;
  return child;
}

}  // namespace cambrian
