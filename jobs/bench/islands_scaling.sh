#!/usr/bin/env bash
# The island design measured at many ranks on a small machine, beside the model: the synthetic
# task with a sleeping cost (task.synthetic_work = sleep, 10 ms fixed), so a worker uses no CPU
# while it "evaluates" and the framework itself is what is measured. One run per point
# RANKS:ISLANDS (islands of contiguous ranks, each with its breeding rank and a population of
# its own, trading every --interval generations along a ring). Per point: workers (ranks less
# the breeding ranks), the archipelago's generation time (the slowest island's time for
# generations 1.., per generation), efficiency = evaluations x cost / (workers x that time), the
# breeding ranks' largest CPU share, and analysis/scaling_model.py's archipelago time for the
# same point, calibrated on the first point's island 0 (with one worker it has no waits), with
# its error. Figures and their reading: docs/scaling.md.
# usage: [MODE=steady_state] jobs/bench/islands_scaling.sh [path/to/cambrian] [POINTS] [quick]
#   POINTS: space-separated RANKS:ISLANDS (default "2:1 16:1 16:2 32:2 32:4 64:4 128:8")
#   quick: two generations of 40 creatures per point (a smoke test; the figures mean little)
#   MODE=steady_state: islands of steady states (evolution.mode = steady_state; a generation is
#     P results taken in, none copied); the model's island time is then steady_time's, calibrated
#     on the first point run once more as a generational run (the calibration reads a
#     generational history)
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=$(realpath "${1:-build/release/src/app/cambrian}")
points=${2:-"2:1 16:1 16:2 32:2 32:4 64:4 128:8"}
quick=${3:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cost_us=10000 population=300 generations=6 interval=2
if [ "$quick" = quick ]; then cost_us=2000 population=40 generations=3 interval=1; fi
mode=${MODE:-generational}

# one archipelago: RANKS ISLANDS MODE OUT
archipelago() {
  mpirun -np "$1" --oversubscribe "$cambrian" evolve --config jobs/experiments/synthetic.ini \
    --task.synthetic_work sleep --task.synthetic_distribution fixed \
    --task.synthetic_cost_us "$cost_us" --evolution.population "$population" \
    --evolution.generations "$generations" --islands.count "$2" --evolution.mode "$3" \
    --islands.interval "$interval" --quiet --out "$4" > "$4.txt" ||
    { cat "$4.txt"; echo "islands_scaling: the run at $1:$2 ($3) failed" >&2; exit 1; }
}
for point in $points; do
  ranks=${point%%:*} islands=${point##*:}
  archipelago "$ranks" "$islands" "$mode" "$work/r${ranks}_i${islands}"
done
first=${points%% *}
archipelago "${first%%:*}" "${first##*:}" generational "$work/calibration"

# the table, with the model's time for each point
/usr/bin/python3 - "$work" "$cost_us" "$interval" "$mode" "$population" $points <<'EOF'
import csv
import os
import sys

import numpy as np

sys.path.insert(0, "analysis")
import scaling_model as sm  # noqa: E402

work, cost, interval, mode = sys.argv[1], float(sys.argv[2]) * 1e-6, int(sys.argv[3]), sys.argv[4]
population, points = int(sys.argv[5]), sys.argv[6:]


def island_dirs(run):
    inner = sorted(d for d in os.listdir(run) if d.startswith("island_"))
    return [os.path.join(run, d) for d in inner] or [run]


def generations(directory):
    with open(os.path.join(directory, "generations.tsv")) as handle:
        return list(csv.DictReader(handle, delimiter="\t"))


calibration = sm.calibrate(os.path.join(island_dirs(os.path.join(work, "calibration"))[0], "history.h5"))
print("# %s, %s islands" % (calibration.describe(), mode))
print("%6s %8s %8s %14s %11s %11s %12s %10s" % ("ranks", "islands", "workers", "generation s", "efficiency",
                                               "rank0 CPU %", "model s", "model err"))
rng = np.random.default_rng(1)
for point in points:
    ranks, islands = (int(x) for x in point.split(":"))
    run = os.path.join(work, "r%d_i%d" % (ranks, islands))
    rows = [generations(d) for d in island_dirs(run)]
    later = [[r for r in island if int(r["generation"]) >= 1] for island in rows]
    # the archipelago advances at its slowest island's pace (generation rows tile each run)
    seconds = max(sum(float(r["wall_seconds"]) for r in island) for island in later) / len(later[0])
    evaluations = sum(np.mean([int(r["evaluations"]) for r in island]) for island in later)
    workers = ranks - islands if ranks > islands else islands
    cpu = max(sum(float(r["rank0_cpu_seconds"]) for r in island) / sum(float(r["wall_seconds"]) for r in island)
              for island in later)
    # the model: each island's workers (the layout's larger blocks first, as island_layout)
    per_island = max(1, (ranks - islands) // islands)
    count = int(round(np.mean([int(r["evaluations"]) for r in later[0]])))
    if mode == "steady_state":
        times = [sm.steady_time(calibration.draw(8 * population, rng), per_island, population, calibration.latency,
                                calibration.serial, calibration.overhead) for _ in range(sm.ISLAND_SAMPLES)]
    else:
        times = [calibration.time(calibration.draw(count, rng), per_island) for _ in range(sm.ISLAND_SAMPLES)]
    model = sm.archipelago_time(times, islands, interval, "ring", rng=rng) if islands > 1 else float(np.mean(times))
    print("%6d %8d %8d %14.4f %10.1f%% %10.1f%% %12.4f %+9.1f%%" % (
        ranks, islands, workers, seconds, 100 * evaluations * cost / (workers * seconds), 100 * cpu, model,
        100 * (model / seconds - 1)))
EOF
