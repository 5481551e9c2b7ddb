// cambrian: evaluating a population — rank 0's self-scheduler over the worker ranks, or in
// process when the job has a single rank.
#pragma once

#include "evolution/population.hpp"
#include "parallel/expected_arrivals.hpp"
#include "parallel/worker.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <unordered_set>
#include <vector>

namespace cambrian {

class MpiContext;
class SettingsSchema;

/// What evaluating one generation cost.
struct EvaluationSpan {
  std::size_t evaluations = 0;  ///< individuals evaluated
  int workers = 0;              ///< ranks that evaluated
  double span_seconds = 0;      ///< first request to last result, wall clock
  double busy_seconds = 0;      ///< sum of the evaluations' wall times
  double dispatch_seconds = 0;  ///< rank 0 handing out and taking in (its waits and the
                                ///< breeding of genomes made as they are handed out left out)
};

/// The order in which a generation's pending individuals are handed out (run.dispatch_order).
/// Results are stored by id, so no order changes them: only which worker gets which creature
/// when, and so the span of a generation.
enum class DispatchOrder : std::uint8_t {
  largest_first,   ///< genes + links (Encoding::size) descending, ties by id: longest
  shuffled,        ///< a permutation drawn per generation from the dispatch seed
  smallest_first,  ///< genes + links ascending, ties by id
};

/// How pending individuals are ordered.
struct DispatchSettings {
  DispatchOrder order = DispatchOrder::largest_first;
  /// shuffled: the permutation of generation g comes from Rng(seed, evaluation, g, 2^64 - 1)
  /// (a counter no evaluation seed uses); 0 = the run seed
  std::uint64_t seed = 0;

  /// Declares run.dispatch_order and run.dispatch_seed (both run-only), bound to this object.
  void declareSettings(SettingsSchema& schema);
};

/// Order in which pending individuals are handed out (`dispatch.order`; by default longest
/// expected first: genes + links descending, ties by id). Where evaluations are expected to be
/// short (`expected_seconds` in (0, DispatchPace::kShortSeconds)) the size orders become id
/// order, so that no genome need be made (bred) before the first is handed out. A pure function
/// of the population's genomes, ids, evaluated flags and generation, `dispatch`, `run_seed` and
/// `expected_seconds`. Returns indices into the population.
std::vector<std::size_t> schedulingOrder(const Population& population,
                                         const DispatchSettings& dispatch = {},
                                         std::uint64_t run_seed = 0, double expected_seconds = 0);

/// One result of a stream of creatures (steady-state evolution).
struct StreamedResult {
  std::uint64_t id = 0;
  Outcome outcome;
  int rank = 0;                 ///< the rank that evaluated it
  double dispatch_seconds = 0;  ///< rank 0 taking it in (receiving, decoding), waits left out
};

/// Evaluates every individual of a population that has no outcome yet; outcomes are stored by
/// id, never by arrival order. Or, for steady-state evolution, a stream of creatures: each
/// submitted one at a time and taken back as it is done.
class PopulationEvaluator {
 public:
  virtual ~PopulationEvaluator() = default;

  /// Steady state: hands out one creature (its genome made here when still deferred), to be
  /// evaluated as soon as a worker is free. Its request is what evaluate() would send.
  virtual void submit(const Individual& individual, std::uint64_t run_seed) = 0;
  /// Steady state: the next result done (waits for one; never spinning). Throws std::logic_error
  /// when nothing is handed out, Error(mpi) on a malformed or unexpected result.
  virtual StreamedResult take() = 0;
  /// Steady state: creatures submitted and not yet taken.
  virtual std::size_t streaming() const = 0;
  /// Steady state: how many creatures to keep handed out so that no worker waits — for the
  /// evaluations taken so far (DispatchPace: a few milliseconds of work per worker).
  virtual std::size_t streamDepth() const = 0;
  /// Steady state, stopping: forgets every creature handed out (their results, where workers
  /// evaluate them, are waited for and dropped, so no message is left unreceived).
  virtual void discardStream() = 0;

  /// Fills outcome, evaluated, eval_seconds and worker_rank of each unevaluated individual.
  /// `meanwhile` (when set) is called once while the workers evaluate — rank 0's own work that
  /// need not hold them up, such as writing the previous generation to the history — or, with no
  /// workers to overlap, before evaluating. It may run on a thread of its own, done before
  /// evaluate() returns (its exception then thrown there): it must not touch MPI, the
  /// population being evaluated or the progress function's state.
  virtual EvaluationSpan evaluate(Population& population, std::uint64_t run_seed,
                                  const std::function<void()>& meanwhile = {}) = 0;
  /// Ranks that evaluate.
  virtual int workers() const = 0;

  /// Called on rank 0 after each result of evaluate(): results in so far and results due.
  using Progress = std::function<void(std::size_t done, std::size_t due)>;
  /// Sets (or, empty, clears) the function told of each result.
  void onProgress(Progress progress) { progress_ = std::move(progress); }

 protected:
  /// Tells the progress function, when there is one.
  void reportProgress(std::size_t done, std::size_t due) const {
    if (progress_)
      progress_(done, due);
  }

 private:
  Progress progress_;
};

/// Evaluates in this process, one creature after another (a job with one rank).
class InProcessEvaluator : public PopulationEvaluator {
 public:
  /// `settings` are the creature settings every evaluation uses; `dispatch` the order.
  explicit InProcessEvaluator(const WorkerSettings& settings, const DispatchSettings& dispatch = {})
      : settings_(settings), dispatch_(dispatch) {}
  EvaluationSpan evaluate(Population& population, std::uint64_t run_seed,
                          const std::function<void()>& meanwhile = {}) override;
  int workers() const override { return 1; }
  /// Queues the request; take() evaluates the oldest (so results come in submission order).
  void submit(const Individual& individual, std::uint64_t run_seed) override;
  StreamedResult take() override;
  std::size_t streaming() const override { return queue_.size(); }
  /// One: a child is bred after each result.
  std::size_t streamDepth() const override { return 1; }
  void discardStream() override { queue_.clear(); }

 private:
  WorkerSettings settings_;
  DispatchSettings dispatch_;
  std::deque<EvalRequest> queue_;  // submitted, not yet evaluated
};

/// How many creatures a worker holds and how long rank 0 may sleep, from the expected
/// evaluation time. A worker holds enough queued work to cover rank 0's sleep several times over
/// (so short creatures come in deep queues and a worker never waits for rank 0 to wake), but
/// never more than its share of what is left to hand out (so at the end of a generation no
/// creature waits behind a queue while other workers are idle). A pure function of its inputs.
struct DispatchPace {
  /// Work a worker holds queued beyond the creature it evaluates, seconds.
  static constexpr double kQueuedSeconds = 0.004;
  /// Creatures shorter than this are held in_flight deep to the end of a generation, handed out
  /// in id order and bred as they go out.
  static constexpr double kShortSeconds = 2 * kQueuedSeconds;
  /// Whether evaluations of `mean_seconds` (0: not known) are short.
  static bool isShort(double mean_seconds) {
    return mean_seconds > 0 && mean_seconds < kShortSeconds;
  }
  /// Most creatures a worker holds at once.
  static constexpr int kMaxHeld = 64;
  /// Creatures per worker that must remain unhanded for a worker to hold one more.
  static constexpr std::size_t kRemainingPerExtra = 4;
  /// Rank 0's sleep while every worker has work queued: a quarter of that work, within these.
  static constexpr long kMinRelaxedMicros = 50, kMaxRelaxedMicros = 20000;
  /// Creatures each worker holds at least (the one it evaluates and the next).
  int in_flight = 2;

  /// Creatures a worker should hold when evaluations take `mean_seconds` (0: not known yet) and
  /// `remaining` creatures of the generation are not yet handed out to any of `workers`.
  int held(double mean_seconds, std::size_t remaining, int workers) const;
  /// Rank 0's sleep between looks while workers hold `held` creatures each of `mean_seconds`;
  /// 0 when a worker holds only the creature it evaluates (then rank 0 answers within a quarter
  /// of an evaluation, Backoff::quarterOf, and at most Backoff::kUrgent).
  long relaxedMicros(double mean_seconds, int held) const;
};

/// Rank 0's self-scheduler: each worker gets creatures (in schedulingOrder) to the depth
/// DispatchPace gives, and each result is answered with the next creatures, so a worker has its
/// next creature queued and never waits for rank 0 to wake up and answer. Requests are posted
/// (MPI_Isend); waits by probe + a sleep sized by the queued work, never spinning. Throws
/// Error(mpi) when a worker sends a malformed or unexpected result.
class MpiScheduler : public PopulationEvaluator {
 public:
  /// Creatures each worker holds at least: the one it evaluates and the next, queued.
  static constexpr int kDefaultInFlight = 2;
  /// `mpi` must have at least two ranks and outlive the scheduler; creatures are handed out in
  /// schedulingOrder(population, dispatch, run seed); `in_flight` >= 1.
  explicit MpiScheduler(MpiContext& mpi, const DispatchSettings& dispatch = {},
                        int in_flight = kDefaultInFlight);
  /// `meanwhile` runs on a thread of its own once every worker holds its first creatures, while
  /// this thread goes on answering the workers.
  EvaluationSpan evaluate(Population& population, std::uint64_t run_seed,
                          const std::function<void()>& meanwhile = {}) override;
  int workers() const override;
  /// Posts the request to the worker holding the fewest creatures (ties: the lowest rank).
  void submit(const Individual& individual, std::uint64_t run_seed) override;
  /// Waits by probe + a sleep sized by the work the workers hold (as evaluate()).
  StreamedResult take() override;
  std::size_t streaming() const override { return streamed_.size(); }
  /// Workers x DispatchPace::held for the mean evaluation so far (the last generation's, or the
  /// stream's own once it has results).
  std::size_t streamDepth() const override;
  void discardStream() override;
  /// Sends the stop message to every worker (once; later calls do nothing).
  void stopWorkers();

 private:
  MpiContext& mpi_;
  DispatchSettings dispatch_;
  DispatchPace pace_;
  ExpectedArrivals arrivals_;     // when a result can next come in (generations and the stream)
  double last_mean_seconds_ = 0;  // the mean evaluation of the last generation (0: none yet)
  bool stopped_ = false;
  // the stream (steady state): ids out, creatures each worker holds, evaluations taken
  std::unordered_set<std::uint64_t> streamed_;
  std::vector<int> stream_held_;
  double stream_busy_seconds_ = 0;
  std::size_t stream_taken_ = 0;
  Backoff stream_backoff_;
  double streamMean() const;
};

}  // namespace cambrian
