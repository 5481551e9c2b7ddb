// cambrian: the one byte form of an Outcome, used by the evaluation result message and the
// checkpoint: every field, doubles as their bits.
#pragma once

#include "cambrian/outcome.hpp"

#include "core/bytes.hpp"

namespace cambrian {

/// Appends `outcome` (status, fitness, steps, wall time, body counts, message, measures).
void writeOutcome(ByteWriter& writer, const Outcome& outcome);
/// Reads what writeOutcome wrote; throws InputError naming the field on bad or truncated bytes.
Outcome readOutcome(ByteReader& reader);

}  // namespace cambrian
