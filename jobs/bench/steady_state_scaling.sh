#!/usr/bin/env bash
# The generational and the steady-state design side by side at many ranks on a small machine,
# beside the model: the synthetic task of jobs/experiments/synthetic.ini (10 ms, uniform spread of
# coefficient of variation 0.5) with a sleeping cost (task.synthetic_work = sleep), so a worker
# uses no CPU while it "evaluates" and the framework itself is what is measured. One run per
# design and rank count, population 300. Per run: workers, time per generation (generations 1..;
# a steady state's generation is 300 results taken in), efficiency = evaluations x mean cost /
# (workers x that time), overhead per evaluation = that time x workers / evaluations - mean cost,
# rank 0's CPU share, and analysis/scaling_model.py's time for the same point (generation_time
# or steady_time), calibrated on the first rank count's generational run, with its error.
# Figures and their reading: docs/scaling.md.
# usage: [PLOT=FILE.png] jobs/bench/steady_state_scaling.sh [path/to/cambrian] [RANKS] [quick]
#   RANKS: space-separated rank counts (default "2 16 32 64")
#   quick: three generations of 40 creatures of 2 ms (a smoke test; the figures mean little)
#   PLOT: also draw each design's measured efficiency (markers) and the model's (lines) there
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=$(realpath "${1:-build/release/src/app/cambrian}")
ranks_list=${2:-"2 16 32 64"}
quick=${3:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cost_us=10000 population=300 generations=6
if [ "$quick" = quick ]; then cost_us=2000 population=40 generations=3; fi

for ranks in $ranks_list; do
  for mode in generational steady_state; do
    out="$work/${mode}_$ranks"
    mpirun -np "$ranks" --oversubscribe "$cambrian" evolve --config jobs/experiments/synthetic.ini \
      --task.synthetic_work sleep --task.synthetic_cost_us "$cost_us" \
      --evolution.population "$population" --evolution.generations "$generations" \
      --evolution.mode "$mode" --quiet --out "$out" > "$out.txt" ||
      { cat "$out.txt"; echo "steady_state_scaling: the $mode run at $ranks ranks failed" >&2; exit 1; }
  done
done

# the table, with the model's time for each run
PLOT=${PLOT:-} /usr/bin/python3 - "$work" "$cost_us" "$population" $ranks_list <<'PY'
import csv
import os
import sys

import numpy as np

sys.path.insert(0, "analysis")
import scaling_model as sm  # noqa: E402

work, cost, population, ranks_list = sys.argv[1], float(sys.argv[2]) * 1e-6, int(sys.argv[3]), sys.argv[4:]


def generations(directory):
    with open(os.path.join(directory, "generations.tsv")) as handle:
        return [r for r in csv.DictReader(handle, delimiter="\t") if int(r["generation"]) >= 1]


calibration = sm.calibrate(os.path.join(work, "generational_%s" % ranks_list[0], "history.h5"))
print("# %s" % calibration.describe())
print("%-13s %6s %8s %13s %11s %14s %12s %10s %10s" % (
    "design", "ranks", "workers", "generation s", "efficiency", "overhead/eval", "rank0 CPU %", "model s",
    "model err"))
rng = np.random.default_rng(1)
points = {"generational": [], "steady_state": []}  # (workers, measured, modelled efficiency)
for ranks in (int(r) for r in ranks_list):
    workers = max(1, ranks - 1)
    for mode in ("generational", "steady_state"):
        rows = generations(os.path.join(work, "%s_%d" % (mode, ranks)))
        seconds = np.mean([float(r["wall_seconds"]) for r in rows])
        evaluations = np.mean([int(r["evaluations"]) for r in rows])
        cpu = sum(float(r["rank0_cpu_seconds"]) for r in rows) / sum(float(r["wall_seconds"]) for r in rows)
        if mode == "generational":
            count = int(round(evaluations))
            model = float(np.mean([calibration.time(calibration.draw(count, rng), workers) for _ in range(5)]))
        else:
            model = float(np.mean([sm.steady_time(calibration.draw(8 * population, rng), workers, population,
                                                  calibration.latency, calibration.serial, calibration.overhead)
                                   for _ in range(3)]))
        efficiency = evaluations * cost / (workers * seconds)
        points[mode].append((workers, efficiency, evaluations * cost / (workers * model)))
        print("%-13s %6d %8d %13.4f %10.1f%% %11.0f us %11.1f%% %10.4f %+9.1f%%" % (
            mode, ranks, workers, seconds, 100 * efficiency, 1e6 * (seconds * workers / evaluations - cost),
            100 * cpu, model, 100 * (model / seconds - 1)))

if os.environ.get("PLOT"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(6.4, 4.2))
    for (mode, rows), colour in zip(points.items(), ("tab:blue", "tab:orange")):
        workers, measured, modelled = zip(*rows)
        label = mode.replace("_", " ")
        axes.plot(workers, modelled, color=colour, label=label + ", model")
        axes.scatter(workers, measured, color=colour, marker="o", zorder=3, label=label + ", measured")
    axes.set_xscale("log", base=2)
    axes.set_ylim(0, 1.05)
    axes.set_xlabel("workers")
    axes.set_ylabel("efficiency")
    axes.set_title("P = %d, %g ms sleeping cost (uniform, cv 0.5)" % (population, cost * 1e3))
    axes.grid(alpha=0.3, which="both")
    axes.legend(fontsize="small")
    figure.tight_layout()
    figure.savefig(os.environ["PLOT"], dpi=110)
    print("# plot %s" % os.environ["PLOT"])
PY
