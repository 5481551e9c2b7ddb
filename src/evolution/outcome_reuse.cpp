// cambrian: outcomes reused for copies of a parent's or a sibling's genome.
#include "evolution/outcome_reuse.hpp"

#include <string_view>
#include <unordered_map>

namespace cambrian {

namespace {

// the genome's bytes as a key (the genotype keeps them while the population lives)
std::string_view key(const Individual& individual) {
  const std::vector<std::uint8_t>& bytes = individual.genomeBytes();
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// `copy` takes `original`'s outcome; it was not simulated
void takeOutcome(Individual& copy, const Individual& original) {
  copy.outcome = original.outcome;
  copy.outcome.wall_seconds = 0;
  copy.evaluated = true;
  copy.eval_seconds = 0;
  copy.worker_rank = -1;
}

}  // namespace

OutcomeReuse reuseKnownOutcomes(Population& generation, const Population* parents) {
  OutcomeReuse reuse;
  std::unordered_map<std::string_view, const Individual*> known;
  if (parents) {
    for (const Individual& parent : parents->individuals)
      if (parent.evaluated && parent.outcome.status != EvalStatus::timeout)
        known.emplace(key(parent), &parent);
  }
  std::unordered_map<std::string_view, std::size_t> pending;  // first unevaluated of a genome
  for (std::size_t i = 0; i < generation.individuals.size(); ++i) {
    Individual& individual = generation.individuals[i];
    if (individual.evaluated)
      continue;
    if (auto parent = known.find(key(individual)); parent != known.end()) {
      takeOutcome(individual, *parent->second);
      ++reuse.from_parents;
      continue;
    }
    auto [first, inserted] = pending.emplace(key(individual), i);
    if (!inserted) {
      individual.evaluated = true;  // not handed out; its outcome comes after the evaluation
      reuse.siblings.emplace_back(i, first->second);
    }
  }
  return reuse;
}

void copySiblingOutcomes(Population& generation, const OutcomeReuse& reuse) {
  for (const auto& [copy, original] : reuse.siblings)
    takeOutcome(generation.individuals[copy], generation.individuals[original]);
}

}  // namespace cambrian
