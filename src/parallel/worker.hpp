// cambrian: what a worker rank does — receive a creature, evaluate it, send the outcome back.
#pragma once

#include "cambrian/evaluate.hpp"

#include "parallel/messages.hpp"
#include "parallel/mpi_context.hpp"

#include <cstdint>
#include <iosfwd>

namespace cambrian {

class SettingsSchema;

/// How a worker evaluates creatures (the same on every rank).
struct WorkerSettings {
  CreatureSettings creature;  ///< encoding, task, physics, environment
  /// Testing aid: throw inside the evaluation of every creature whose id is a multiple of this
  /// (0 = never), to exercise the failure path.
  std::uint64_t fail_every = 0;
  /// Testing aid: on receiving the creature with this id, the worker rank stops with an
  /// unrecoverable Error(worker_failure), outside the per-creature catch (0 = never). Only worker
  /// ranks serve requests, so a one-rank (in-process) run never stops for it.
  std::uint64_t test_abort_at = 0;

  /// Declares the two testing keys run.fail_every and run.test_worker_abort_at (run-only), bound
  /// to this object; the creature settings declare their own.
  void declareTestingSettings(SettingsSchema& schema);
};

/// Evaluates one request. Never throws: an exception (bad genome bytes, an error inside
/// evaluate, an injected failure) becomes an Outcome with status failed, kWorstFitness and the
/// message, and a line on `log` naming `rank` and the creature id.
EvalResult evaluateRequest(const EvalRequest& request, const WorkerSettings& settings, int rank,
                           std::ostream& log);

/// One message from rank 0 that is not the stop message: decodes the request and evaluates it
/// (evaluateRequest). Throws Error(worker_failure) when the message is not a well-formed request,
/// and for the creature `settings.test_abort_at`; the message names the creature or the tag.
EvalResult serveRequest(const Message& message, const WorkerSettings& settings, int rank,
                        std::ostream& log);

/// The worker loop: waits for requests from rank 0 (probe + sleep, no spinning), answers each with
/// its result (serveRequest), returns on the stop message. Throws Error(worker_failure) on a
/// malformed message or the injected test_abort_at.
void runWorker(MpiContext& mpi, const WorkerSettings& settings);

}  // namespace cambrian
