#!/usr/bin/env python3
"""Does evolution work? Compare the best walker of the first and of the last generation over
several runs (seeds) of the walk experiment.

For each run (a history.h5 and, optionally, the trajectories of its first- and last-generation
best creatures exported by `cambrian replay --export`), the script reports the distance and the
distance in body lengths, and from a trajectory the *steadiness* of the motion: the share of the
measured seconds in which the centre of mass moved forward (in the direction of the net
displacement) by at least 10 % of the mean speed. A creature that falls over makes its distance
in one or two seconds (low steadiness); a walker makes it across the whole measured phase.

    walk_study.py --run s1=runs/study/walk-s1 --run s2=runs/study/walk-s2 --output study.png

Each run directory holds history.h5 and, when present, best-first.h5 and best-last.h5
(jobs/studies/walk_study.sh writes them). Prints a Markdown table; exit codes 0 ok, 2 usage,
4 bad input file.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cambrian_history as ch  # noqa: E402
from animate import TrajectoryError, load_trajectory  # noqa: E402

MEASURE_PHASE = 3  # EvalPhase::measure


def per_second_progress(trajectory):
    """Forward progress of the centre of mass in each whole second of the measured phase, m,
    along the direction of the net horizontal displacement over that phase."""
    measured = trajectory["phase"] == MEASURE_PHASE
    time = trajectory["time"][measured]
    com = trajectory["center_of_mass"][measured][:, :2]
    if len(time) < 2:
        return np.zeros(0)
    # the direction of travel over the whole phase
    net = com[-1] - com[0]
    length = np.linalg.norm(net)
    direction = net / length if length > 0 else np.array([1.0, 0.0])
    # positions sampled at whole seconds from the phase's start
    seconds = np.arange(time[0], time[-1] + 1e-9, 1.0)
    along = com @ direction
    samples = np.interp(seconds, time, along)
    return np.diff(samples)


def steadiness(progress):
    """Share of the seconds with forward progress of at least 10 % of the mean per second."""
    if len(progress) == 0:
        return 0.0
    mean = progress.sum() / len(progress)
    if mean <= 0:
        return 0.0
    return float(np.mean(progress >= 0.1 * mean))


def generation_best(individuals, generation, ok_code):
    """Row index of the best ok individual of `generation` (lowest id on ties)."""
    rows = np.flatnonzero((individuals["generation"] == generation) & (individuals["status"] == ok_code))
    if len(rows) == 0:
        raise ch.HistoryError(f"generation {generation} has no ok individual")
    fitness = individuals["fitness"][rows]
    best = rows[fitness == fitness.max()]
    return best[np.argmin(individuals["id"][best])]


def measure(individuals, name, row):
    """A measure of one row; NaN when the run's task does not report it (measures are stored by
    name, one column per measure the task declares)."""
    column = individuals.get("measure:" + name)
    return float("nan") if column is None else float(column[row])


def study_run(label, directory):
    """The figures of one run: best per generation and the first/last best creatures."""
    with ch.History(os.path.join(directory, "history.h5")) as history:
        generations = history.generations()
        individuals = history.individuals()
        ok_code = history.status_names().index("ok")
    last = int(generations["generation"].max())
    result = {"label": label, "best": generations["best"], "generation": generations["generation"]}
    for which, generation in (("first", 0), ("last", last)):
        row = generation_best(individuals, generation, ok_code)
        entry = {
            "id": int(individuals["id"][row]),
            "distance": measure(individuals, "distance", row),
            "body_lengths": measure(individuals, "body_lengths", row),
            "body_length": measure(individuals, "body_length", row),
            "parts": int(individuals["parts"][row]),
            "progress": None,
        }
        path = os.path.join(directory, f"best-{which}.h5")
        if os.path.exists(path):
            trajectory = load_trajectory(path)
            entry["progress"] = per_second_progress(trajectory)
            entry["com_time"] = trajectory["time"]
            entry["com"] = trajectory["center_of_mass"]
            entry["phase"] = trajectory["phase"]
        result[which] = entry
    return result


def markdown_table(results):
    """One row per run: first and last best, distance and body lengths, steadiness."""
    lines = [
        "| run | best gen 1: m (body lengths, parts) | best last gen: m (body lengths, parts) | gain | steadiness last |",
        "| --- | --- | --- | --- | --- |",
    ]
    for r in results:
        first, last = r["first"], r["last"]
        steady = "n/a" if last["progress"] is None else f"{steadiness(last['progress']):.0%}"
        gain = last["distance"] / first["distance"] if first["distance"] > 0 else float("inf")
        lines.append(
            f"| {r['label']} | {first['distance']:.2f} ({first['body_lengths']:.1f}, {first['parts']}) "
            f"| {last['distance']:.2f} ({last['body_lengths']:.1f}, {last['parts']}) | {gain:.1f}x | {steady} |"
        )
    return "\n".join(lines)


def plot(results, output, dpi):
    """Best fitness per generation for every run, and the last bests' forward progress."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    # best distance per generation
    colours = [f"C{i % 10}" for i in range(len(results))]
    for r, colour in zip(results, colours):
        left.plot(r["generation"] + 1, r["best"], marker=".", color=colour, label=r["label"])
    left.set_xlabel("generation")
    left.set_ylabel("best distance in 10 s (m)")
    left.set_title("best walker per generation")
    left.grid(alpha=0.3)
    left.legend()
    # centre-of-mass progress of the first and last bests over the measured phase, one colour a run
    for r, colour in zip(results, colours):
        for which, style in (("first", ":"), ("last", "-")):
            entry = r[which]
            if entry["progress"] is None:
                continue
            measured = entry["phase"] == MEASURE_PHASE
            time = entry["com_time"][measured]
            com = entry["com"][measured][:, :2]
            travelled = np.linalg.norm(com - com[0], axis=1)
            right.plot(
                time - time[0], travelled, style, color=colour, label=f"{r['label']} {which} gen"
            )
    right.set_xlabel("measured time (s)")
    right.set_ylabel("distance from the start of the measure (m)")
    right.set_title("first (dotted) and last (solid) best")
    right.grid(alpha=0.3)
    right.legend(fontsize=7, ncol=2)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--run", action="append", required=True, metavar="LABEL=DIR",
                        help="a run directory (history.h5, optional best-first.h5 / best-last.h5)")
    parser.add_argument("-o", "--output", default="walk_study.png", help="figure (PNG)")
    parser.add_argument("--dpi", type=int, default=120)
    return parser.parse_args(argv)


def main(argv=None):
    arguments = parse_arguments(argv)
    # every run, then the table and the figure
    results = []
    for spec in arguments.run:
        label, _, directory = spec.partition("=")
        if not directory:
            label, directory = os.path.basename(os.path.normpath(spec)), spec
        try:
            results.append(study_run(label, directory))
        except (ch.HistoryError, TrajectoryError) as error:
            print(f"walk_study.py: {directory}: {error}", file=sys.stderr)
            return 4
    print(markdown_table(results))
    plot(results, arguments.output, arguments.dpi)
    print(f"figure: {arguments.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
