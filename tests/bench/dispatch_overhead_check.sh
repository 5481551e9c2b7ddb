#!/usr/bin/env bash
# Smoke test of the short-creature overhead benchmark (jobs/bench/dispatch_overhead.sh quick), no
# timing assertions: a cambrian row per cost and genome (directed graphs, springy Snakes) with the
# evaluations of two generations of 300 (300 + 240; the steady state's 600), a finite overhead and
# a rank 0 CPU share; a row per installed peer and cost. Run by CTest (label bench).
# usage: dispatch_overhead_check.sh PATH/TO/cambrian SOURCE_DIR
set -euo pipefail
cambrian=$1 source=$2
fail() { echo "dispatch_overhead_check: FAIL: $*" >&2; exit 1; }

table=$(bash "$source/jobs/bench/dispatch_overhead.sh" "$cambrian" sleep quick) ||
  fail "the benchmark exited $?"
echo "$table"
grep -q '^work *cost (us) *system *evaluations *wall (s) *overhead (us)' <<< "$table" ||
  fail "no header"
for cost in 100 1000 10000; do
  for genome in "" _springy; do
    grep -Eq "^sleep +$cost +cambrian$genome +540 +[0-9.]+ +-?[0-9.]+ +-?[0-9.]+ +[0-9.]+$" \
      <<< "$table" || fail "no sound cambrian$genome row at $cost us"
    # the steady state: two generations of 300 results
    grep -Eq "^sleep +$cost +cambrian_steady$genome +600 +[0-9.]+ +-?[0-9.]+ +-?[0-9.]+ +[0-9.]+$" \
      <<< "$table" || fail "no sound cambrian_steady$genome row at $cost us"
  done
done
# every row has a number of evaluations and a wall time above zero
awk 'NR > 1 && !($4 > 0 && $5 > 0) { bad = 1 } END { exit bad }' <<< "$table" ||
  fail "a row without evaluations or wall time"
