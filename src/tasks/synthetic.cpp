// cambrian: the synthetic task.
#include "tasks/synthetic.hpp"

#include "cambrian/rng.hpp"

#include "core/settings.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

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

void SyntheticTask::declareSettings(SettingsSchema& s) {
  s.add("task.synthetic_cost_us", cost_us, "synthetic task: busy work per evaluation, microseconds")
      .require([this] { return cost_us >= 0 && cost_us <= 3.6e9; }, "must be in [0, 3.6e9] us");
  s.add("task.synthetic_cost_per_gene_us", cost_per_gene_us,
        "synthetic task: extra busy work per genome node, microseconds")
      .require([this] { return cost_per_gene_us >= 0 && cost_per_gene_us <= 3.6e9; },
               "must be in [0, 3.6e9] us");
  s.add("task.synthetic_noise", noise,
        "synthetic task, uniform distribution: relative spread of the cost (0..1)")
      .require([this] { return noise >= 0 && noise <= 1; }, "must be in [0, 1]");
  s.addChoice("task.synthetic_distribution", distribution,
              {{"uniform", SyntheticDistribution::uniform},
               {"lognormal", SyntheticDistribution::lognormal},
               {"fixed", SyntheticDistribution::fixed}},
              "synthetic task: law of the cost around its mean (base + per-gene cost): uniform "
              "(synthetic_noise) | lognormal (synthetic_cv) | fixed");
  s.addChoice("task.synthetic_work", work,
              {{"spin", SyntheticWork::spin}, {"sleep", SyntheticWork::sleep}},
              "synthetic task: spend the cost as CPU work (spin) or asleep (sleep: to measure the "
              "framework at more ranks than cores); the results are the same");
  s.add("task.synthetic_cv", cv,
        "synthetic task, lognormal distribution: coefficient of variation of the cost (0..4)")
      .require([this] { return cv >= 0 && cv <= 4; }, "must be in [0, 4]");
}

std::vector<MeasureInfo> SyntheticTask::measures() const {
  return {{"cost_us", "us"}, {"nodes", "1"}};
}

double SyntheticTask::costMicroseconds(const GenomeSize& size, std::uint64_t eval_seed) const {
  // the mean cost: base plus the per-gene part
  double cost = cost_us + cost_per_gene_us * static_cast<double>(size.genes);
  Rng rng(eval_seed, RngPurpose::evaluation);

  // times a deterministic factor of mean 1 drawn from the creature's own stream
  double factor = 1;
  switch (distribution) {
    case SyntheticDistribution::uniform:
      factor = 1 + noise * (2 * rng.uniform() - 1);
      break;
    case SyntheticDistribution::lognormal: {
      double variance = std::log(1 + cv * cv);
      if (variance > 0)
        factor = std::exp(std::sqrt(variance) * rng.normal() - variance / 2);
      break;
    }
    case SyntheticDistribution::fixed:
      break;
  }
  return std::max(0.0, cost * factor);
}

double SyntheticTask::fitness(const GenomeSize& size) {
  // mean part side per gene (bigger parts climb) plus a small bonus per link
  double fitness = size.total_part_size;
  fitness += 0.1 * static_cast<double>(size.links);
  return std::isfinite(fitness) ? fitness : kWorstFitness;
}

Outcome SyntheticTask::evaluateGenome(const Genotype& genome, const Encoding& encoding,
                                      std::uint64_t eval_seed) const {
  GenomeSize size = encoding.size(genome);
  Outcome outcome;
  outcome.status = EvalStatus::ok;
  outcome.fitness = fitness(size);
  outcome.parts = static_cast<int>(size.genes);
  outcome.joints = static_cast<int>(size.links);
  double cost = costMicroseconds(size, eval_seed);

  // busy work (or a sleep) until the steady clock says the cost is spent
  auto start = Clock::now();
  auto budget =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::micro>(cost));
  if (work == SyntheticWork::sleep) {
    std::this_thread::sleep_until(start + budget);
  } else {
    volatile double sink = 1;
    while (Clock::now() - start < budget)
      sink = spin(sink, 256);
  }
  // no physics steps: everything but wall_seconds stays deterministic
  outcome.steps = 0;
  outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  outcome.measures = {{"cost_us", cost}, {"nodes", static_cast<double>(size.genes)}};
  return outcome;
}

/// The synthetic task's prototype (for the registry).
const Task& syntheticTask() {
  static const SyntheticTask task;
  return task;
}

}  // namespace cambrian
