#!/usr/bin/env bash
# Runs one fuzz target for a bounded time: first every input of its corpus (the valid inputs and
# the regression inputs of crashes once found), then new mutations. Fails on any crash, sanitizer
# report, leak, input slower than 10 s or allocation past 2 GiB; the failing input is saved in
# WORK/artifacts/. New interesting inputs go to WORK/new/, never into the repository's corpus.
# KNOWN_FAULTY_LIBRARY (optional) names a library outside cambrian with known faults on damaged
# input (libhdf5: docs/fuzzing-and-sanitizers.md): a timeout or crash whose innermost frame
# outside the C library and the sanitizer and fuzzer runtime lies in it ends the run with a
# notice, not a failure (cambrian's readers meet those faults in a child process), and so does an
# out-of-memory whose input, replayed alone, fails in it (replay_finding.sh); any other timeout,
# crash or out-of-memory fails.
# usage: fuzz_check.sh BINARY CORPUS WORK SECONDS [KNOWN_FAULTY_LIBRARY]
set -euo pipefail
binary=$1 corpus=$2 work=$3 seconds=$4 known_library=${5:-}
rm -rf "$work/new"
mkdir -p "$work/new" "$work/artifacts"
status=0
# the readers' child process stays off: the fuzzer looks for faults in the reading code itself;
# errors ASan reports inside libhdf5 on damaged files are the library's (asan.supp); a fixed
# seed, so that a CI run repeats the same inputs
export CAMBRIAN_READ_SECONDS=0
here=$(cd "$(dirname "$0")" && pwd)
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}suppressions=$here/../sanitizers/asan.supp"
"$binary" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/new" "$corpus" 2>&1 | tee "$work/log" || status=$?
[ "$status" -ne 0 ] && [ -n "$known_library" ] || exit "$status"
kind=$(grep -o -m1 -E "ERROR: [A-Za-z]+: [A-Za-z-]+" "$work/log" || true)
if innermost=$(bash "$here/library_fault.sh" "$work/log" "$known_library"); then
  echo "fuzz_check: $kind inside $known_library (innermost frame: $innermost)"
# an out-of-memory report has no stack of its cause: its input, replayed alone, shows where
elif grep -q "libFuzzer: out-of-memory" "$work/log" &&
  oom=$(sed -n 's/^Test unit written to \(.*oom-.*\)$/\1/p' "$work/log" | tail -n 1) &&
  [ -n "$oom" ] &&
  bash "$here/replay_finding.sh" "$binary" "$oom" "$known_library"; then
  echo "fuzz_check: $kind; its input $oom, replayed alone, fails inside $known_library" \
    "($oom.replay*.txt)"
else
  exit "$status"
fi
echo "fuzz_check: a known fault of that library on damaged input" \
  "(docs/fuzzing-and-sanitizers.md), not a cambrian failure; fuzzing stopped there"
exit 0
