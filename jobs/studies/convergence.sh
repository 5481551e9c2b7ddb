#!/usr/bin/env bash
# "Which physics settings are right?": the convergence study of docs/physics-and-tasks.md. The
# study's creatures (jobs/studies/convergence/creatures: random and evolved bodies, with where
# each came from) and the hand-written ones (jobs/creatures) are evaluated under the reference
# (the default's 1/240 s with 5 substeps and 100 iterations) and the physics variants named
# below, each 24 times with gravity nudged by a millionth, and analysis/convergence.py prints the
# table and draws the figure.
# usage: bash jobs/studies/convergence.sh [VARIANT ...]   (default: the variants of the docs table)
#   environment: CAMBRIAN (binary, default build/release/src/app/cambrian), OUT (default
#   runs/convergence), JOBS (evaluations at once, default: the number of cores), REFERENCE (the
#   variant the table compares with, default "reference, 240 Hz controller"; it must be run)
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=${CAMBRIAN:-build/release/src/app/cambrian}
out=${OUT:-runs/convergence}
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=("reference, 240 Hz controller"
  "reference, 240 Hz controller, x10" reference default "240Hz x1, 20 it, tol 1e-4"
  "240Hz x3, 20 it, tol 1e-4" "240Hz x4, 20 it, tol 1e-4" "240Hz x2, 50 it, tol 1e-5")
args=()
for variant in "${variants[@]}"; do
  args+=(--variant "$variant")
done
# an interrupted study continues: results already in $out/results.tsv are kept
/usr/bin/python3 analysis/convergence.py run --cambrian "$cambrian" \
  --creatures jobs/studies/convergence/creatures --creatures jobs/creatures \
  --out "$out" --perturbations 24 --jobs "${JOBS:-$(nproc)}" --quiet "${args[@]}"
MPLBACKEND=Agg /usr/bin/python3 analysis/convergence.py report --out "$out" \
  --figure "$out/convergence.png" --reference "${REFERENCE:-reference, 240 Hz controller}" --bootstrap 400
