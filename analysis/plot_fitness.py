#!/usr/bin/env python3
"""Plot fitness over generations from a cambrian history file: best, mean, median and the
interquartile band (q25..q75), written to a PNG (headless, matplotlib's Agg backend).

    python3 analysis/plot_fitness.py run/history.h5 --output fitness.png
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
    parser.add_argument("history", help="history.h5 written by `cambrian evolve`")
    parser.add_argument("-o", "--output", default="fitness.png", help="PNG to write (default: fitness.png)")
    parser.add_argument("--title", default=None, help="plot title (default: the file and seed)")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    return parser.parse_args(argv)


def plot(generations, title, output, dpi=120):
    """Draws the fitness curves of a generations table (dict of arrays) into `output`."""
    g = generations["generation"]
    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.fill_between(g, generations["q25"], generations["q75"], alpha=0.25, label="q25..q75")
    axes.plot(g, generations["best"], label="best", linewidth=2)
    axes.plot(g, generations["mean"], label="mean")
    axes.plot(g, generations["median"], label="median", linestyle="--")
    axes.set_xlabel("generation")
    axes.set_ylabel("fitness")
    axes.set_title(title)
    axes.grid(alpha=0.3)
    axes.legend(loc="best")
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        with cambrian_history.History(arguments.history) as history:
            generations = history.generations()
            seed = history.attributes.get("seed")
    except cambrian_history.HistoryError as error:
        print(f"plot_fitness: error: {error}", file=sys.stderr)
        return 4
    if len(generations["generation"]) == 0:
        print(f"plot_fitness: error: {arguments.history}: no generations yet", file=sys.stderr)
        return 4
    title = arguments.title or f"{arguments.history} (seed {seed})"
    plot(generations, title, arguments.output, arguments.dpi)
    print(f"wrote {arguments.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
