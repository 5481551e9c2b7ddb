#!/usr/bin/env bash
# No motion from nothing, at the level of an evolution: a small walk evolution whose effectors
# all have zero strength must find no creature that travels — its best distance at most 1 % of
# the same evolution's with the default strength (the rest of the physics is equal).
# usage: zero_strength_evolution.sh CAMBRIAN WORKDIR
set -euo pipefail
cambrian=$1
work=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# the best fitness of the last generation of a run's generations.tsv
best() {
  awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "best") c = i; next } { b = $c }
              END { print b }' "$1/generations.tsv"
}

common=(evolve --task.name walk --task.evaluation_time 3 --evolution.population 20
        --evolution.generations 4 --seed 3 --quiet --fresh)
rm -rf "$work"
"$cambrian" "${common[@]}" --out "$work/normal" > /dev/null
"$cambrian" "${common[@]}" --physics.strength_per_area 0 --out "$work/zero" > /dev/null
normal=$(best "$work/normal")
zero=$(best "$work/zero")
echo "best distance in 3 s: default strength $normal m, zero strength $zero m"
awk -v n="$normal" -v z="$zero" 'BEGIN {
  if (n < 0.2) { print "FAIL: the default evolution found too little motion to compare with"; exit 1 }
  if (z > 0.01 * n) { printf "FAIL: zero strength reached %.3g %% of the default\n", 100 * z / n; exit 1 }
  printf "zero strength: %.3g %% of the default (limit 1 %%)\n", 100 * z / n }'
