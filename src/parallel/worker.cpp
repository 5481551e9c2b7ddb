#include "parallel/worker.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "parallel/mpi_context.hpp"

#include <chrono>
#include <iostream>
#include <ostream>
#include <stdexcept>

namespace cambrian {

void WorkerSettings::declareTestingSettings(SettingsSchema& s) {
  s.add("run.fail_every", fail_every,
        "testing: workers fail every creature whose id is a multiple of this (0 = never)");
  s.add("run.test_worker_abort_at", test_abort_at,
        "testing: the worker rank that receives the creature with this id stops with an "
        "unrecoverable error, ending the job with exit code 8 (0 = never)")
      .runOnly();
}

EvalResult evaluateRequest(const EvalRequest& request, const WorkerSettings& settings, int rank,
                           std::ostream& log) {
  EvalResult result;
  result.id = request.id;
  auto start = std::chrono::steady_clock::now();
  try {
    // the creature, then its evaluation
    Genotype genome = decodeGenome(request.genome);
    if (settings.fail_every > 0 && request.id % settings.fail_every == 0) {
      throw std::runtime_error(
          "injected failure (run.fail_every = " + std::to_string(settings.fail_every) + ")");
    }
    result.outcome = evaluate(genome, settings.creature, request.eval_seed);
  } catch (const std::exception& e) {
    // a failed outcome, never a dead rank
    result.outcome = Outcome{};
    result.outcome.status = EvalStatus::failed;
    result.outcome.fitness = kWorstFitness;
    result.outcome.message = e.what();
    result.outcome.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log << "cambrian evolve: rank " << rank << ": creature " << request.id
        << " failed: " << e.what() << std::endl;
  }
  return result;
}

EvalResult serveRequest(const Message& message, const WorkerSettings& settings, int rank,
                        std::ostream& log) {
  // a request, well formed, or the rank cannot go on
  if (message.tag != Tag::request) {
    throw Error(ExitCode::worker_failure,
                "unexpected message tag " + std::to_string(static_cast<int>(message.tag)));
  }
  EvalRequest request;
  try {
    request = decodeRequest(message.bytes);
  } catch (const Error& e) {
    throw Error(ExitCode::worker_failure, e.what());
  }
  // testing aid: an unrecoverable error, outside the per-creature catch
  if (settings.test_abort_at != 0 && request.id == settings.test_abort_at) {
    throw Error(ExitCode::worker_failure, "injected unrecoverable error on receiving creature " +
                                              std::to_string(request.id) +
                                              " (run.test_worker_abort_at)");
  }
  return evaluateRequest(request, settings, rank, log);
}

void runWorker(MpiContext& mpi, const WorkerSettings& settings) {
  // serve requests until told to stop; waiting for the next, look again within 100 us for the
  // first 20 ms (rank 0 answers a result at once), then within a quarter of an evaluation
  double busy_seconds = 0;
  std::uint64_t served = 0;
  for (;;) {
    double mean = served > 0 ? busy_seconds / static_cast<double>(served) : 0;
    Message message = mpi.receiveAny(0, Backoff::quarterOf(mean), Backoff::kUrgent);
    if (message.tag == Tag::stop)
      return;
    EvalResult result = serveRequest(message, settings, mpi.rank(), std::cerr);
    busy_seconds += result.outcome.wall_seconds;
    ++served;
    mpi.send(0, Tag::result, encodeResult(result));
  }
}

}  // namespace cambrian
