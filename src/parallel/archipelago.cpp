// cambrian: migration batches between the islands' breeding ranks.
#include "parallel/archipelago.hpp"

#include "cambrian/encodings.hpp"

#include "core/bytes.hpp"
#include "core/outcome_bytes.hpp"

namespace cambrian {

std::vector<std::uint8_t> encodeMigrants(std::uint64_t event, int source,
                                         const std::vector<const Individual*>& individuals) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  w.u64(event);
  w.u64(static_cast<std::uint64_t>(source));
  w.u64(individuals.size());
  for (const Individual* individual : individuals) {
    w.u64(individual->id);
    const std::vector<std::uint8_t>& genome = individual->genomeBytes();
    w.blob(genome.data(), genome.size());
    writeOutcome(w, individual->outcome);
  }
  return bytes;
}

std::vector<Individual> decodeMigrants(const std::vector<std::uint8_t>& bytes, std::uint64_t& event,
                                       int& source) {
  ByteReader r(bytes.data(), bytes.size(), "migrants");
  r.context("field 'event'");
  event = r.u64();
  r.context("field 'source'");
  source = static_cast<int>(r.u64());
  r.context("field 'count'");
  const std::uint64_t count = r.u64();
  std::vector<Individual> individuals;
  for (std::uint64_t k = 0; k < count; ++k) {
    Individual individual;
    r.context("field 'id'");
    individual.id = r.u64();
    r.context("field 'genome'");
    individual.genome = decodeGenome(r.blob());
    individual.outcome = readOutcome(r);
    individual.evaluated = true;
    individuals.push_back(std::move(individual));
  }
  r.expectEnd();
  return individuals;
}

Archipelago::Archipelago(MpiContext& breeders, const MigrationSettings& settings,
                         std::uint64_t run_seed, std::uint64_t generations)
    : breeders_(breeders),
      settings_(settings),
      run_seed_(run_seed),
      generations_(generations),
      sent_(static_cast<std::size_t>(breeders.size()), 0),
      received_(static_cast<std::size_t>(breeders.size()), 0),
      closed_(static_cast<std::size_t>(breeders.size()), -1) {}

void Archipelago::drain() {
  // migrants and final counts only: the breeding ranks' other messages (the digests at the end)
  // are not the archipelago's
  Message message;
  while (breeders_.tryReceive(Tag::migrants, message)) {
    std::uint64_t event = 0;
    int source = -1;
    std::vector<Individual> batch = decodeMigrants(message.bytes, event, source);
    ++received_.at(static_cast<std::size_t>(message.source));
    // a batch sent again (after a resume) is kept once
    arrived_.emplace(std::make_pair(event, source), std::move(batch));
  }
  // final counts after the batches they count (drained first: they were sent before them)
  while (breeders_.tryReceive(Tag::stop, message)) {
    ByteReader r(message.bytes.data(), message.bytes.size(), "an island's final count");
    closed_.at(static_cast<std::size_t>(message.source)) = static_cast<std::int64_t>(r.u64());
  }
}

bool Archipelago::mayStillCome(std::uint64_t event, int source) const {
  if (arrived_.count({event, source}))
    return false;
  const auto s = static_cast<std::size_t>(source);
  return closed_[s] < 0 || received_[s] < static_cast<std::uint64_t>(closed_[s]);
}

void Archipelago::close() {
  // the final count to every other island
  for (int other = 0; other < breeders_.size(); ++other) {
    if (other == breeders_.rank())
      continue;
    std::vector<std::uint8_t> bytes;
    ByteWriter w(bytes);
    w.u64(sent_[static_cast<std::size_t>(other)]);
    breeders_.post(other, Tag::stop, std::move(bytes));
  }
  // everything sent here taken in, everything sent from here taken
  Backoff backoff;
  for (;;) {
    drain();
    bool all_in = true;
    for (int other = 0; other < breeders_.size(); ++other) {
      const auto o = static_cast<std::size_t>(other);
      if (other != breeders_.rank() &&
          (closed_[o] < 0 || received_[o] < static_cast<std::uint64_t>(closed_[o])))
        all_in = false;
    }
    if (all_in && breeders_.completePosted() == 0)
      return;
    backoff.wait();
  }
}

std::optional<std::vector<Individual>> Archipelago::exchange(const Population& evaluated,
                                                             bool (*stop_requested)()) {
  const std::uint64_t g = evaluated.generation;
  const int island = breeders_.rank();
  const auto interval = static_cast<std::uint64_t>(settings_.interval);
  // this island's best go out where some generation will take them in (at g + interval + 1)
  if (migratesAfter(settings_, g) && g + interval + 1 < generations_) {
    std::vector<const Individual*> best;
    for (std::size_t index : emigrants(evaluated, settings_.migrants))
      best.push_back(&evaluated.individuals[index]);
    for (int target : migrationTargets(settings_, island, g, run_seed_)) {
      breeders_.post(target, Tag::migrants, encodeMigrants(g, island, best));
      ++sent_[static_cast<std::size_t>(target)];
    }
  }
  breeders_.completePosted();
  // the batches sent one interval ago come in now
  std::vector<Individual> immigrants;
  if (g < interval || !migratesAfter(settings_, g - interval))
    return immigrants;
  const std::uint64_t event = g - interval;
  for (int source : migrationSources(settings_, island, event, run_seed_)) {
    Backoff backoff;
    for (drain(); !arrived_.count({event, source}); drain()) {
      if (!mayStillCome(event, source) || (stop_requested && stop_requested()))
        return std::nullopt;
      backoff.wait();
    }
    auto batch = arrived_.extract({event, source});
    for (Individual& individual : batch.mapped())
      immigrants.push_back(std::move(individual));
  }
  // batches of passed events are never taken in again
  arrived_.erase(arrived_.begin(), arrived_.lower_bound({event + 1, 0}));
  return immigrants;
}

}  // namespace cambrian
