#!/usr/bin/env bash
# The framework's overhead per evaluation for short creatures, cambrian (generational, and steady
# state: `cambrian_steady`) beside its peers: 300 synthetic creatures of a fixed cost (100 us,
# 1 ms, 10 ms), 2 workers, the cost spent spinning or asleep. Overhead per evaluation = wall x
# workers / evaluations - cost (the whole loop: breeding, dispatch, history); for cambrian also
# beyond the evaluations' own measured time (wall x workers - their busy time, per evaluation:
# what a sleep's wake-up latency does not count in) and over the middle generations alone
# ("mid-run": the first and the last carry the run's one-off file costs). Peers, where their
# Debian packages are installed: DEAP with multiprocessing.Pool and with mpi4py.futures
# (python3-deap, python3-mpi4py), pagmo2's thread batch evaluator (libpagmo-dev). Figures and
# their reading: docs/performance.md. cambrian's creatures are directed-graph genomes of about
# 5 KB (rows `cambrian`, `cambrian_steady`) and springy Snakes, 6 muscles of 4 numbers each, as
# small as the peers' 20 floats (rows `cambrian_springy`, `cambrian_steady_springy`).
# usage: [GENOMES="graph springy"] jobs/bench/dispatch_overhead.sh [path/to/cambrian]
#          [spin|sleep|both] [quick]
#   quick: three generations per cost (a smoke test; the figures mean little)
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=$(realpath "${1:-build/release/src/app/cambrian}")
works=${2:-both}
quick=${3:-}
[ "$works" = both ] && works="spin sleep"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
workers=2
python=/usr/bin/python3
genomes=${GENOMES:-graph springy}
# the springy Snake's settings (its operators: no grafting)
springy=(--genome.encoding springy --springy.organism jobs/creatures/springy/snake.organism
  --evolution.graft_fraction 0 --evolution.crossover_fraction 0.5
  --evolution.mutation_fraction 0.5)

# generations per cost: a few seconds of work each
generations() {
  [ "$quick" = quick ] && { echo 3; return; }
  case $1 in 100) echo 60 ;; 1000) echo 20 ;; *) echo 10 ;; esac
}

# "overhead_us" from evaluations, wall seconds, workers, cost
overhead() { awk -v e="$1" -v w="$2" -v n="$3" -v c="$4" 'BEGIN { printf "%.1f", w * n / e * 1e6 - c }'; }

# the peers that are installed
peers=()
if $python -c 'import deap' 2> /dev/null; then
  peers+=(deap_pool)
  $python -c 'import mpi4py' 2> /dev/null && peers+=(deap_mpi4py)
fi
if [ -f /usr/include/pagmo/batch_evaluators/thread_bfe.hpp ] &&
  g++ -O2 -std=c++17 jobs/bench/peers/pagmo_overhead.cpp -o "$work/pagmo_overhead" -lpagmo -ltbb \
    -lboost_serialization 2> "$work/pagmo_build.txt"; then
  peers+=(pagmo_thread_bfe)
fi

printf "%-6s %-9s %-23s %11s %9s %13s %17s %13s %14s\n" work "cost (us)" system evaluations \
  "wall (s)" "overhead (us)" "beyond eval (us)" "rank 0 CPU %" "mid-run (us)"
for spend in $works; do
  for cost in 100 1000 10000; do
    g=$(generations "$cost")
    # cambrian, generational and steady state: the generations' own times (startup and the
    # final tables left out, as for peers)
    for genome in $genomes; do
      for mode in generational steady_state; do
        system=cambrian
        [ "$mode" = steady_state ] && system=cambrian_steady
        extra=()
        [ "$genome" = springy ] && system=${system}_springy extra=("${springy[@]}")
        out="$work/$system-$spend-$cost"
        mpirun -np $((workers + 1)) --oversubscribe "$cambrian" evolve \
          --config jobs/experiments/synthetic.ini --task.synthetic_distribution fixed \
          --task.synthetic_cost_us "$cost" --task.synthetic_work "$spend" \
          --evolution.generations "$g" --evolution.mode "$mode" --quiet --out "$out" \
          ${extra[@]+"${extra[@]}"} > "$out.txt"
        # all generations, and the middle ones alone (the first and the last carry the run's
        # one-off costs: creating the files, the final history rows and checkpoint)
        read -r evals wall cpu busy mid_evals mid_wall <<< "$(awk -F'\t' -v last=$((g - 1)) '
          NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
          { e += $col["evaluations"]; w += $col["wall_seconds"]; c += $col["rank0_cpu_seconds"]
            b += $col["worker_busy_seconds"]
            if ($col["generation"] > 0 && $col["generation"] < last) {
              me += $col["evaluations"]; mw += $col["wall_seconds"] } }
          END { printf "%d %.6f %.6f %.6f %d %.6f", e, w, c, b, me, mw }' "$out/generations.tsv")"
        middle=-
        [ "$mid_evals" -gt 0 ] && middle=$(overhead "$mid_evals" "$mid_wall" $workers "$cost")
        printf "%-6s %-9s %-23s %11s %9.3f %13s %17s %13.1f %14s\n" "$spend" "$cost" "$system" \
          "$evals" "$wall" "$(overhead "$evals" "$wall" $workers "$cost")" \
          "$(awk -v e="$evals" -v w="$wall" -v b="$busy" -v n=$workers 'BEGIN { printf "%.1f", (w * n - b) / e * 1e6 }')" \
          "$(awk -v c="$cpu" -v w="$wall" 'BEGIN { print 100 * c / w }')" "$middle"
      done
    done
    for peer in "${peers[@]}"; do
      case $peer in
        deap_pool) line=$($python jobs/bench/peers/deap_overhead.py --map pool --workers $workers \
          --cost-us "$cost" --work "$spend" --generations "$g") ;;
        deap_mpi4py) line=$(mpirun -np $((workers + 1)) --oversubscribe $python -m mpi4py.futures \
          jobs/bench/peers/deap_overhead.py --map mpi --workers $workers --cost-us "$cost" \
          --work "$spend" --generations "$g") ;;
        pagmo_thread_bfe) line=$("$work/pagmo_overhead" "$cost" "$spend" 300 "$g") ;;
      esac
      read -r _ evals _ wall _ threads <<< "$line"
      printf "%-6s %-9s %-23s %11s %9.3f %13s %17s %13s %14s\n" "$spend" "$cost" "$peer" "$evals" \
        "$wall" "$(overhead "$evals" "$wall" "$threads" "$cost")" "-" "-" "-"
    done
  done
done
