#!/usr/bin/env bash
# Smoke test of the step-cost benchmark (bench/step_cost.cpp), no timing assertions: a short run
# at 2 and 5 parts prints the plain table and a TSV row per chain and loop with a positive time,
# ratios, a first part that moved, solver rows for the bare loops and status ok, also with a
# physics override; bad arguments exit 2 naming the argument. Run by CTest (label bench).
# usage: step_cost_check.sh PATH/TO/cambrian_step_cost
set -euo pipefail

if [ $# -ne 1 ]; then
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
bench=$1
fail() { echo "step_cost_check: FAIL: $*" >&2; exit 1; }
short=(--parts 2,5 --seconds 0.2 --rounds 2 --warmup 0.1)

# the plain table: a summary row per chain, a detail row per chain and loop
table=$("$bench" "${short[@]}") || fail "the plain run exited $?"
echo "$table"
grep -q '^parts *bare us/step *matched us/step *cambrian us/step *cambrian/bare' <<< "$table" ||
  fail "no summary header"
for parts in 2 5; do
  grep -Eq "^$parts +[0-9.]+ \([0-9.]+-[0-9.]+\) +[0-9.]+ .* [0-9.]+ +[0-9.]+$" <<< "$table" ||
    fail "no summary row for $parts parts"
  for loop in bare matched cambrian; do
    grep -Eq "^$parts +$loop .* ok$" <<< "$table" || fail "no sound detail row: $parts $loop"
  done
done

# the TSV, default physics and one override: every row sane
check_tsv() {
  local tsv=$1 label=$2
  awk -F'\t' -v label="$label" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    {
      rows++
      where = label ": " $col["parts"] " parts, " $col["loop"]
      if ($col["us_per_step"] <= 0) { print where ": us_per_step " $col["us_per_step"]; bad = 1 }
      if ($col["ratio_to_bare"] <= 0) { print where ": ratio_to_bare " $col["ratio_to_bare"]; bad = 1 }
      # moved: the first part travelled, or at least moved at some speed
      if ($col["distance_m"] < 0.001 && $col["max_speed_m_s"] < 0.05) {
        print where ": did not move (distance " $col["distance_m"] " m, max speed " \
              $col["max_speed_m_s"] " m/s)"; bad = 1
      }
      if ($col["max_speed_m_s"] > 50) { print where ": exploded"; bad = 1 }
      if ($col["loop"] != "cambrian" && $col["joint_rows"] <= 0) {
        print where ": no solver rows counted"; bad = 1
      }
      if ($col["status"] != "ok") { print where ": status " $col["status"]; bad = 1 }
      seen[$col["parts"] " " $col["loop"]] = 1
    }
    END {
      for (p = 2; p <= 5; p += 3)
        if (!((p " bare") in seen && (p " matched") in seen && (p " cambrian") in seen)) {
          print label ": a loop of " p " parts is missing"; bad = 1
        }
      if (rows != 6) { print label ": " rows " rows, expected 6"; bad = 1 }
      exit bad
    }' <<< "$tsv" || fail "$label TSV"
}
tsv=$("$bench" "${short[@]}" --tsv) || fail "the TSV run exited $?"
echo "$tsv"
check_tsv "$tsv" defaults
tsv=$("$bench" "${short[@]}" --tsv physics.substeps=1 physics.solver_iterations=10) ||
  fail "the override run exited $?"
check_tsv "$tsv" "substeps=1 solver_iterations=10"

# bad arguments: exit 2, the message names the argument and its value
expect_usage() {
  local needle=$1
  shift
  local rc=0 err
  err=$("$bench" "$@" 2>&1 > /dev/null) || rc=$?
  [ "$rc" = 2 ] || fail "'$*' exited $rc, expected 2"
  grep -qF -- "$needle" <<< "$err" || fail "'$*': message does not name '$needle': $err"
}
expect_usage "--parts '1'" --parts 1
expect_usage "--parts 'x'" --parts 2,x
expect_usage "--rounds '0'" --rounds 0
expect_usage "--seconds 'soon'" --seconds soon
expect_usage "--loops 'bare,fast'" --loops bare,fast
expect_usage "physics.substeps = 0" physics.substeps=0
expect_usage "physics.nonsense" physics.nonsense=1
expect_usage "task.evaluation_time" task.evaluation_time=1
expect_usage "--frobnicate" --frobnicate
expect_usage "--parts" --parts
"$bench" --help | grep -q '^usage: cambrian_step_cost' || fail "--help printed no usage"
echo "step_cost_check: ok"
