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

void MigrationSettings::declareSettings(SettingsSchema& s) {
  MigrationSettings& m = *this;
  s.describeSection("islands",
                    "[islands] the island model: populations of their own, trading "
                    "their best");
  s.add("islands.count", m.islands,
        "islands, each with a breeding rank, workers and a population of evolution.population "
        "of its own (the ranks split into as many blocks; 1: one population)")
      .require([&m] { return m.islands >= 1 && m.islands <= 65536; }, "must be in 1..65536");
  s.add("islands.interval", m.interval, "generations between migrations")
      .require([&m] { return m.interval >= 1; }, "must be >= 1");
  s.add("islands.migrants", m.migrants,
        "the best this many of an island's generation go to each island it sends to (0: none)")
      .require([&m] { return m.migrants >= 0; }, "must be >= 0");
  s.addChoice("islands.topology", m.topology,
              {{"ring", MigrationTopology::ring},
               {"full", MigrationTopology::full},
               {"random", MigrationTopology::random}},
              "which islands each sends to: ring (the next) | full (every other) | random (one "
              "other, drawn at every migration)");
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

Individual asImmigrant(Individual immigrant, std::uint64_t id, std::uint64_t generation) {
  immigrant.id = id;
  immigrant.generation = generation;
  immigrant.origin = Origin::migrant;
  immigrant.parents.clear();
  immigrant.eval_seconds = 0;
  immigrant.worker_rank = -1;
  return immigrant;
}

std::size_t placeImmigrants(Population& next, const std::vector<Individual>& immigrants) {
  std::size_t placed = 0;
  for (std::size_t i = next.individuals.size(); i-- > 0 && placed < immigrants.size();) {
    Individual& place = next.individuals[i];
    if (place.evaluated || place.origin == Origin::elite)
      continue;
    place = asImmigrant(immigrants[placed++], place.id, place.generation);
  }
  return placed;
}

}  // namespace cambrian
