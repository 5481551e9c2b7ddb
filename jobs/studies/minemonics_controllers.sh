#!/usr/bin/env bash
# Minemonics' sine vs chaotic control: jobs/experiments/minemonics/walk-sine.ini and
# walk-chaotic.ini (P = 100, G = 30, 20 s at 240 Hz, a controller on every joint and no network)
# over several seeds; the last generation's best of each run replayed bit for bit, and again at
# half the time step (a physics check: a gait that needs the step's error does not survive it);
# the fitness of every run in one figure (analysis/plot_fitness.py).
# usage: bash jobs/studies/minemonics_controllers.sh [--skip-runs] [SEED ...]   (default 1 2 3)
#   environment: CAMBRIAN (binary, default build/release/src/app/cambrian), OUT (default
#   runs/minemonics), WORKERS (default: the number of cores), EVOLVE_ARGS (more evolve options;
#   docs/minemonics.md's table was made with "--evolution.scheme generational
#   --physics.max_joint_speed 0", before the files took the reaper and the joint-speed discard),
#   KINDS (the files walk-KIND.ini compared, default "sine chaotic"; "sine hills" compares the
#   plane and the hill), TITLE (the figure's)
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
out=${OUT:-runs/minemonics}
workers=${WORKERS:-$(nproc)}
evolve_args=${EVOLVE_ARGS:-}
read -r -a kinds <<< "${KINDS:-sine chaotic}"
title=${TITLE:-Minemonics: sine vs chaotic joint controllers}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 MPLBACKEND=Agg

histories=()
for kind in "${kinds[@]}"; do
  for seed in "${seeds[@]}"; do
    dir=$out/$kind-$seed
    if ! $skip_runs; then
      mpirun --oversubscribe -np $((workers + 1)) "$cambrian" evolve $evolve_args \
        --config "jobs/experiments/minemonics/walk-$kind.ini" --seed "$seed" --out "$dir" --quiet
    fi
    # the best of the last generation: bit for bit, then at half the step
    "$cambrian" replay --history "$dir/history.h5" --best > "$dir/best.txt"
    "$cambrian" replay --history "$dir/history.h5" --best \
      --physics.time_step 0.0020833333333333333 > "$dir/best-half-step.txt"
    echo "$kind seed $seed: best $(grep -m1 '^fitness' "$dir/best.txt" | awk '{print $2}')," \
      "at half the step $(grep -m1 '^fitness' "$dir/best-half-step.txt" | awk '{print $3}')"
    histories+=("$dir/history.h5")
  done
done

/usr/bin/python3 analysis/plot_fitness.py "${histories[@]}" \
  --title "$title" --output "$out/${kinds[0]}_vs_${kinds[1]:-none}.png"
