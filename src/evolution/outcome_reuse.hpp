// cambrian: outcomes reused for copies. When a task's outcome is a pure function of the genome
// and the settings (Task::repeatable), a child whose genome is byte for byte a parent's or an
// earlier sibling's would be simulated to the same bits: it takes that outcome instead.
#pragma once

#include "evolution/population.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace cambrian {

/// What reuseKnownOutcomes found in a generation.
struct OutcomeReuse {
  std::size_t from_parents = 0;  ///< copies that took a parent's outcome
  /// (copy, original) indices of copies of an earlier sibling that is still to be evaluated
  std::vector<std::pair<std::size_t, std::size_t>> siblings;
};

/// Before a generation is evaluated: every unevaluated individual whose genome equals that of
/// an evaluated individual of `parents` (may be null) takes its outcome, unless that outcome is
/// a timeout (a wall-clock bound, not a property of the genome); one that equals an earlier
/// unevaluated sibling is marked evaluated, to take the sibling's outcome after the evaluation
/// (copySiblingOutcomes). Copies keep eval_seconds 0 and worker_rank -1, as elites do.
OutcomeReuse reuseKnownOutcomes(Population& generation, const Population* parents);

/// After the evaluation: each copy of a sibling takes the sibling's outcome.
void copySiblingOutcomes(Population& generation, const OutcomeReuse& reuse);

}  // namespace cambrian
