#!/usr/bin/env bash
# Runs one fuzz target for a bounded time: first every input of its corpus (the valid inputs and
# the regression inputs of crashes once found), then new mutations. Fails on any crash, sanitizer
# report, leak, input slower than 10 s or allocation past 2 GiB; the failing input is saved in
# WORK/artifacts/. New interesting inputs go to WORK/new/, never into the repository's corpus.
# KNOWN_HANG (optional) names a function of a library outside cambrian with a known endless loop
# (docs/fuzzing-and-sanitizers.md): a timeout whose stack shows it ends the run with a notice,
# not a failure; any other timeout fails.
# usage: fuzz_check.sh BINARY CORPUS WORK SECONDS [KNOWN_HANG]
set -euo pipefail
binary=$1 corpus=$2 work=$3 seconds=$4 known_hang=${5:-}
rm -rf "$work/new"
mkdir -p "$work/new" "$work/artifacts"
status=0
# libFuzzer owns SIGALRM (its per-input timeout): cambrian's own header bound stays off here;
# errors ASan reports inside libhdf5 on damaged files are the library's (asan.supp); a fixed
# seed, so that a CI run repeats the same inputs
export CAMBRIAN_HEADER_READ_SECONDS=0
here=$(cd "$(dirname "$0")" && pwd)
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}suppressions=$here/../sanitizers/asan.supp"
"$binary" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/new" "$corpus" 2>&1 | tee "$work/log" || status=$?
if [ "$status" -ne 0 ] && [ -n "$known_hang" ] && grep -q "ERROR: libFuzzer: timeout" "$work/log" &&
  grep -q " in $known_hang " "$work/log"; then
  echo "fuzz_check: a timeout inside $known_hang: the known library hang" \
    "(docs/fuzzing-and-sanitizers.md), not a cambrian failure; fuzzing stopped there"
  exit 0
fi
exit "$status"
