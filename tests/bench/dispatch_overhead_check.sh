#!/usr/bin/env bash
# Smoke test of the short-creature overhead benchmark (jobs/bench/dispatch_overhead.sh quick), no
# timing assertions: a cambrian row per cost and genome (directed graphs, springy Snakes) with the
# evaluations of three generations of 300 (300 + 240 + 240; the steady state's 900), a finite
# overhead, a rank 0 CPU share and a mid-run overhead (the middle generation's); a row per
# installed peer and cost. Run by CTest (label bench).
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
    number='-?[0-9.]+'
    grep -Eq "^sleep +$cost +cambrian$genome +780 +[0-9.]+ +$number +$number +[0-9.]+ +$number$" \
      <<< "$table" || fail "no sound cambrian$genome row at $cost us"
    # the steady state: three generations of 300 results
    grep -Eq \
      "^sleep +$cost +cambrian_steady$genome +900 +[0-9.]+ +$number +$number +[0-9.]+ +$number$" \
      <<< "$table" || fail "no sound cambrian_steady$genome row at $cost us"
  done
done
# every row has a number of evaluations and a wall time above zero
awk 'NR > 1 && !($4 > 0 && $5 > 0) { bad = 1 } END { exit bad }' <<< "$table" ||
  fail "a row without evaluations or wall time"
