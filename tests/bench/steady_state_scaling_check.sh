#!/usr/bin/env bash
# Smoke test of the steady-state benchmark (jobs/bench/steady_state_scaling.sh quick at 2 and 3
# ranks): a row per design and rank count with its workers, a positive generation time and
# model time; no timing assertions. Run by CTest (label bench).
# usage: steady_state_scaling_check.sh PATH/TO/cambrian SOURCE_DIR
set -euo pipefail
cambrian=$1 source=$2
fail() { echo "steady_state_scaling_check: FAIL: $*" >&2; exit 1; }

table=$(bash "$source/jobs/bench/steady_state_scaling.sh" "$cambrian" "2 3" quick) ||
  fail "the benchmark exited $?"
echo "$table"
grep -q '^# calibration' <<< "$table" || fail "no calibration line"
grep -Eq '^design +ranks +workers +generation s +efficiency' <<< "$table" || fail "no header"
for design in generational steady_state; do
  for row in "2 1" "3 2"; do
    read -r r w <<< "$row"
    grep -Eq "^$design +$r +$w +[0-9.]+ +[0-9.]+% +-?[0-9]+ us +[0-9.]+% +[0-9.]+ +[-+][0-9.]+%$" \
      <<< "$table" || fail "no $design row for $r ranks, $w workers"
  done
done
awk '$2 ~ /^[0-9]+$/ && !($4 > 0 && $9 > 0) { bad = 1 } END { exit bad }' <<< "$table" ||
  fail "a row without a generation time or a model time"
echo "steady_state_scaling_check: OK"
