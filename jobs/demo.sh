#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs a small walking evolution on all local cores,
# then writes the fitness plot, the lineage of the best creature, an animation of it and the
# run's report (a web page with the creatures in a 3-D viewer), and prints where they are.
# usage: bash jobs/demo.sh [extra `cambrian evolve` options, e.g. --seed 2]
# environment (for tests): CAMBRIAN=binary skips the set-up and the build; DEMO_OUT=dir
set -euo pipefail
cd "$(dirname "$0")/.."

# set up and build the release configuration, unless a binary is given
if [ -z "${CAMBRIAN:-}" ]; then
  bash jobs/setup/install-deps.sh
  cmake --preset release > /dev/null
  cmake --build --preset release
fi
cambrian=${CAMBRIAN:-build/release/src/app/cambrian}

# Open MPI refuses root unless told; rank 0 sleeps while it waits, so one worker per core plus
# rank 0 is the right layout. --fresh: the demo starts over each time (a real run resumes).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
workers=$(nproc)
out=${DEMO_OUT:-runs/demo}
mpirun -np $((workers + 1)) --oversubscribe "$cambrian" evolve \
  --config jobs/experiments/demo.ini --out "$out" --fresh "$@"

# the fitness over generations and the lineage of the best creature
export MPLBACKEND=Agg
python=/usr/bin/python3
"$python" analysis/plot_fitness.py "$out/history.h5" --output "$out/fitness.png"
"$python" analysis/lineage.py "$out/history.h5" --output "$out/lineage.png" \
  --table "$out/lineage.tsv" > /dev/null

# the best creature, re-simulated bit for bit and animated
"$cambrian" replay --history "$out/history.h5" --best --export "$out/best.h5"
"$python" analysis/animate.py "$out/best.h5" --output "$out/best.gif" --max-frames 180

# the run's report: settings, fitness, lineage, operators, diversity, load, and the best of the
# first, middle and last generations in the browser viewer (one self-contained file)
"$python" analysis/report.py "$out" --cambrian "$cambrian" > /dev/null

echo
echo "run files:     $out/ (history.h5, checkpoint.h5, individuals.tsv, generations.tsv)"
echo "fitness plot:  $out/fitness.png"
echo "lineage:       $out/lineage.png, $out/lineage.tsv"
echo "best creature: $out/best.gif (trajectory $out/best.h5)"
echo "report:        $out/report.html (open it in a browser; the creatures play in it)"
