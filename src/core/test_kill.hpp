// cambrian: a testing aid (setting run.test_kill_at) that makes rank 0 kill itself with SIGKILL
// at a named point of a named generation, so tests can prove that a run killed anywhere resumes
// exactly. Points: "evaluation" (half of the generation's results are in, and the previous
// generation's history rows and checkpoint are written), "history" (its rows
// are in history.h5, no checkpoint yet), "checkpoint_write" (checkpoint.h5.tmp written but not
// closed), "checkpoint_rename" (temporary file complete, not yet renamed into place),
// "checkpoint_done" (checkpoint in place, its time not yet in the history).
#pragma once

#include <cstdint>
#include <string>

namespace cambrian {

/// Arms the kill point "POINT:GENERATION" ("" disarms). Throws ConfigError naming
/// run.test_kill_at and the value when it is malformed or names an unknown point.
void setTestKillPoint(const std::string& spec);

/// Whether the armed point is `point` at `generation` (so the caller can first get to where the
/// point is defined to be).
bool testKillArmed(const std::string& point, std::uint64_t generation);

/// Raises SIGKILL when the armed point is `point` at `generation`; otherwise returns.
void testKillPoint(const std::string& point, std::uint64_t generation);

}  // namespace cambrian
