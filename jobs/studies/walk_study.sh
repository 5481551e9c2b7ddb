#!/usr/bin/env bash
# "Does evolution work?": the default walk experiment (jobs/experiments/walk.ini, P = 100,
# G = 30, 10 s) over several seeds, the first- and last-generation best walkers of each run
# replayed with their trajectories, and analysis/walk_study.py's table and figure.
# usage: bash jobs/studies/walk_study.sh [--skip-runs] [SEED ...]   (default seeds 1 2 3)
#   environment: CAMBRIAN (binary, default build/release/src/app/cambrian), OUT (default
#   runs/study), WORKERS (default: the number of cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
skip_runs=false
if [ "${1:-}" = "--skip-runs" ]; then
  skip_runs=true
  shift
fi
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
cambrian=${CAMBRIAN:-build/release/src/app/cambrian}
out=${OUT:-runs/study}
workers=${WORKERS:-$(nproc)}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 MPLBACKEND=Agg

# the runs (resumed if interrupted: the same command continues from the checkpoint)
runs=()
for seed in "${seeds[@]}"; do
  dir=$out/walk-s$seed
  if ! $skip_runs; then
    mpirun --oversubscribe -np $((workers + 1)) "$cambrian" evolve \
      --config jobs/experiments/walk.ini --seed "$seed" --out "$dir" --quiet
  fi
  # the first and last generation's best, replayed bit for bit with their trajectories
  last=$(/usr/bin/python3 -c "import sys; sys.path.insert(0, 'analysis'); import cambrian_history as ch
with ch.History('$dir/history.h5') as h: print(int(h.generations()['generation'].max()))")
  "$cambrian" replay --history "$dir/history.h5" --best --generation 0 --export "$dir/best-first.h5" > "$dir/best-first.txt"
  "$cambrian" replay --history "$dir/history.h5" --best --generation "$last" --export "$dir/best-last.h5" > "$dir/best-last.txt"
  runs+=(--run "seed $seed=$dir")
done

# the table and the figure
/usr/bin/python3 analysis/walk_study.py "${runs[@]}" --output "$out/walk_study.png"
