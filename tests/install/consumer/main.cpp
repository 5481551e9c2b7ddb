// An embedder of an installed cambrian: loads a creature file (or draws a random genome of the
// default encoding when no file is given), evaluates it on a short walk and prints its status
// and fitness.
//   consumer [GENOME_FILE]
#include "cambrian/encodings.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/version.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  try {
    // the default creature settings, with a short walk so the check stays quick
    cambrian::CreatureSettings settings;
    settings.set("task.evaluation_time", "1.0");
    settings.check();
    const cambrian::Genotype genome =
        argc > 1 ? cambrian::readGenomeFile(argv[1]) : settings.encoding().random(42, 0, 0);

    const cambrian::Outcome outcome = cambrian::evaluate(genome, settings, 1);
    std::printf("cambrian %s: status %s fitness %.6f parts %d steps %llu\n", cambrian::kVersion,
                cambrian::statusName(outcome.status), outcome.fitness, outcome.parts,
                static_cast<unsigned long long>(outcome.steps));
    return outcome.status == cambrian::EvalStatus::ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
