#!/usr/bin/env bash
# Peak resident memory of rank 0 and of the largest worker (the run summary's rank0_peak_rss_mb
# and worker_peak_rss_mb, getrusage), for populations of synthetic creatures (directed-graph
# genomes, no evaluation cost: rank 0's own holdings) and for a walk (a worker simulating in
# Bullet). 2 workers, 3 generations, the history and checkpoints written as in any run.
# Figures and their reading: docs/performance.md ("Memory").
# usage: jobs/bench/memory.sh [path/to/cambrian] [quick]
#   quick: populations 1,000 and 3,000 and a walk of 4 creatures (a smoke test)
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=$(realpath "${1:-build/release/src/app/cambrian}")
quick=${2:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
populations="1000 10000 100000"
[ "$quick" = quick ] && populations="1000 3000"

# one run of 3 ranks; prints "population rank0_MB per_creature_kB worker_MB wall_s"
measure() {
  local name=$1 population=$2
  shift 2
  mpiexec -n 3 --oversubscribe "$cambrian" evolve --out "$work/$name" --fresh --run.quiet true \
    --evolution.population "$population" "$@" > "$work/$name.txt"
  awk -v p="$population" -v name="$name" '
    $1 == "rank0_peak_rss_mb" { r = $2 } $1 == "worker_peak_rss_mb" { w = $2 }
    $1 == "wall_seconds" { t = $2 }
    END { per = name == "synthetic" ? sprintf("%.2f", r * 1000 / p) : "-"
          printf "%-10s %10d %10.1f %12s %10.1f %8.1f\n", name, p, r, per, w, t }' \
    "$work/$name.txt"
}

printf "%-10s %10s %10s %12s %10s %8s\n" run population "rank 0 MB" "kB/creature" "worker MB" \
  "wall s"
for population in $populations; do
  measure synthetic "$population" --task.name synthetic --task.synthetic_cost_us 0 \
    --evolution.generations 3
done
# a walk (jobs/experiments/walk.ini): what a worker simulating in Bullet holds
if [ "$quick" = quick ]; then
  measure walk 4 --config jobs/experiments/walk.ini --evolution.generations 1
else
  measure walk 20 --config jobs/experiments/walk.ini --evolution.generations 3
fi
