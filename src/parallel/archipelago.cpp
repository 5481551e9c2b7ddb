// cambrian: migration batches between the islands' breeding ranks.
#include "parallel/archipelago.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "core/bytes.hpp"
#include "core/outcome_bytes.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

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
                         std::uint64_t run_seed, bool (*stop_requested)())
    : breeders_(breeders),
      settings_(settings),
      run_seed_(run_seed),
      stop_requested_(stop_requested),
      sent_(static_cast<std::size_t>(breeders.size()), 0),
      received_(static_cast<std::size_t>(breeders.size()), 0),
      closed_(static_cast<std::size_t>(breeders.size()), -1) {}

void Archipelago::send(int island, Tag tag, std::vector<std::uint8_t> bytes) {
  breeders_.post(island, tag, std::move(bytes));
  ++sent_.at(static_cast<std::size_t>(island));
}

void Archipelago::drain() {
  // the archipelago's tags only: the breeding ranks' other messages (the digests at the end)
  // are not its
  Message message;
  while (breeders_.tryReceive(Tag::migrants, message)) {
    std::uint64_t event = 0;
    int source = -1;
    std::vector<Individual> batch = decodeMigrants(message.bytes, event, source);
    ++received_.at(static_cast<std::size_t>(message.source));
    // a batch sent again (after a resume) is kept once
    arrived_.emplace(std::make_pair(event, source), std::move(batch));
  }
  // a target's checkpoint needs no batch of an event before this one: out of the outbox
  while (breeders_.tryReceive(Tag::needed, message)) {
    ++received_.at(static_cast<std::size_t>(message.source));
    ByteReader r(message.bytes.data(), message.bytes.size(), "an island's first needed event");
    const std::uint64_t first_needed = r.u64();
    for (auto it = outbox_.begin(); it != outbox_.end();) {
      if (it->first.second == message.source && it->first.first < first_needed)
        it = outbox_.erase(it);
      else
        ++it;
    }
  }
  // final counts after the messages they count (drained first: they were sent before them)
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

std::vector<std::uint8_t> Archipelago::checkpointState() const {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  w.u64(1);  // layout version
  w.u64(outbox_.size());
  for (const auto& [key, batch] : outbox_) {
    w.u64(static_cast<std::uint64_t>(key.second));
    w.blob(batch.data(), batch.size());
  }
  return bytes;
}

void Archipelago::checkpointed(std::uint64_t next_generation) {
  checkpointed_.store(next_generation);
}

void Archipelago::resume(const std::vector<std::uint8_t>& state) {
  if (state.empty())
    return;
  try {
    ByteReader r(state.data(), state.size(), "the checkpoint's /migrations");
    r.context("field 'version'");
    if (const std::uint64_t version = r.u64(); version != 1)
      throw InputError("the checkpoint's /migrations: layout version " + std::to_string(version) +
                       " (this cambrian reads 1)");
    r.context("field 'count'");
    const std::uint64_t count = r.u64();
    for (std::uint64_t k = 0; k < count; ++k) {
      r.context("field 'target'");
      const std::uint64_t target = r.u64();
      if (target >= static_cast<std::uint64_t>(breeders_.size()) ||
          target == static_cast<std::uint64_t>(breeders_.rank()))
        throw InputError("the checkpoint's /migrations: target island " + std::to_string(target) +
                         " is not another island of " + std::to_string(breeders_.size()));
      r.context("field 'batch'");
      std::vector<std::uint8_t> batch = r.blob();
      std::uint64_t event = 0;
      int source = -1;
      decodeMigrants(batch, event, source);
      // the batch again, for a target that may have lost it
      outbox_[{event, static_cast<int>(target)}] = batch;
      send(static_cast<int>(target), Tag::migrants, std::move(batch));
    }
    r.expectEnd();
  } catch (const InputError& e) {
    throw Error(ExitCode::checkpoint, e.what());
  }
}

std::string Archipelago::missingFor(const std::vector<std::uint64_t>& starts,
                                    const std::string& directory) const {
  // the batches each target will wait for from here on must be in this island's outbox, or made
  // again (a resume's first exchange sends its last generation's)
  const int island = breeders_.rank();
  const std::uint64_t next_generation = starts.at(static_cast<std::size_t>(island));
  const auto interval = static_cast<std::uint64_t>(settings_.interval);
  const std::uint64_t made_again_from = next_generation == 0 ? 0 : next_generation - 1;
  std::string problem;
  for (int target = 0; target < breeders_.size() && problem.empty(); ++target) {
    const std::uint64_t from = starts[static_cast<std::size_t>(target)];
    if (target == island)
      continue;
    // its first exchange (after generation from - 1) takes in event from - 1 - interval
    const std::uint64_t first_needed = from > interval ? from - 1 - interval : 0;
    for (std::uint64_t event = first_needed; event < made_again_from; ++event) {
      if (!migratesAfter(settings_, event) || outbox_.count({event, target}))
        continue;
      const std::vector<int> targets = migrationTargets(settings_, island, event, run_seed_);
      if (std::find(targets.begin(), targets.end(), target) != targets.end()) {
        problem = "islands: island " + std::to_string(target) + " continues from generation " +
                  std::to_string(from) + ", but island " + std::to_string(island) + " (" +
                  directory + ", from generation " + std::to_string(next_generation) +
                  ") no longer holds the migrants it sent it after generation " +
                  std::to_string(event) + ": island " + std::to_string(target) +
                  "'s checkpoint is older than the one it told the others of (a "
                  "checkpoint put back by hand, or its directory lost?); put its newest "
                  "checkpoint back, or start every island over with --fresh";
        break;
      }
    }
  }
  return problem;
}

void Archipelago::start(std::uint64_t next_generation, const std::string& directory) {
  const std::string problem = missingFor(breeders_.allGather(next_generation), directory);
  // every island refuses before any runs a generation: the one that found it says why, the
  // others wait for its abort to end the job (and say so themselves if it never came)
  if (breeders_.allReduceMax(problem.empty() ? 0 : 1) == 0)
    return;
  if (!problem.empty())
    throw Error(ExitCode::checkpoint, problem);
  std::this_thread::sleep_for(std::chrono::seconds(10));
  throw Error(ExitCode::checkpoint,
              "islands: another island cannot continue (its message says why)");
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

std::optional<std::vector<Individual>> Archipelago::exchange(const Population& evaluated) {
  const std::uint64_t g = evaluated.generation;
  const int island = breeders_.rank();
  const auto interval = static_cast<std::uint64_t>(settings_.interval);
  // a checkpoint since the last exchange: the others learn the first event it still needs (a
  // resume from it takes in the batches of event checkpointed - 1 - interval first)
  if (const std::uint64_t checkpointed = checkpointed_.load(); checkpointed > announced_) {
    announced_ = checkpointed;
    const std::uint64_t last = checkpointed - 1;
    for (int other = 0; other < breeders_.size(); ++other) {
      if (other == island)
        continue;
      std::vector<std::uint8_t> bytes;
      ByteWriter w(bytes);
      w.u64(last >= interval ? last - interval : 0);
      send(other, Tag::needed, std::move(bytes));
    }
  }
  // this island's best go out, to be taken in at g + interval + 1 (also after the last
  // generation but one: a resume may raise evolution.generations); after a resume, not again
  // where the outbox sent them already
  if (migratesAfter(settings_, g)) {
    std::vector<const Individual*> best;
    for (std::size_t index : emigrants(evaluated, settings_.migrants))
      best.push_back(&evaluated.individuals[index]);
    const std::vector<std::uint8_t> batch = encodeMigrants(g, island, best);
    for (int target : migrationTargets(settings_, island, g, run_seed_)) {
      if (outbox_.emplace(std::make_pair(g, target), batch).second)
        send(target, Tag::migrants, batch);
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
      if (!mayStillCome(event, source) || (stop_requested_ && stop_requested_()))
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
