// cambrian: island topologies, emigrant choice and immigrant placement.
#include "evolution/migration.hpp"

#include "cambrian/rng.hpp"

#include <algorithm>
#include <stdexcept>

namespace cambrian {

const char* migrationTopologyName(MigrationTopology topology) {
  switch (topology) {
    case MigrationTopology::ring:
      return "ring";
    case MigrationTopology::full:
      return "full";
    case MigrationTopology::random:
      return "random";
  }
  return "unknown";
}

MigrationTopology parseMigrationTopology(const std::string& name) {
  for (MigrationTopology topology :
       {MigrationTopology::ring, MigrationTopology::full, MigrationTopology::random}) {
    if (name == migrationTopologyName(topology))
      return topology;
  }
  throw std::invalid_argument("'" + name + "' is not a migration topology (ring, full, random)");
}

bool migratesAfter(const MigrationSettings& settings, std::uint64_t generation) {
  if (settings.islands < 2 || settings.interval < 1 || settings.migrants < 1)
    return false;
  return (generation + 1) % static_cast<std::uint64_t>(settings.interval) == 0;
}

std::vector<int> migrationTargets(const MigrationSettings& settings, int island,
                                  std::uint64_t generation, std::uint64_t run_seed) {
  const int n = settings.islands;
  if (n < 2)
    return {};
  switch (settings.topology) {
    case MigrationTopology::ring:
      return {(island + 1) % n};
    case MigrationTopology::full: {
      std::vector<int> others;
      for (int other = 0; other < n; ++other) {
        if (other != island)
          others.push_back(other);
      }
      return others;
    }
    case MigrationTopology::random: {
      // one of the other n - 1 islands, from a stream of this generation and island
      Rng rng(run_seed, RngPurpose::migration, generation, static_cast<std::uint64_t>(island));
      return {(island + 1 + static_cast<int>(rng.below(static_cast<std::uint64_t>(n - 1)))) % n};
    }
  }
  return {};
}

std::vector<int> migrationSources(const MigrationSettings& settings, int island,
                                  std::uint64_t generation, std::uint64_t run_seed) {
  std::vector<int> sources;
  for (int other = 0; other < settings.islands; ++other) {
    std::vector<int> targets = migrationTargets(settings, other, generation, run_seed);
    if (std::find(targets.begin(), targets.end(), island) != targets.end())
      sources.push_back(other);
  }
  return sources;
}

std::uint64_t islandSeed(std::uint64_t run_seed, int island) {
  if (island == 0)
    return run_seed;
  return Rng(run_seed, RngPurpose::migration, ~std::uint64_t{0}, static_cast<std::uint64_t>(island))
      .nextU64();
}

std::vector<std::size_t> emigrants(const Population& population, int count) {
  std::vector<std::size_t> chosen;
  for (std::size_t index : population.ranking()) {
    if (static_cast<int>(chosen.size()) >= count)
      break;
    if (population.individuals[index].evaluated)
      chosen.push_back(index);
  }
  return chosen;
}

Population withImmigrants(const Population& population, const std::vector<Individual>& immigrants) {
  const std::size_t size = population.individuals.size();
  const std::size_t replaced = std::min(immigrants.size(), size > 0 ? size - 1 : 0);
  std::uint64_t highest = 0;
  for (const Individual& individual : population.individuals)
    highest = std::max(highest, individual.id + 1);
  std::vector<bool> leaves(size, false);
  std::vector<std::size_t> ranking = population.ranking();
  for (std::size_t k = 0; k < replaced; ++k)
    leaves[ranking[size - 1 - k]] = true;

  Population pool;
  pool.generation = population.generation;
  for (std::size_t i = 0; i < size; ++i) {
    if (!leaves[i])
      pool.individuals.push_back(population.individuals[i]);
  }
  for (std::size_t k = 0; k < replaced; ++k) {
    const Individual& immigrant = immigrants[k];
    if (immigrant.id == kNoId || immigrant.id < highest)
      throw std::invalid_argument("immigrant id " + std::to_string(immigrant.id) +
                                  " is not above the population's ids");
    highest = immigrant.id + 1;
    pool.individuals.push_back(immigrant);
  }
  return pool;
}

}  // namespace cambrian
