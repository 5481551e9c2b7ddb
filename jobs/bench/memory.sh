#!/usr/bin/env bash
# Peak resident memory of rank 0 and of the largest worker (the run summary's rank0_peak_rss_mb
# and worker_peak_rss_mb, getrusage), for populations of synthetic creatures (directed-graph
# genomes, no evaluation cost: rank 0's own holdings) and for a walk (a worker simulating in
# Bullet). 2 workers, 3 generations, the history and checkpoints written as in any run; and the
# same populations spread over 4 islands (the largest breeding rank's peak).
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

# one run of RANKS ranks (3: rank 0 and 2 workers); prints "name population rank0_MB
# per_creature_kB worker_MB wall_s". Islands: POPULATION summed over ISLANDS islands (each breeds
# population / ISLANDS), rank 0 the largest breeding rank, per creature of its own population
measure() {
  local name=$1 population=$2 ranks=$3 islands=$4
  shift 4
  mpiexec -n "$ranks" --oversubscribe "$cambrian" evolve --out "$work/$name" --fresh \
    --run.quiet true --evolution.population $((population / islands)) --islands.count "$islands" \
    "$@" > "$work/$name.txt"
  awk -v p="$population" -v k="$islands" -v name="$name" '
    $1 == "rank0_peak_rss_mb" { r = $2 } $1 == "worker_peak_rss_mb" { w = $2 }
    $1 == "wall_seconds" { t = $2 }
    END { per = name == "walk" ? "-" : sprintf("%.2f", r * 1000 * k / p)
          printf "%-10s %10d %10.1f %12s %10.1f %8.1f\n", name, p, r, per, w, t }' \
    "$work/$name.txt"
}

printf "%-10s %10s %10s %12s %10s %8s\n" run population "rank 0 MB" "kB/creature" "worker MB" \
  "wall s"
for population in $populations; do
  measure synthetic "$population" 3 1 --task.name synthetic --task.synthetic_cost_us 0 \
    --evolution.generations 3
done
# the same populations as 4 islands (8 ranks: a breeding rank and a worker each), trading every
# generation: what each breeding rank holds when the population is spread over islands
for population in $populations; do
  measure islands "$population" 8 4 --task.name synthetic --task.synthetic_cost_us 0 \
    --evolution.generations 3 --islands.interval 1
done
# a walk (jobs/experiments/walk.ini): what a worker simulating in Bullet holds
if [ "$quick" = quick ]; then
  measure walk 4 3 1 --config jobs/experiments/walk.ini --evolution.generations 1
else
  measure walk 20 3 1 --config jobs/experiments/walk.ini --evolution.generations 3
fi
