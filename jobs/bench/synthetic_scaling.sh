#!/usr/bin/env bash
# Strong scaling of the evolve framework on the synthetic task (10 ms per evaluation, P = 300):
# one worker (-np 2) against two workers (-np 3), rank 0's serial share and CPU time.
# usage: jobs/bench/synthetic_scaling.sh [path/to/cambrian] [generations]
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=${1:-build/src/app/cambrian}
generations=${2:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# one run per rank count; per-generation figures come from generations.tsv
for np in 2 3; do
  mpirun -np "$np" --oversubscribe "$cambrian" evolve --config jobs/experiments/synthetic.ini \
    --evolution.generations "$generations" --quiet --out "$work/np$np" > "$work/np$np.txt"
done

# mean generation wall time (generation 0 has no elites: all 300 evaluated), serial share
summary() {
  awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
              { wall += $col["wall_seconds"]; serial += $col["rank0_serial_seconds"];
                evals += $col["evaluations"]; n++ }
              END { printf "%.4f %.6f %d", wall / n, serial / wall, evals }' "$1/generations.tsv"
}
read -r wall2 share2 evals2 <<< "$(summary "$work/np2")"
read -r wall3 share3 evals3 <<< "$(summary "$work/np3")"
cpu2=$(awk '/^rank0_cpu_seconds/ { print $2 }' "$work/np2.txt")
cpu3=$(awk '/^rank0_cpu_seconds/ { print $2 }' "$work/np3.txt")
d2=$(awk '/^digest/ { print $2 }' "$work/np2.txt")
d3=$(awk '/^digest/ { print $2 }' "$work/np3.txt")
run2=$(awk '/^wall_seconds/ { print $2 }' "$work/np2.txt")
run3=$(awk '/^wall_seconds/ { print $2 }' "$work/np3.txt")

echo "synthetic task, 10 ms per evaluation, population 300, $generations generations"
printf "%-8s %-14s %-14s %-16s %-16s %s\n" ranks "gen wall (s)" "run wall (s)" "rank0 serial %" \
  "rank0 cpu (s)" digest
printf "%-8s %-14s %-14s %-16s %-16s %s\n" "-np 2" "$wall2" "$run2" \
  "$(awk -v s="$share2" 'BEGIN { printf "%.3f", 100 * s }')" "$cpu2" "$d2"
printf "%-8s %-14s %-14s %-16s %-16s %s\n" "-np 3" "$wall3" "$run3" \
  "$(awk -v s="$share3" 'BEGIN { printf "%.3f", 100 * s }')" "$cpu3" "$d3"
awk -v a="$wall2" -v b="$wall3" 'BEGIN { printf "speedup (1 -> 2 workers): %.2f  efficiency %.0f%%\n", a / b, 50 * a / b }'
[ "$d2" = "$d3" ] && echo "digests match" || { echo "DIGESTS DIFFER"; exit 1; }
