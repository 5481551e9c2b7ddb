#include "tasks/synthetic.hpp"

#include "cambrian/rng.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// a little floating-point work the optimiser cannot remove
double spin(double x, int rounds) {
  for (int i = 0; i < rounds; ++i)
    x = x * 1.0000001 + 0.0000001;
  return x;
}

}  // namespace

double syntheticCostMicroseconds(const Genome& genome, const TaskSettings& task,
                                 std::uint64_t eval_seed) {
  // the mean cost: base plus the per-gene part
  double cost = task.synthetic_cost_us +
                task.synthetic_cost_per_gene_us * static_cast<double>(genome.nodes.size());
  Rng rng(eval_seed, RngPurpose::evaluation);

  // times a deterministic factor of mean 1 drawn from the creature's own stream
  double factor = 1;
  switch (task.synthetic_distribution) {
    case SyntheticDistribution::uniform:
      factor = 1 + task.synthetic_noise * (2 * rng.uniform() - 1);
      break;
    case SyntheticDistribution::lognormal: {
      double variance = std::log(1 + task.synthetic_cv * task.synthetic_cv);
      if (variance > 0)
        factor = std::exp(std::sqrt(variance) * rng.normal() - variance / 2);
      break;
    }
    case SyntheticDistribution::fixed:
      break;
  }
  return std::max(0.0, cost * factor);
}

double syntheticFitness(const Genome& genome) {
  // mean box side per node (bigger boxes climb) plus a small bonus per connection
  double fitness = 0;
  for (const PartGene& node : genome.nodes) {
    double side = (node.dimensions.x + node.dimensions.y + node.dimensions.z) / 3;
    if (std::isfinite(side))
      fitness += std::max(0.0, side);
  }
  fitness += 0.1 * static_cast<double>(genome.connections.size());
  return std::isfinite(fitness) ? fitness : kWorstFitness;
}

Outcome evaluateSynthetic(const Genome& genome, const TaskSettings& task, std::uint64_t eval_seed) {
  Outcome outcome;
  outcome.status = EvalStatus::ok;
  outcome.fitness = syntheticFitness(genome);
  outcome.parts = static_cast<int>(genome.nodes.size());
  outcome.joints = static_cast<int>(genome.connections.size());
  double cost_us = syntheticCostMicroseconds(genome, task, eval_seed);

  // busy work until the steady clock says the cost is spent
  auto start = Clock::now();
  auto budget = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double, std::micro>(cost_us));
  volatile double sink = 1;
  while (Clock::now() - start < budget)
    sink = spin(sink, 256);
  // no physics steps: everything but wall_seconds stays deterministic
  outcome.steps = 0;
  outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  outcome.measures = {{"cost_us", cost_us}, {"nodes", static_cast<double>(genome.nodes.size())}};
  return outcome;
}

}  // namespace cambrian
