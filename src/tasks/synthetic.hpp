// cambrian: the synthetic task — a fixed amount of real CPU work and a cheap fitness, for
// measuring the framework's own overhead and scaling without physics.
#pragma once

#include "tasks/task.hpp"

#include <cstdint>

namespace cambrian {

/// How the synthetic task's cost varies from creature to creature (task.synthetic_distribution).
enum class SyntheticDistribution : std::uint8_t {
  uniform,    ///< mean cost times 1 + synthetic_noise * (2u - 1)
  lognormal,  ///< lognormal with the mean cost as mean and synthetic_cv as coefficient of variation
  fixed,      ///< the mean cost, always
};

/// How the synthetic task spends its cost (task.synthetic_work).
enum class SyntheticWork : std::uint8_t {
  spin,   ///< real CPU work, timed by a steady clock: the cost of a creature
  sleep,  ///< a sleep: the framework measured at more ranks than the machine has cores
};

/// Evaluates genomes without bodies: busy work for a cost drawn per creature, a fitness that is
/// a smooth function of the genome's sizes.
class SyntheticTask : public Task {
 public:
  std::unique_ptr<Task> clone() const override { return std::make_unique<SyntheticTask>(*this); }
  std::string name() const override { return "synthetic"; }
  std::string summary() const override { return "CPU work and a cheap fitness, no physics"; }
  void declareSettings(SettingsSchema& schema) override;
  std::vector<MeasureInfo> measures() const override;
  bool needsBody() const override { return false; }
  /// Busy-works (or, with SyntheticWork::sleep, sleeps) for costMicroseconds() by a steady
  /// clock, then returns status ok, fitness() and the measures "cost_us" (the deterministic target
  /// cost) and "nodes". Does not allocate while it works.
  Outcome evaluateGenome(const Genotype& genome, const Encoding& encoding,
                         std::uint64_t eval_seed) const override;

  /// The cost in microseconds spent on a genome of `size`: the mean cost
  /// m = cost_us + cost_per_gene_us * genes, drawn by `distribution` from
  /// Rng(eval_seed, RngPurpose::evaluation) (a pure function of the arguments):
  /// - uniform: m * (1 + noise * (2u - 1)), u the stream's first uniform;
  /// - lognormal: m * exp(s z - s^2 / 2), s^2 = ln(1 + cv^2), z the stream's first normal
  ///   (Rng::normal), so the mean is m and the coefficient of variation cv;
  /// - fixed: m.
  /// Never negative.
  double costMicroseconds(const GenomeSize& size, std::uint64_t eval_seed) const;
  /// The fitness: the mean part side of every gene plus 0.1 per link, always >= 0 and finite.
  static double fitness(const GenomeSize& size);

  double cost_us = 10000;       ///< busy work per evaluation, microseconds
  double cost_per_gene_us = 0;  ///< extra per gene (genome node)
  double noise = 0;             ///< uniform: relative spread of the cost
  SyntheticDistribution distribution = SyntheticDistribution::uniform;  ///< cost law
  double cv = 0.5;                           ///< lognormal: coefficient of variation of the cost
  SyntheticWork work = SyntheticWork::spin;  ///< how the cost is spent
};

}  // namespace cambrian
