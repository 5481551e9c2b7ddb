// cambrian: evaluating a population — rank 0's self-scheduler over the worker ranks, or in
// process when the job has a single rank.
#pragma once

#include "evolution/population.hpp"
#include "parallel/worker.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
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
  double dispatch_seconds = 0;  ///< rank 0 handing out and taking in (its waits left out)
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
/// expected first: genes + links descending, ties by id). A pure function of the
/// population's genomes, ids, evaluated flags and generation, `dispatch` and `run_seed`.
/// Returns indices into the population.
std::vector<std::size_t> schedulingOrder(const Population& population,
                                         const DispatchSettings& dispatch = {},
                                         std::uint64_t run_seed = 0);

/// Evaluates every individual of a population that has no outcome yet; outcomes are stored by
/// id, never by arrival order.
class PopulationEvaluator {
 public:
  virtual ~PopulationEvaluator() = default;
  /// Fills outcome, evaluated, eval_seconds and worker_rank of each unevaluated individual.
  /// `meanwhile` (when set) is called once while the workers evaluate — rank 0's own work that
  /// need not hold them up, such as writing the previous generation to the history — or, with no
  /// workers to overlap, before evaluating.
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

 private:
  WorkerSettings settings_;
  DispatchSettings dispatch_;
};

/// Rank 0's self-scheduler: each worker gets `in_flight` creatures (in schedulingOrder) and
/// each result is answered with the next creature, so a worker has its next creature queued and
/// never waits for rank 0 to wake up and answer. In the tail of a generation (fewer than
/// kQueueWhileRemainingPerWorker creatures per worker left to hand out) workers hold one
/// creature, so none waits behind a long one while others idle. Requests are posted (MPI_Isend);
/// waits by probe + adaptive sleep, never spinning. Throws Error(mpi) when a worker sends a
/// malformed or unexpected result.
class MpiScheduler : public PopulationEvaluator {
 public:
  /// Creatures each worker holds at once: the one it evaluates and the next, queued.
  static constexpr int kDefaultInFlight = 2;
  /// Creatures per worker that must remain unhanded for a worker to hold more than one.
  static constexpr std::size_t kQueueWhileRemainingPerWorker = 4;
  /// `mpi` must have at least two ranks and outlive the scheduler; creatures are handed out in
  /// schedulingOrder(population, dispatch, run seed); `in_flight` >= 1.
  explicit MpiScheduler(MpiContext& mpi, const DispatchSettings& dispatch = {},
                        int in_flight = kDefaultInFlight);
  /// `meanwhile` runs once every worker holds its first creatures.
  EvaluationSpan evaluate(Population& population, std::uint64_t run_seed,
                          const std::function<void()>& meanwhile = {}) override;
  int workers() const override;
  /// Sends the stop message to every worker (once; later calls do nothing).
  void stopWorkers();

 private:
  MpiContext& mpi_;
  DispatchSettings dispatch_;
  int in_flight_;
  bool stopped_ = false;
};

}  // namespace cambrian
