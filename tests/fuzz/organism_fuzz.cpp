// Fuzz target: springy organism files, text (docs/springy.md) or bytes (told apart by the tag),
// read by parseOrganismText and organismFromBytes. Input they refuse ends in cambrian::Error; an
// organism they accept is written again to the same bytes, its text form reads back to those
// bytes (a NaN's payload aside), and the rules refuse it by name or pass it.
#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "encodings/springy/muscle_operators.hpp"
#include "encodings/springy/organism_forms.hpp"
#include "encodings/springy/rules.hpp"
#include "fuzz/genome_checks.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cambrian::springy;
  using cambrian::fuzz::require;
  Organism organism;
  const bool binary = size >= kOrganismTag.size() &&
                      std::memcmp(data, kOrganismTag.data(), kOrganismTag.size()) == 0;
  try {
    organism = binary ? organismFromBytes(data, size)
                      : parseOrganismText(std::string(reinterpret_cast<const char*>(data), size),
                                          "organism");
  } catch (const cambrian::Error&) {
    return 0;
  }
  const std::vector<std::uint8_t> bytes = organismToBytes(organism);
  if (binary)
    require(bytes == std::vector<std::uint8_t>(data, data + size), "written again, the same bytes");
  const Organism again = organismFromBytes(bytes.data(), bytes.size());
  require(organismToBytes(again) == bytes, "its bytes read back to the same bytes");
  // a NaN is written "nan", its payload lost (as in genome files): then the text must be stable
  const std::string text = organismToText(organism);
  const Organism from_text = parseOrganismText(text, "text form");
  if (text.find("nan") == std::string::npos)
    require(organismToBytes(from_text) == bytes, "its text form reads back to the same bytes");
  else
    require(organismToText(from_text) == text, "its text form with a NaN reads back to the text");
  try {
    checkOrganism(organism, MuscleLimits{});
  } catch (const cambrian::Error&) {
    return 0;  // broken rules are refused by name
  }
  cambrian::Rng rng(1, cambrian::RngPurpose::test);
  try {
    checkOrganism(randomControl(organism, MuscleOperatorSettings{}, rng), MuscleLimits{});
  } catch (const cambrian::Error&) {
    return 0;  // a tube longer than the maximal muscle length has no muscle
  }
  return 0;
}
