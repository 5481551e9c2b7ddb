#include "evolution/population.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace cambrian {

const char* originName(Origin origin) {
  switch (origin) {
    case Origin::random:
      return "random";
    case Origin::seed:
      return "seed";
    case Origin::elite:
      return "elite";
    case Origin::mutation:
      return "mutation";
    case Origin::crossover:
      return "crossover";
    case Origin::graft:
      return "graft";
    case Origin::gene_specification:
      return "gene_specification";
    case Origin::gene_split:
      return "gene_split";
    case Origin::gene_purge:
      return "gene_purge";
    case Origin::branch_specification:
      return "branch_specification";
    case Origin::grow_stub:
      return "grow_stub";
    case Origin::graft_feature:
      return "graft_feature";
    case Origin::migrant:
      return "migrant";
    case Origin::segment_crossover:
      return "segment_crossover";
  }
  return "unknown";
}

double Individual::fitness() const {
  if (!evaluated || !std::isfinite(outcome.fitness))
    return kWorstFitness;
  return outcome.fitness;
}

std::vector<std::size_t> Population::ranking() const {
  // fitness descending, then id ascending: a total order independent of arrival order
  std::vector<std::size_t> order(individuals.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) {
    double fa = individuals[a].fitness(), fb = individuals[b].fitness();
    if (fa != fb)
      return fa > fb;
    return individuals[a].id < individuals[b].id;
  });
  return order;
}

std::size_t Population::indexOf(std::uint64_t id) const {
  // ids increase along the vector: binary search
  auto it = std::lower_bound(individuals.begin(), individuals.end(), id,
                             [](const Individual& i, std::uint64_t key) { return i.id < key; });
  if (it == individuals.end() || it->id != id) {
    throw std::out_of_range("population: no individual with id " + std::to_string(id));
  }
  return static_cast<std::size_t>(it - individuals.begin());
}

bool Population::allEvaluated() const {
  return std::all_of(individuals.begin(), individuals.end(),
                     [](const Individual& i) { return i.evaluated; });
}

const Individual* bestOk(const std::vector<Individual>& individuals,
                         std::optional<std::uint64_t> generation) {
  const Individual* best = nullptr;
  for (const Individual& row : individuals) {
    if (row.outcome.status != EvalStatus::ok || (generation && row.generation != *generation))
      continue;
    if (!best || row.fitness() > best->fitness() ||
        (row.fitness() == best->fitness() && row.id < best->id))
      best = &row;
  }
  return best;
}

}  // namespace cambrian
