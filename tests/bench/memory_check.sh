#!/usr/bin/env bash
# Smoke test of the memory benchmark (jobs/bench/memory.sh quick), no size assertions beyond
# sense: a row per run (one population, 4 islands) with rank 0's and the largest worker's peak
# memory above zero, rank 0 holding more for 3,000 creatures than for 1,000, a walk row. Run by
# CTest (label bench).
# usage: memory_check.sh PATH/TO/cambrian SOURCE_DIR
set -euo pipefail
cambrian=$1 source=$2
fail() { echo "memory_check: FAIL: $*" >&2; exit 1; }

table=$(bash "$source/jobs/bench/memory.sh" "$cambrian" quick) || fail "the benchmark exited $?"
echo "$table"
grep -q '^run *population *rank 0 MB *kB/creature *worker MB *wall s$' <<< "$table" ||
  fail "no header"
for run in "synthetic +1000" "synthetic +3000" "islands +1000" "islands +3000"; do
  grep -Eq "^$run +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+$" <<< "$table" || fail "no row for $run"
done
grep -Eq "^walk +4 +[0-9.]+ +- +[0-9.]+ +[0-9.]+$" <<< "$table" || fail "no row for the walk"
awk 'NR > 1 && !($3 > 0 && $5 > 0) { bad = 1 } END { exit bad }' <<< "$table" ||
  fail "a row without rank 0's or a worker's peak"
awk '$1 == "synthetic" { r[$2] = $3 } END { exit !(r[3000] > r[1000]) }' <<< "$table" ||
  fail "rank 0 holds no more for 3,000 creatures than for 1,000"
