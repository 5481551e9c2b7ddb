// cambrian: the [run] keys.
#include "run/run_settings.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "core/test_kill.hpp"

#include <cmath>

namespace cambrian {

void RunSettings::declareSettings(SettingsSchema& s) {
  RunSettings& r = *this;
  s.describeSection("run", "[run] this run");
  s.add("run.out", r.out_dir, "output directory (history.h5, individuals.tsv, generations.tsv)")
      .runOnly();
  s.add("run.quiet", r.quiet, "no progress lines, only the digest").runOnly();
  s.add("run.verbose", r.verbose, "timing details after each progress line").runOnly();
  s.add("run.progress", r.progress,
        "a live line within each generation (evaluations done / population, the generation's "
        "ETA), rewritten in place: auto (when standard output is a terminal) | live | plain "
        "(the generation lines only, as in a batch log)")
      .oneOf({"auto", "live", "plain"})
      .runOnly();
  s.add("run.checkpoint_every", r.checkpoint_every,
        "write DIR/checkpoint.h5 every this many generations (0 = no generation cadence; a "
        "checkpoint always follows the last generation and precedes a clean stop)")
      .require([&r] { return r.checkpoint_every >= 0; }, "must be >= 0")
      .runOnly();
  s.add("run.checkpoint_minutes", r.checkpoint_minutes,
        "... or when this many minutes passed since the last one, whichever comes first (0 = "
        "off)")
      .require([&r] { return r.checkpoint_minutes >= 0 && std::isfinite(r.checkpoint_minutes); },
               "must be >= 0")
      .runOnly();
  s.add("run.max_hours", r.max_hours,
        "stop cleanly (checkpoint, exit 0) before this many hours of wall time: no generation "
        "starts that the measured times say would not end in time (0 = no limit)")
      .require([&r] { return r.max_hours >= 0 && std::isfinite(r.max_hours); }, "must be >= 0")
      .runOnly();
  s.add("run.reuse_outcomes", r.reuse_outcomes,
        "a child whose genome is byte for byte a parent's or an earlier sibling's takes that "
        "outcome instead of being simulated again, for tasks whose outcome depends on nothing "
        "else (every task with bodies); the results are the same bits either way")
      .runOnly();
  s.add("run.lock_wait", r.lock_wait,
        "seconds to wait for the output directory's lock (DIR/run.lock) while another run holds "
        "it: a run killed a moment ago still lets go of it, and a cluster file system may keep "
        "a dead node's lock for its lease period; a live run on this host is refused after at "
        "most 10 s")
      .require([&r] { return r.lock_wait >= 0 && std::isfinite(r.lock_wait); }, "must be >= 0")
      .runOnly();
  s.add("run.arrival_order", r.arrival_order,
        "evolution.mode = steady_state: a history.h5 of this run's settings whose order of "
        "results taken in (its rows) and each child's bred_after this run follows, so that it "
        "repeats that run bit for bit at any rank count; past the recorded rows it goes on as "
        "results arrive (empty: as they arrive); with islands (islands.count > 1), the earlier "
        "run's directory, whose island_K/history.h5 island K follows")
      .runOnly();
  s.add("run.test_kill_at", r.test_kill_at,
        "testing: rank 0 SIGKILLs itself at POINT:GENERATION, POINT one of evaluation, history, "
        "checkpoint_write, checkpoint_rename, checkpoint_done")
      .runOnly();
  s.addCheck([&r] { setTestKillPoint(r.test_kill_at); });
}

}  // namespace cambrian
