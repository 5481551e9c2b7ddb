// Fuzz target: the evolve protocol's messages (src/parallel/messages.cpp), as a worker decodes a
// request (and the genome in it) and rank 0 a result. The first byte chooses which; the rest is
// the message. A message refused ends in cambrian::Error; one accepted is written back to the
// same bytes.
#include "fuzz/genome_checks.hpp"
#include "parallel/messages.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0)
    return 0;
  std::vector<std::uint8_t> message(data + 1, data + size);
  try {
    if (data[0] % 2 == 0) {
      cambrian::EvalRequest request = cambrian::decodeRequest(message);
      cambrian::fuzz::require(cambrian::encodeRequest(request) == message,
                              "a request written again gives the same bytes");
      cambrian::fuzz::checkAcceptedGenome(cambrian::decodeGenome(request.genome));
    } else {
      cambrian::EvalResult result = cambrian::decodeResult(message);
      cambrian::fuzz::require(cambrian::encodeResult(result) == message,
                              "a result written again gives the same bytes");
    }
  } catch (const cambrian::Error&) {
  }
  return 0;
}
