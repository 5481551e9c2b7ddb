#!/usr/bin/env bash
# Per-step cost of each environment kind against the plane: the same creatures (the walker, the
# snake and 20 random genomes) simulated on the plane and on each other kind, interleaved, for
# several rounds; prints steps per second per kind and the ratio of each to the plane.
# usage: bash jobs/bench/environment_cost.sh [path/to/cambrian] [ROUNDS] [-- SETTINGS ...]
#   SETTINGS   --key value pairs given to every run (e.g. --environment.hill_spacing 0.25)
# Timings on shared machines are noisy: compare the ratios of one run (docs/performance.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=${1:-build/release/src/app/cambrian}
rounds=${2:-3}
shift $(( $# > 2 ? 2 : $# ))
[ "${1:-}" = -- ] && shift
settings=("$@")
kinds=(plane hills)

creatures=(--genome jobs/creatures/walker4.genome --genome jobs/creatures/snake.genome)
for seed in $(seq 1 20); do creatures+=(--random "--seed $seed"); done

declare -A steps seconds
for kind in "${kinds[@]}"; do steps[$kind]=0; seconds[$kind]=0; done
for round in $(seq 1 "$rounds"); do
  for ((i = 0; i < ${#creatures[@]}; i += 2)); do
    for kind in "${kinds[@]}"; do
      # shellcheck disable=SC2086
      out=$("$cambrian" simulate ${creatures[i]} ${creatures[i + 1]} --environment.name "$kind" \
        ${settings[@]+"${settings[@]}"} 2>&1) || true
      n=$(awk '$1 == "steps" {print $2}' <<< "$out")
      t=$(awk '$1 == "wall" && $2 == "time" {print $3}' <<< "$out")
      [ -n "$n" ] && [ -n "$t" ] || continue
      steps[$kind]=$(( ${steps[$kind]} + n ))
      seconds[$kind]=$(awk -v a="${seconds[$kind]}" -v b="$t" 'BEGIN {printf "%.6f", a + b}')
    done
  done
done
printf '%-8s %12s %10s %12s %8s\n' kind steps seconds steps/s "cost/plane"
base=$(awk -v s="${steps[plane]}" -v t="${seconds[plane]}" 'BEGIN {print t / s}')
for kind in "${kinds[@]}"; do
  awk -v k="$kind" -v s="${steps[$kind]}" -v t="${seconds[$kind]}" -v b="$base" \
    'BEGIN {printf "%-8s %12d %10.2f %12.0f %8.2f\n", k, s, t, s / t, (t / s) / b}'
done
