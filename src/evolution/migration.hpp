// cambrian: the island model's rules that need no messages: where each island's emigrants go,
// who they are, and how immigrants join a population. MPI carries them (parallel/).
#pragma once

#include "core/settings.hpp"
#include "evolution/population.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cambrian {

/// Which islands an island sends its emigrants to.
enum class MigrationTopology : std::uint8_t {
  ring,    ///< island i to island i + 1 (the last to the first)
  full,    ///< every island to every other
  random,  ///< each island to one other, drawn afresh at every migration from the run seed
};

/// "ring", "full", "random".
const char* migrationTopologyName(MigrationTopology topology);
/// The topology named `name`; throws std::invalid_argument naming the choices.
MigrationTopology parseMigrationTopology(const std::string& name);

/// The archipelago: how many islands and how they trade individuals.
struct MigrationSettings {
  int islands = 1;    ///< 1: no islands (one population, as without this setting)
  int interval = 10;  ///< generations between migrations (after generation interval - 1, ...)
  int migrants = 2;   ///< the best this many of an island's generation emigrate
  MigrationTopology topology = MigrationTopology::ring;

  /// Declares the [islands] keys, bound to this object, with their ranges.
  void declareSettings(SettingsSchema& schema);
};

/// One island's side of the migrations, as the run driver sees it (parallel/archipelago.hpp
/// carries it over MPI). Called on the breeding rank's main thread but for checkpointState and
/// checkpointed, which the checkpoint writer calls while the next generation evaluates.
class MigrationExchange {
 public:
  virtual ~MigrationExchange() = default;
  /// Once, before the first exchange: the generation this island's run starts at (0: afresh,
  /// else where its checkpoint continues) and its output directory (for messages). Throws
  /// Error(checkpoint) where another island would wait for ever: it starts from an older
  /// checkpoint than the one it told this island of (put back by hand, or its directory lost),
  /// and this island dropped batches that one needs.
  virtual void start(std::uint64_t next_generation, const std::string& directory) = 0;
  /// After each evaluated generation, before the next is bred: sends this island's emigrants
  /// where due and returns the immigrants the next generation takes in (placeImmigrants), or
  /// null when the run must stop (a stop while waiting for them, another island stopped).
  virtual std::optional<std::vector<Individual>> exchange(const Population& evaluated) = 0;
  /// What a checkpoint keeps for a resume (opaque bytes: the batches sent that their targets'
  /// checkpoints may still need).
  virtual std::vector<std::uint8_t> checkpointState() const = 0;
  /// A checkpoint of the generations before `next_generation` is written (with checkpointState).
  virtual void checkpointed(std::uint64_t next_generation) = 0;
  /// A resume from a checkpoint that kept `state` (empty: one written without islands).
  virtual void resume(const std::vector<std::uint8_t>& state) = 0;
  /// Once, when the run ends or stops.
  virtual void close() = 0;
};

/// Whether island emigrants leave after generation `generation` (every `interval`, from
/// generation interval - 1 on; never with one island).
bool migratesAfter(const MigrationSettings& settings, std::uint64_t generation);

/// The islands island `island` sends to after generation `generation`, ascending; empty with
/// one island. The random topology's draw is a pure function of (run seed, generation, island).
std::vector<int> migrationTargets(const MigrationSettings& settings, int island,
                                  std::uint64_t generation, std::uint64_t run_seed);
/// The islands that send to island `island` after generation `generation`, ascending.
std::vector<int> migrationSources(const MigrationSettings& settings, int island,
                                  std::uint64_t generation, std::uint64_t run_seed);

/// The run seed of island `island`: the run's own for island 0, else one drawn from it, so
/// every island has random streams of its own and one island is the run without islands.
std::uint64_t islandSeed(std::uint64_t run_seed, int island);

/// Indices of the `count` best evaluated individuals of `population` (fitness descending, ties
/// to the lower id), fewer when it holds fewer.
std::vector<std::size_t> emigrants(const Population& population, int count);

/// `immigrant` as it joins this island: the id and generation given, origin migrant, no parents
/// here, its genome and outcome kept (not evaluated here: no time, no worker).
Individual asImmigrant(Individual immigrant, std::uint64_t id, std::uint64_t generation);

/// Places `immigrants` in the bred generation `next`: each takes the place, id and generation
/// of one of its last bred individuals (the highest ids; never an elite or an individual that
/// already holds an outcome), keeps its genome and outcome, and becomes origin migrant with no
/// parents in this island. Returns how many were placed (fewer where `next` has fewer bred
/// places). Deterministic: the places depend on `next` alone.
std::size_t placeImmigrants(Population& next, const std::vector<Individual>& immigrants);

}  // namespace cambrian
