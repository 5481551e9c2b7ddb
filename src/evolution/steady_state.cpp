// cambrian: steady-state evolution — a child bred from the members as they are now, and the
// reverse tournament a result taken in meets.
#include "evolution/steady_state.hpp"

#include "cambrian/rng.hpp"

#include "evolution/breeder.hpp"
#include "evolution/selection.hpp"

#include <algorithm>
#include <stdexcept>

namespace cambrian {

std::size_t SteadyMembers::rankOf(double fitness, std::uint64_t id) const {
  // fitness descending, then id ascending (Population::ranking's order)
  std::size_t low = 0, high = ranked_ids_.size();
  while (low < high) {
    const std::size_t middle = (low + high) / 2;
    const double f = ranked_fitness_[middle];
    if (f > fitness || (f == fitness && ranked_ids_[middle] < id))
      low = middle + 1;
    else
      high = middle;
  }
  return low;
}

void SteadyMembers::addToRanking(const Individual& individual) {
  const std::size_t at = rankOf(individual.fitness(), individual.id);
  ranked_fitness_.insert(ranked_fitness_.begin() + static_cast<std::ptrdiff_t>(at),
                         individual.fitness());
  ranked_ids_.insert(ranked_ids_.begin() + static_cast<std::ptrdiff_t>(at), individual.id);
}

void SteadyMembers::removeFromRanking(const Individual& individual) {
  const std::size_t at = rankOf(individual.fitness(), individual.id);
  ranked_fitness_.erase(ranked_fitness_.begin() + static_cast<std::ptrdiff_t>(at));
  ranked_ids_.erase(ranked_ids_.begin() + static_cast<std::ptrdiff_t>(at));
}

bool SteadyMembers::takeIn(Individual individual) {
  std::vector<Individual>& members = members_.individuals;
  auto place = [&] {
    return std::lower_bound(members.begin(), members.end(), individual.id,
                            [](const Individual& i, std::uint64_t id) { return i.id < id; });
  };
  // room left: it joins
  if (members.size() < static_cast<std::size_t>(settings_.population)) {
    addToRanking(individual);
    members.insert(place(), std::move(individual));
    return true;
  }
  // the worst of a reverse tournament gives way to it when it is at least as fit
  Rng rng(settings_.seed, RngPurpose::selection, individual.id, kSteadyStream + 1);
  const std::size_t count = members.size();
  std::size_t loser = rng.below(count);
  for (int k = 1; k < settings_.replacement_tournament; ++k) {
    std::size_t contestant = rng.below(count);
    const Individual& a = members[contestant];
    const Individual& b = members[loser];
    if (a.fitness() < b.fitness() || (a.fitness() == b.fitness() && a.id < b.id))
      loser = contestant;
  }
  if (individual.fitness() < members[loser].fitness())
    return false;
  removeFromRanking(members[loser]);
  members.erase(members.begin() + static_cast<std::ptrdiff_t>(loser));
  addToRanking(individual);
  members.insert(place(), std::move(individual));
  return true;
}

Individual Breeder::steadyChild(const SteadyMembers& members, std::uint64_t bred_after) {
  if (members.size() == 0)
    throw std::invalid_argument("steadyChild: no members to breed from");
  const std::uint64_t id = next_id_;
  Rng rng(settings_.seed, RngPurpose::selection, id, kSteadyStream);

  // the operator, in the offspring shares
  const double u = rng.uniform();
  const Origin origin = u < settings_.mutation_fraction ? Origin::mutation
                        : u < settings_.mutation_fraction + settings_.crossover_fraction
                            ? Origin::crossover
                            : Origin::graft;

  // the parents, from the members' ranking (one for mutation, two otherwise)
  SelectionSettings selection = settings_.selection;
  if (origin == Origin::mutation && settings_.mutation_selection != MutationSelection::same)
    selection.method = selectionMethodFor(settings_.mutation_selection);
  const std::vector<std::size_t> picks =
      selectParents(members.rankedFitness(), origin == Origin::mutation ? 1 : 2, selection, rng);
  const Individual& a = members.member(members.rankedIds()[picks[0]]);
  const Individual* b = picks.size() > 1 ? &members.member(members.rankedIds()[picks[1]]) : nullptr;
  std::vector<std::uint64_t> parents =
      b ? std::vector<std::uint64_t>{a.id, b->id} : std::vector<std::uint64_t>{a.id};

  // made when first read, from the stream (seed, variation, id, kSteadyStream)
  Individual child = offspring(id, kSteadyStream, origin, std::move(parents),
                               varyParents(origin, a.genome, b ? b->genome : Genotype{}));
  child.generation = members.population().generation;
  child.bred_after = bred_after;
  return child;
}

}  // namespace cambrian
