#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs a small walking evolution on all local cores,
# then plots it. Usage: bash jobs/demo.sh [extra `cambrian evolve` options]
set -euo pipefail
cd "$(dirname "$0")/.."

bash jobs/setup/install-deps.sh

# build the release configuration
cmake --preset release > /dev/null
cmake --build --preset release

# Open MPI refuses root unless told; rank 0 sleeps while it waits, so one rank per core plus
# rank 0 is the right layout
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
workers=$(nproc)
out=runs/demo
mpirun -np $((workers + 1)) --oversubscribe build/release/src/app/cambrian evolve \
  --config jobs/experiments/demo.ini --out "$out" "$@"

# plots
if [ -f "$out/history.h5" ] && [ -f analysis/plot_fitness.py ]; then
  /usr/bin/python3 analysis/plot_fitness.py "$out/history.h5" --output "$out/fitness.png"
  echo "fitness plot: $out/fitness.png"
fi
echo "run files: $out/"
