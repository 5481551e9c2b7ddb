#!/usr/bin/env bash
# Smoke test of the islands benchmark (jobs/bench/islands_scaling.sh quick at 2 to 4 ranks): a
# row per point with its workers, a positive generation time, efficiency and model time; no
# timing assertions. Run by CTest (label bench).
# usage: islands_scaling_check.sh PATH/TO/cambrian SOURCE_DIR
set -euo pipefail
cambrian=$1 source=$2
fail() { echo "islands_scaling_check: FAIL: $*" >&2; exit 1; }

table=$(bash "$source/jobs/bench/islands_scaling.sh" "$cambrian" "2:1 3:1 4:2" quick) ||
  fail "the benchmark exited $?"
echo "$table"
grep -q '^# calibration' <<< "$table" || fail "no calibration line"
grep -Eq '^ *ranks +islands +workers +generation s +efficiency' <<< "$table" || fail "no header"
for row in "2 1 1" "3 1 2" "4 2 2"; do
  read -r r i w <<< "$row"
  grep -Eq "^ +$r +$i +$w +[0-9.]+ +[0-9.]+% +[0-9.]+% +[0-9.]+ +[-+][0-9.]+%$" <<< "$table" ||
    fail "no row for $r ranks, $i islands, $w workers"
done
awk '$1 ~ /^[0-9]+$/ && !($4 > 0 && $7 > 0) { bad = 1 } END { exit bad }' <<< "$table" ||
  fail "a row without a generation time or a model time"
echo "islands_scaling_check: OK"
