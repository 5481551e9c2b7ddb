// cambrian: the synthetic task — a fixed amount of real CPU work and a cheap fitness, for
// measuring the framework's own overhead and scaling without physics.
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"
#include "cambrian/outcome.hpp"

#include <cstdint>

namespace cambrian {

/// The cost in microseconds the synthetic task spends on `genome`: the mean cost
/// m = synthetic_cost_us + synthetic_cost_per_gene_us * nodes, drawn by synthetic_distribution
/// from Rng(eval_seed, RngPurpose::evaluation) (a pure function of the three arguments):
/// - uniform: m * (1 + synthetic_noise * (2u - 1)), u the stream's first uniform;
/// - lognormal: m * exp(s z - s^2 / 2), s^2 = ln(1 + synthetic_cv^2), z the stream's first
///   normal (Rng::normal), so the mean is m and the coefficient of variation synthetic_cv;
/// - fixed: m.
/// Never negative.
double syntheticCostMicroseconds(const Genome& genome, const TaskSettings& task,
                                 std::uint64_t eval_seed);

/// The synthetic fitness: a smooth, deterministic function of the genome that evolution can
/// climb (mean box side of every node plus 0.1 per connection, capped by the node and connection
/// counts), always >= 0 and finite.
double syntheticFitness(const Genome& genome);

/// Busy-works for syntheticCostMicroseconds() (real CPU work timed by a steady clock, not a
/// sleep), then returns status ok, syntheticFitness() and the measures "cost_us" (the
/// deterministic target cost) and "nodes". Does not allocate while it works.
Outcome evaluateSynthetic(const Genome& genome, const TaskSettings& task, std::uint64_t eval_seed);

}  // namespace cambrian
