#!/usr/bin/env python3
"""Plot fitness over generations from a cambrian history file: best, mean, median and the
interquartile band (q25..q75), written to a PNG (headless, matplotlib's Agg backend). Given
several histories (runs of one experiment at several seeds, say), it draws each run's best
(solid) and median (dashed) in one colour per run, labelled by seed, to show the spread. With
--sequence the runs are steps of one sequence (each started from the best of the one before,
evolution.seed_history, perhaps under another test): one panel each, left to right, with its own
fitness axis and the generations counted on from the step before.

    python3 analysis/plot_fitness.py run/history.h5 --output fitness.png
    python3 analysis/plot_fitness.py seed1/history.h5 seed2/history.h5 --output seeds.png
    python3 analysis/plot_fitness.py t1/history.h5 t2/history.h5 --sequence --label "step 1" \
        --label "step 2" --output chain.png
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cambrian_history  # noqa: E402


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Plot best / mean / median fitness and the q25..q75 band over generations "
        "from a cambrian history.h5 (works while the run is still writing it)."
    )
    parser.add_argument(
        "history", nargs="+", help="history.h5 written by `cambrian evolve`; several: one line pair per run"
    )
    parser.add_argument("-o", "--output", default="fitness.png", help="PNG to write (default: fitness.png)")
    parser.add_argument("--title", default=None, help="plot title (default: the file and seed)")
    parser.add_argument(
        "--log", action="store_true", help="logarithmic fitness axis (runs that differ by orders of magnitude)"
    )
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    parser.add_argument(
        "--sequence",
        action="store_true",
        help="the runs are steps of one sequence: a panel each, generations counted on",
    )
    parser.add_argument(
        "--label",
        action="append",
        default=None,
        help="a run's label, once per history in their order (default: seed or directory)",
    )
    arguments = parser.parse_args(argv)
    if arguments.label is not None and len(arguments.label) != len(arguments.history):
        parser.error(f"--label given {len(arguments.label)} times for {len(arguments.history)} histories")
    return arguments


def draw_curves(axes, g, generations):
    """The q25..q75 band and the best, mean and median lines of a generations table at x = g."""
    axes.fill_between(g, generations["q25"], generations["q75"], alpha=0.25, label="q25..q75")
    axes.plot(g, generations["best"], label="best", linewidth=2)
    axes.plot(g, generations["mean"], label="mean")
    axes.plot(g, generations["median"], label="median", linestyle="--")


def plot(generations, title, output, dpi=120):
    """Draws the fitness curves of a generations table (dict of arrays) into `output`."""
    figure, axes = plt.subplots(figsize=(8, 4.5))
    draw_curves(axes, generations["generation"], generations)
    axes.set_xlabel("generation")
    axes.set_ylabel("fitness")
    axes.set_title(title)
    axes.grid(alpha=0.3)
    axes.legend(loc="best")
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def plot_runs(runs, title, output, dpi=120, log=False):
    """Draws each run's best (solid) and median (dashed) in a colour of its own; `runs` is a list
    of (label, generations table)."""
    figure, axes = plt.subplots(figsize=(8, 4.5))
    colours = plt.get_cmap("tab10")
    for k, (label, generations) in enumerate(runs):
        g = generations["generation"]
        colour = colours(k % 10)
        axes.plot(g, generations["best"], color=colour, linewidth=2, label=f"{label}: best")
        axes.plot(g, generations["median"], color=colour, linestyle="--", label=f"{label}: median")
    axes.set_xlabel("generation")
    axes.set_ylabel("fitness")
    if log:
        axes.set_yscale("symlog", linthresh=1.0)
    axes.set_title(title)
    axes.grid(alpha=0.3)
    axes.legend(loc="best", fontsize=8)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def plot_sequence(runs, title, output, dpi=120):
    """Draws the steps of a sequence left to right, a panel each with its own fitness axis (a step
    may score another test) and its generations numbered on from the step before; `runs` is a
    list of (label, generations table)."""
    figure, panels = plt.subplots(1, len(runs), figsize=(max(8, 4 * len(runs)), 4.5), squeeze=False)
    offset = 0
    for axes, (label, generations) in zip(panels[0], runs):
        g = [offset + x for x in generations["generation"]]
        draw_curves(axes, g, generations)
        axes.set_title(label, fontsize=10)
        axes.set_xlabel("generation")
        axes.grid(alpha=0.3)
        offset = g[-1] + 1
    panels[0][0].set_ylabel("fitness")
    panels[0][0].legend(loc="best", fontsize=8)
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def run_label(path, seed, seeds):
    """A run's label: its seed, or its directory where two runs share a seed."""
    if seed is not None and seeds.count(seed) == 1:
        return f"seed {seed}"
    return os.path.basename(os.path.dirname(os.path.abspath(path))) or path


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    tables, seeds = [], []
    for path in arguments.history:
        try:
            with cambrian_history.History(path) as history:
                generations = history.generations()
                seed = history.attributes.get("seed")
        except cambrian_history.HistoryError as error:
            print(f"plot_fitness: error: {error}", file=sys.stderr)
            return 4
        if len(generations["generation"]) == 0:
            print(f"plot_fitness: error: {path}: no generations yet", file=sys.stderr)
            return 4
        tables.append(generations)
        seeds.append(None if seed is None else int(seed))
    labels = arguments.label or [run_label(path, seed, seeds) for path, seed in zip(arguments.history, seeds)]
    if arguments.sequence:
        title = arguments.title or f"a sequence of {len(tables)} runs"
        plot_sequence(list(zip(labels, tables)), title, arguments.output, arguments.dpi)
    elif len(tables) == 1:
        title = arguments.title or f"{arguments.history[0]} (seed {seeds[0]})"
        plot(tables[0], title, arguments.output, arguments.dpi)
        if arguments.log:
            print("plot_fitness: --log applies to several runs only", file=sys.stderr)
    else:
        runs = list(zip(labels, tables))
        title = arguments.title or f"{len(runs)} runs"
        plot_runs(runs, title, arguments.output, arguments.dpi, arguments.log)
    print(f"wrote {arguments.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
