// cambrian: the byte messages of the evolve protocol, on the project's byte writer and reader
// and the one byte form of an outcome.
#include "parallel/messages.hpp"

#include "cambrian/error.hpp"

#include "core/bytes.hpp"
#include "core/outcome_bytes.hpp"

namespace cambrian {

std::vector<std::uint8_t> encodeRequest(const EvalRequest& request) {
  return encodeRequest(request.id, request.eval_seed, request.genome);
}

std::vector<std::uint8_t> encodeRequest(std::uint64_t id, std::uint64_t eval_seed,
                                        const std::vector<std::uint8_t>& genome) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(3 * sizeof(std::uint64_t) + genome.size());
  ByteWriter w(bytes);
  w.u64(id);
  w.u64(eval_seed);
  w.blob(genome.data(), genome.size());
  return bytes;
}

EvalRequest decodeRequest(const std::vector<std::uint8_t>& bytes) {
  ByteReader r(bytes.data(), bytes.size(), "evaluation request");
  EvalRequest request;
  r.context("field 'id'");
  request.id = r.u64();
  r.context("field 'eval_seed'");
  request.eval_seed = r.u64();
  r.context("field 'genome'");
  request.genome = r.blob();
  r.expectEnd();
  return request;
}

std::vector<std::uint8_t> encodeResult(const EvalResult& result) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  w.u64(result.id);
  writeOutcome(w, result.outcome);
  return bytes;
}

EvalResult decodeResult(const std::vector<std::uint8_t>& bytes) {
  ByteReader r(bytes.data(), bytes.size(), "evaluation result");
  EvalResult result;
  r.context("field 'id'");
  result.id = r.u64();
  result.outcome = readOutcome(r);
  r.expectEnd();
  return result;
}

}  // namespace cambrian
