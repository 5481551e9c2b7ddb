// An embedder of an installed cambrian: loads a creature file (or draws a random genome when no
// file is given), evaluates it on a short walk and prints its status and fitness.
//   consumer [GENOME_FILE]
#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"
#include "cambrian/version.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  try {
    const cambrian::GenomeLimits limits;
    const cambrian::Genome genome =
        argc > 1 ? cambrian::readGenomeFile(argv[1]) : cambrian::randomGenome(limits, 42);

    // a short walk, so the check stays quick
    cambrian::TaskSettings task;
    task.evaluation_time = 1.0;
    const cambrian::PhysicsSettings physics;
    const cambrian::Outcome outcome = cambrian::evaluate(genome, limits, task, physics, 1);

    std::printf("cambrian %s: status %s fitness %.6f parts %d steps %llu\n", cambrian::kVersion,
                cambrian::statusName(outcome.status), outcome.fitness, outcome.parts,
                static_cast<unsigned long long>(outcome.steps));
    return outcome.status == cambrian::EvalStatus::ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
