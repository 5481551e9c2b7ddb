// Fuzz target: genome files (the text form of docs/genome.md, or genome bytes), read by
// readGenomeFile. Files it refuses end in cambrian::Error; a genome it accepts passes the checks
// of genome_checks.hpp.
#include "fuzz/fuzz_file.hpp"
#include "fuzz/genome_checks.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static cambrian::fuzz::FuzzFile file("genome");
  const std::string& path = file.write(data, size);
  cambrian::Genotype genome;
  try {
    genome = cambrian::readGenomeFile(path);
  } catch (const cambrian::Error&) {
    return 0;
  }
  cambrian::fuzz::checkAcceptedGenome(genome);
  return 0;
}
