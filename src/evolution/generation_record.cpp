// cambrian: generation record helpers and the run digest.
#include "evolution/generation_record.hpp"

#include <algorithm>
#include <cstring>

namespace cambrian {

double GenerationRecord::evaluationsPerSecond() const {
  if (evaluation_span_seconds <= 0)
    return 0;
  return static_cast<double>(evaluations) / evaluation_span_seconds;
}

double GenerationRecord::utilisation() const {
  double available = workers * evaluation_span_seconds;
  if (available <= 0)
    return 0;
  return worker_busy_seconds / available;
}

std::uint64_t distinctGenomes(const Population& population) {
  // the byte strings sorted in place (no copies), then the runs of equal ones counted
  std::vector<const std::vector<std::uint8_t>*> genomes;
  for (const Individual& individual : population.individuals)
    genomes.push_back(&individual.genomeBytes());
  auto less = [](auto* a, auto* b) { return *a < *b; };
  auto equal = [](auto* a, auto* b) { return *a == *b; };
  std::sort(genomes.begin(), genomes.end(), less);
  return static_cast<std::uint64_t>(std::unique(genomes.begin(), genomes.end(), equal) -
                                    genomes.begin());
}

void RunDigest::add(const Individual& individual) {
  // id and fitness as little-endian 64-bit words, then the genome bytes
  hash_.addWord(individual.id);
  const std::vector<std::uint8_t>& genome = individual.genomeBytes();
  hash_.addWord(genome.size());
  hash_.add(genome.data(), genome.size());
  double fitness = individual.fitness();
  std::uint64_t bits;
  std::memcpy(&bits, &fitness, sizeof bits);
  hash_.addWord(bits);
}

void RunDigest::add(const Population& population) {
  for (const Individual& individual : population.individuals)
    add(individual);
}

std::string RunDigest::hex() const {
  return hex16(hash_.value());
}

}  // namespace cambrian
