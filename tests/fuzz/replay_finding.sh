#!/usr/bin/env bash
# Replays one fuzz finding (a crash, leak, timeout or out-of-memory input) once, alone, to see
# where it fails, and tells whether that lies in a known faulty library (library_fault.sh). The
# replay has a malloc limit, so that an input that allocates too much shows the stack of its
# large allocation. An out-of-memory input whose replay shows no such stack in LIBRARY is
# replayed once more without the ASan suppressions (tests/sanitizers/asan.supp): HDF5 1.10's
# H5HG_read copies overlapping ranges of up to a GiB out of a damaged global heap, touching pages
# past the RSS limit with little live heap, and only the unsuppressed overlap check shows it there
# (docs/fuzzing-and-sanitizers.md). Each replay's output is FINDING.replay.txt (and
# FINDING.replay-unsuppressed.txt).
# Exits 0: the fault lies in LIBRARY; 1: elsewhere; 2: the input does not fail when replayed.
# usage: replay_finding.sh BINARY FINDING LIBRARY
set -uo pipefail
binary=$1 finding=$2 library=$3
here=$(cd "$(dirname "$0")" && pwd)
replay() {
  "$binary" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 "$finding" > "$1" 2>&1
}
if replay "$finding.replay.txt"; then
  exit 2
fi
bash "$here/library_fault.sh" "$finding.replay.txt" "$library" > /dev/null && exit 0
grep -q "libFuzzer: out-of-memory" "$finding.replay.txt" || exit 1
unsuppressed=$(printf '%s' "${ASAN_OPTIONS:-}" | tr ':' '\n' | grep -v '^suppressions=' | paste -sd: -)
ASAN_OPTIONS=$unsuppressed replay "$finding.replay-unsuppressed.txt" && exit 1
bash "$here/library_fault.sh" "$finding.replay-unsuppressed.txt" "$library" > /dev/null
