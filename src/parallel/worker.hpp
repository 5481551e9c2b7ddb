// cambrian: what a worker rank does — receive a creature, evaluate it, send the outcome back.
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"

#include "parallel/messages.hpp"

#include <cstdint>
#include <iosfwd>

namespace cambrian {

class MpiContext;

/// How a worker evaluates creatures (the same on every rank).
struct WorkerSettings {
  GenomeLimits limits;
  TaskSettings task;
  PhysicsSettings physics;
  /// Testing aid: throw inside the evaluation of every creature whose id is a multiple of this
  /// (0 = never), to exercise the failure path.
  std::uint64_t fail_every = 0;
};

/// Evaluates one request. Never throws: an exception (bad genome bytes, an error inside
/// evaluate, an injected failure) becomes an Outcome with status failed, kWorstFitness and the
/// message, and a line on `log` naming `rank` and the creature id.
EvalResult evaluateRequest(const EvalRequest& request, const WorkerSettings& settings, int rank,
                           std::ostream& log);

/// The worker loop: waits for requests from rank 0 (probe + sleep, no spinning), answers each with
/// its result, returns on the stop message. Throws Error(worker_failure) on a malformed message.
void runWorker(MpiContext& mpi, const WorkerSettings& settings);

}  // namespace cambrian
