// Fuzz target: genome bytes (the form MPI messages, history rows and checkpoints carry), read by
// decodeGenome. Bytes it refuses end in cambrian::Error; a genome it accepts passes the checks of
// genome_checks.hpp.
#include "fuzz/genome_checks.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cambrian::Genotype genome;
  try {
    genome = cambrian::decodeGenome(data, size);
  } catch (const cambrian::Error&) {
    return 0;
  }
  cambrian::fuzz::checkAcceptedGenome(genome);
  return 0;
}
