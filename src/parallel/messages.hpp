// cambrian: the byte messages of the evolve protocol (no MPI here: plain encode / decode).
#pragma once

#include "cambrian/outcome.hpp"

#include <cstdint>
#include <vector>

namespace cambrian {

/// rank 0 -> worker: evaluate this genome.
struct EvalRequest {
  std::uint64_t id = 0;              ///< the individual's id
  std::uint64_t eval_seed = 0;       ///< seed of any randomness inside the evaluation
  std::vector<std::uint8_t> genome;  ///< serializeGenome() bytes
  friend bool operator==(const EvalRequest&, const EvalRequest&) = default;
};

/// worker -> rank 0: the outcome for an id.
struct EvalResult {
  std::uint64_t id = 0;
  Outcome outcome;
};

/// Little-endian encoding of a request.
std::vector<std::uint8_t> encodeRequest(const EvalRequest& request);
/// The same bytes from the fields (rank 0's: the genome's byte form is not copied first).
std::vector<std::uint8_t> encodeRequest(std::uint64_t id, std::uint64_t eval_seed,
                                        const std::vector<std::uint8_t>& genome);
/// Inverse of encodeRequest; throws InputError naming the field on truncated bytes.
EvalRequest decodeRequest(const std::vector<std::uint8_t>& bytes);
/// Little-endian encoding of a result (every Outcome field, bit-exact doubles).
std::vector<std::uint8_t> encodeResult(const EvalResult& result);
/// Inverse of encodeResult; throws InputError naming the field on truncated or bad bytes.
EvalResult decodeResult(const std::vector<std::uint8_t>& bytes);

}  // namespace cambrian
