#include "parallel/scheduler.hpp"

#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/rng.hpp"

#include "core/settings.hpp"
#include "core/test_kill.hpp"
#include "parallel/mpi_context.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <iostream>
#include <limits>
#include <numeric>
#include <utility>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// the individual counter of the shuffled dispatch order's stream: no creature has this id, so
// the stream is none of the evaluation seeds' Rng(run seed, evaluation, 0, id)
constexpr std::uint64_t kDispatchStream = ~std::uint64_t{0};

// seconds since `start`
double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// populations above this many keep the genomes they have sent in the byte form alone: below it
// the decoded forms are a few megabytes, and decoding the parents again would cost rank 0 4 % of
// its time at 100 us creatures
constexpr std::size_t kDecodedKeptUpTo = 2000;

// in a population of more than kDecodedKeptUpTo, rank 0 keeps a genome it has sent in the byte
// form alone from now on (decoded again only where it is bred from): 100,000 graph genomes hold
// about 0.8 GB less
void keepSentBytesOnly(const Individual& individual, std::size_t population_size) {
  if (population_size > kDecodedKeptUpTo)
    individual.genome.dropDecoded();
}

// the request for individual `individual` of a population of `population_size`
EvalRequest makeRequest(const Individual& individual, std::uint64_t run_seed,
                        std::size_t population_size) {
  EvalRequest request;
  request.id = individual.id;
  request.eval_seed = evaluationSeed(run_seed, individual.id);
  request.genome = individual.genomeBytes();
  keepSentBytesOnly(individual, population_size);
  return request;
}

// the same request as its message bytes, the genome's byte form not copied on the way
std::vector<std::uint8_t> requestMessage(const Individual& individual, std::uint64_t run_seed,
                                         std::size_t population_size) {
  std::vector<std::uint8_t> bytes = encodeRequest(
      individual.id, evaluationSeed(run_seed, individual.id), individual.genomeBytes());
  keepSentBytesOnly(individual, population_size);
  return bytes;
}

// stores an outcome on the individual it belongs to
void store(Individual& individual, const Outcome& outcome, int rank) {
  individual.outcome = outcome;
  individual.evaluated = true;
  individual.eval_seconds = outcome.wall_seconds;
  individual.worker_rank = rank;
}

// the individuals without an outcome, in population order (ids increasing)
std::vector<std::size_t> pendingInIdOrder(const Population& population) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < population.individuals.size(); ++i) {
    if (!population.individuals[i].evaluated)
      order.push_back(i);
  }
  return order;
}

// whether any of the pending individuals' genomes is still to be made (bred)
bool anyToBeMade(const Population& population) {
  return std::any_of(population.individuals.begin(), population.individuals.end(),
                     [](const Individual& i) { return !i.evaluated && !i.genome.made(); });
}

// the result a worker sent; Error(mpi) naming the rank when its bytes do not decode
EvalResult resultFrom(const Message& message) {
  try {
    return decodeResult(message.bytes);
  } catch (const Error& e) {
    throw Error(ExitCode::mpi,
                "malformed result from rank " + std::to_string(message.source) + ": " + e.what());
  }
}

// rank 0's next sleep: `relaxed` (DispatchPace::relaxedMicros, while every worker has work
// queued) or, when that is 0, short looks within a quarter of an evaluation of `mean` seconds;
// but never shorter than `earliest` (ExpectedArrivals: no result can be there before), at most
// the longest relaxed sleep
void paceWait(Backoff& backoff, long relaxed, double mean, long earliest) {
  earliest = std::min(earliest, DispatchPace::kMaxRelaxedMicros);
  if (earliest > std::max(relaxed, Backoff::kMin))
    backoff.range(earliest, earliest);
  else if (relaxed > 0)
    backoff.range(relaxed, relaxed);
  else
    backoff.range(Backoff::kMin, std::min(Backoff::quarterOf(mean), Backoff::kUrgent));
}

}  // namespace

void DispatchSettings::declareSettings(SettingsSchema& s) {
  s.addChoice("run.dispatch_order", order,
              {{"largest_first", DispatchOrder::largest_first},
               {"shuffled", DispatchOrder::shuffled},
               {"smallest_first", DispatchOrder::smallest_first}},
              "order in which a generation's creatures are handed out: largest_first (genome "
              "size) | shuffled | smallest_first; results are the same, only the span changes")
      .runOnly();
  s.addSeed("run.dispatch_seed", seed,
            "shuffled: seed of the per-generation permutations (0 = the run seed)")
      .runOnly();
}

std::vector<std::size_t> schedulingOrder(const Population& population,
                                         const DispatchSettings& dispatch, std::uint64_t run_seed,
                                         double expected_seconds) {
  std::vector<std::size_t> order = pendingInIdOrder(population);

  // shuffled: Fisher-Yates from the generation's own stream, whatever the results so far
  if (dispatch.order == DispatchOrder::shuffled) {
    Rng rng(dispatch.seed != 0 ? dispatch.seed : run_seed, RngPurpose::evaluation,
            population.generation, kDispatchStream);
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[rng.below(i)]);
    return order;
  }

  // short creatures: id order, each genome made only when it is handed out
  if (DispatchPace::isShort(expected_seconds))
    return order;

  // by genome size (the encoding's genes + links), largest or smallest first, ties by id
  bool largest = dispatch.order == DispatchOrder::largest_first;
  std::vector<std::size_t> sizes(population.individuals.size(), 0);
  for (std::size_t i : order) {
    const Genotype& genome = population.individuals[i].genome;
    GenomeSize genome_size = genome.encoding().size(genome);
    sizes[i] = genome_size.genes + genome_size.links;
  }
  auto size = [&](std::size_t i) { return sizes[i]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (size(a) != size(b))
      return largest ? size(a) > size(b) : size(a) < size(b);
    return population.individuals[a].id < population.individuals[b].id;
  });
  return order;
}

EvaluationSpan InProcessEvaluator::evaluate(Population& population, std::uint64_t run_seed,
                                            const std::function<void()>& meanwhile) {
  // nothing runs alongside: rank 0's other work first, outside the span
  if (meanwhile)
    meanwhile();
  EvaluationSpan span;
  span.workers = 1;
  auto start = Clock::now();
  // one after another, in scheduling order
  std::vector<std::size_t> order = schedulingOrder(population, dispatch_, run_seed);
  std::size_t order_size = order.size();
  for (std::size_t index : order) {
    Individual& individual = population.individuals[index];
    EvalResult result = evaluateRequest(
        makeRequest(individual, run_seed, population.individuals.size()), settings_, 0, std::cerr);
    store(individual, result.outcome, 0);
    span.busy_seconds += result.outcome.wall_seconds;
    ++span.evaluations;
    reportProgress(span.evaluations, order_size);
    // testing aid: a kill in the middle of the generation
    if (2 * span.evaluations >= order_size && 2 * (span.evaluations - 1) < order_size)
      testKillPoint("evaluation", population.generation);
  }
  span.span_seconds = since(start);
  return span;
}

void InProcessEvaluator::submit(const Individual& individual, std::uint64_t run_seed) {
  queue_.push_back(makeRequest(individual, run_seed, 0));
}

StreamedResult InProcessEvaluator::take() {
  if (queue_.empty())
    throw std::logic_error("InProcessEvaluator::take: nothing submitted");
  EvalResult result = evaluateRequest(queue_.front(), settings_, 0, std::cerr);
  queue_.pop_front();
  return {result.id, std::move(result.outcome), 0, 0};
}

int DispatchPace::held(double mean_seconds, std::size_t remaining, int workers) const {
  // enough queued work to cover rank 0's sleep several times over
  int depth = in_flight;
  if (mean_seconds > 0) {
    double covering = std::ceil(kQueuedSeconds / mean_seconds);
    depth = static_cast<int>(std::min<double>(1 + covering, std::max(in_flight, kMaxHeld)));
    depth = std::max(depth, in_flight);
  }
  // but one creature more only for every kRemainingPerExtra per worker still to hand out; short
  // creatures keep one queued to the end (a worker holding one waits a round trip to rank 0 for
  // each, longer than the imbalance a queued short creature can cause)
  std::size_t share = 1 + remaining / (kRemainingPerExtra * static_cast<std::size_t>(workers));
  if (isShort(mean_seconds))
    share = std::max(share, static_cast<std::size_t>(in_flight));
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(depth), share));
}

long DispatchPace::relaxedMicros(double mean_seconds, int held) const {
  if (held <= 1 || mean_seconds <= 0)
    return 0;
  // a quarter of the work queued behind the creature being evaluated
  double queued = (held - 1) * mean_seconds;
  return std::clamp(static_cast<long>(queued * 1e6 / 4), kMinRelaxedMicros, kMaxRelaxedMicros);
}

MpiScheduler::MpiScheduler(MpiContext& mpi, const DispatchSettings& dispatch, int in_flight)
    : mpi_(mpi),
      dispatch_(dispatch),
      arrivals_(mpi.size()),
      stream_held_(static_cast<std::size_t>(mpi.size()), 0) {
  pace_.in_flight = std::max(1, in_flight);
  if (mpi.size() < 2)
    throw Error(ExitCode::mpi, "MpiScheduler needs at least 2 ranks");
}

int MpiScheduler::workers() const {
  return mpi_.size() - 1;
}

EvaluationSpan MpiScheduler::evaluate(Population& population, std::uint64_t run_seed,
                                      const std::function<void()>& meanwhile) {
  EvaluationSpan span;
  span.workers = workers();
  // the hand-out order; where it is by size and genomes are still to be bred, the first rounds go
  // in id order (bred one by one as they go out) and the rest are bred and sorted while those
  // evaluate
  const bool sort_later = dispatch_.order != DispatchOrder::shuffled &&
                          !DispatchPace::isShort(last_mean_seconds_) && anyToBeMade(population);
  std::vector<std::size_t> order =
      sort_later ? pendingInIdOrder(population)
                 : schedulingOrder(population, dispatch_, run_seed, last_mean_seconds_);
  std::vector<char> outstanding_for(population.individuals.size(), 0);
  auto start = Clock::now();

  // creatures to every worker
  std::size_t next = 0, outstanding = 0;
  std::vector<int> held(static_cast<std::size_t>(mpi_.size()), 0);  // creatures at each worker
  double breeding_seconds = 0;  // genomes made (bred) while handing out: not dispatch time
  auto hand = [&](int worker) {
    std::size_t index = order[next++];
    auto breeding_start = Clock::now();
    population.individuals[index].genome.bytes();
    breeding_seconds += since(breeding_start);
    mpi_.post(
        worker, Tag::request,
        requestMessage(population.individuals[index], run_seed, population.individuals.size()));
    outstanding_for[index] = 1;
    ++outstanding;
    arrivals_.handed(worker, held[static_cast<std::size_t>(worker)], Clock::now());
    ++held[static_cast<std::size_t>(worker)];
  };
  // the mean evaluation so far in this generation, else the last generation's
  auto mean = [&] {
    return span.evaluations > 0 ? span.busy_seconds / static_cast<double>(span.evaluations)
                                : last_mean_seconds_;
  };
  // creatures a worker should hold now (deep queues for short creatures, one in the tail)
  auto depth = [&] { return pace_.held(mean(), order.size() - next, workers()); };
  auto fill = [&](int worker) {
    int target = depth();
    while (next < order.size() && held[static_cast<std::size_t>(worker)] < target)
      hand(worker);
  };
  // round by round, so every worker has its first creature before any gets a second
  auto dispatch_start = Clock::now();
  const int rounds = depth();
  for (int round = 1; round <= rounds; ++round) {
    for (int worker = 1; worker < mpi_.size(); ++worker) {
      if (next < order.size() && held[static_cast<std::size_t>(worker)] < std::min(round, depth()))
        hand(worker);
    }
  }
  if (sort_later) {
    // the rest in the scheduling order (which breeds them), the creatures handed out left out
    auto breeding_start = Clock::now();
    std::vector<std::size_t> rest = schedulingOrder(population, dispatch_, run_seed);
    breeding_seconds += since(breeding_start);
    order.resize(next);
    for (std::size_t index : rest) {
      if (!outstanding_for[index])
        order.push_back(index);
    }
  }
  span.dispatch_seconds += since(dispatch_start);

  // rank 0's own work, on a thread beside this one, which goes on answering the workers (a
  // history row or a checkpoint can take longer than a short creature's whole queue)
  std::future<void> own_work;
  if (meanwhile) {
    mpi_.completePosted();
    own_work = std::async(std::launch::async, meanwhile);
  }
  // its error, as soon as it has one; else once it is done
  auto ownWorkDone = [&](bool wait) {
    if (own_work.valid() &&
        (wait || own_work.wait_for(std::chrono::seconds(0)) == std::future_status::ready))
      own_work.get();
  };

  // every result is answered with the next creatures; wait by probe + sleep
  Message message;
  Backoff backoff;
  while (outstanding > 0) {
    mpi_.completePosted();
    ownWorkDone(false);
    auto receive_start = Clock::now();
    if (!mpi_.tryReceive(Tag::result, message)) {
      // while every worker has work queued, nothing is urgent: sleep a quarter of it; when a
      // worker holds only the creature it evaluates (it may be waiting for the next), and once
      // everything is handed out (the generation ends with the last result), look often; but
      // not before a result can be there
      auto now = Clock::now();
      arrivals_.foundNothing(now);
      paceWait(backoff, next < order.size() ? pace_.relaxedMicros(mean(), depth()) : 0, mean(),
               arrivals_.microsToEarliest(held, now));
      backoff.wait();
      continue;
    }
    backoff.reset();
    EvalResult result = resultFrom(message);
    // stored by id, whatever the arrival order
    std::size_t index = 0;
    try {
      index = population.indexOf(result.id);
    } catch (const std::out_of_range&) {
      throw Error(ExitCode::mpi, "rank " + std::to_string(message.source) +
                                     " answered for unknown creature " + std::to_string(result.id));
    }
    if (!outstanding_for[index]) {
      throw Error(ExitCode::mpi, "rank " + std::to_string(message.source) +
                                     " answered for creature " + std::to_string(result.id) +
                                     " that was not asked for");
    }
    outstanding_for[index] = 0;
    store(population.individuals[index], result.outcome, message.source);
    span.busy_seconds += result.outcome.wall_seconds;
    ++span.evaluations;
    --outstanding;
    --held[static_cast<std::size_t>(message.source)];
    arrivals_.resultCame(message.source, held[static_cast<std::size_t>(message.source)],
                         result.outcome.wall_seconds);
    // testing aid: a kill in the middle of the generation (after rank 0's own work, as in
    // the point's definition)
    if (2 * span.evaluations >= order.size() && 2 * (span.evaluations - 1) < order.size()) {
      if (testKillArmed("evaluation", population.generation))
        ownWorkDone(true);
      testKillPoint("evaluation", population.generation);
    }
    fill(message.source);
    span.dispatch_seconds += since(receive_start);
    reportProgress(span.evaluations, order.size());
  }
  // every result is in, so every request was received; rank 0's own work done
  mpi_.waitPosted();
  ownWorkDone(true);
  span.span_seconds = since(start);
  span.dispatch_seconds = std::max(0.0, span.dispatch_seconds - breeding_seconds);
  if (span.evaluations > 0)
    last_mean_seconds_ = span.busy_seconds / static_cast<double>(span.evaluations);
  return span;
}

double MpiScheduler::streamMean() const {
  return stream_taken_ > 0 ? stream_busy_seconds_ / static_cast<double>(stream_taken_)
                           : last_mean_seconds_;
}

std::size_t MpiScheduler::streamDepth() const {
  // as deep as a generation's middle: plenty left to hand out
  const int held = pace_.held(streamMean(), std::numeric_limits<std::size_t>::max() / 2, workers());
  return static_cast<std::size_t>(workers()) * static_cast<std::size_t>(std::max(1, held));
}

void MpiScheduler::submit(const Individual& individual, std::uint64_t run_seed) {
  // the worker holding the fewest (ties: the lowest rank)
  int worker = 1;
  for (int w = 2; w < mpi_.size(); ++w) {
    if (stream_held_[static_cast<std::size_t>(w)] < stream_held_[static_cast<std::size_t>(worker)])
      worker = w;
  }
  mpi_.post(worker, Tag::request, requestMessage(individual, run_seed, 0));
  streamed_.insert(individual.id);
  arrivals_.handed(worker, stream_held_[static_cast<std::size_t>(worker)], Clock::now());
  ++stream_held_[static_cast<std::size_t>(worker)];
}

StreamedResult MpiScheduler::take() {
  if (streamed_.empty())
    throw std::logic_error("MpiScheduler::take: nothing submitted");
  Message message;
  for (;;) {
    mpi_.completePosted();
    if (mpi_.tryReceive(Tag::result, message))
      break;
    // every worker with one queued behind the one it evaluates: sleep a quarter of that work;
    // else a worker may be waiting, so look often; but not before a result can be there
    auto now = Clock::now();
    arrivals_.foundNothing(now);
    const int least = *std::min_element(stream_held_.begin() + 1, stream_held_.end());
    paceWait(stream_backoff_, pace_.relaxedMicros(streamMean(), least), streamMean(),
             arrivals_.microsToEarliest(stream_held_, now));
    stream_backoff_.wait();
  }
  auto start = Clock::now();
  stream_backoff_.reset();
  EvalResult result = resultFrom(message);
  if (streamed_.erase(result.id) == 0)
    throw Error(ExitCode::mpi, "rank " + std::to_string(message.source) +
                                   " answered for creature " + std::to_string(result.id) +
                                   " that was not asked for");
  --stream_held_[static_cast<std::size_t>(message.source)];
  arrivals_.resultCame(message.source, stream_held_[static_cast<std::size_t>(message.source)],
                       result.outcome.wall_seconds);
  stream_busy_seconds_ += result.outcome.wall_seconds;
  ++stream_taken_;
  return {result.id, std::move(result.outcome), message.source, since(start)};
}

void MpiScheduler::discardStream() {
  while (!streamed_.empty())
    take();
}

void MpiScheduler::stopWorkers() {
  if (stopped_)
    return;
  stopped_ = true;
  for (int worker = 1; worker < mpi_.size(); ++worker)
    mpi_.send(worker, Tag::stop, {});
}

}  // namespace cambrian
