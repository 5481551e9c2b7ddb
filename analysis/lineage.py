#!/usr/bin/env python3
"""The lineage of one creature in a cambrian history: the best creature of the run (or --id),
walked back to generation 0 along parent_a (the main line), with every ancestor reached through
parent_b (crossover, graft) counted too.

Prints the main line as a TSV table (generation, id, operator, fitness, change, parents) and
draws fitness along it, each step marked with the operator that made it, over the best fitness
of each generation for reference (PNG, headless).

    python3 analysis/lineage.py run/history.h5 --output lineage.png [--id 1234] [--table lineage.tsv]

Exit codes: 0 ok, 2 usage, 4 bad input file (missing, not a history, empty, broken lineage).
"""

import argparse
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cambrian_history as ch  # noqa: E402

PROGRAM = "lineage"
# one marker per operator, so the plot reads in black and white too
MARKERS = {"random": "o", "seed": "*", "elite": "s", "mutation": "^", "crossover": "D", "graft": "P",
           "gene_specification": "v", "gene_split": "<", "gene_purge": ">", "branch_specification": "p",
           "grow_stub": "h", "graft_feature": "X", "segment_crossover": "d", "migrant": "8"}
COLUMNS = ["step", "generation", "id", "operator", "fitness", "change", "parent_a", "parent_b"]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Walk the lineage of the best creature of a cambrian history (or of --id) back "
        "to generation 0; print the main line (parent_a) as TSV and plot fitness along it with "
        "the operator of each step marked.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("history", help="history.h5 written by `cambrian evolve`")
    parser.add_argument("-o", "--output", default="lineage.png", help="PNG to write (default: lineage.png)")
    parser.add_argument("--id", type=int, default=None, help="creature to follow (default: the best of the run, ties: lowest id)")
    parser.add_argument("--table", default=None, help="also write the lineage table to this TSV file")
    parser.add_argument("--title", default=None, help="plot title (default: file and id)")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    return parser.parse_args(argv)


def best_id(individuals):
    """Id of the fittest creature of the run (ties: the lowest id)."""
    fitness = individuals["fitness"]
    best = fitness.max()
    return int(individuals["id"][fitness == best].min())


def trace(individuals, labels, start_id):
    """(main line, ancestors): the main line is a list of row indices from start_id back to
    generation 0 following parent_a; ancestors is the set of every id reachable through
    parent_a and parent_b. Raises InputFileError for an unknown id or a missing parent."""
    rows = ch.first_rows(individuals)
    if start_id not in rows:
        raise ch.InputFileError(f"no individual with id {start_id}")
    # main line: parent_a back to a creature without parents
    line, seen = [], set()
    row = rows[start_id]
    while True:
        line.append(row)
        parent = int(individuals["parent_a"][row])
        if parent == int(ch.NO_ID):
            break
        if parent not in rows:
            raise ch.InputFileError(f"parent {parent} of id {int(individuals['id'][row])} is not in the history")
        if parent in seen:
            raise ch.InputFileError(f"the lineage of {start_id} loops at id {parent}")
        seen.add(parent)
        row = rows[parent]
    # every ancestor through either parent (breadth first)
    ancestors, frontier = set(), [start_id]
    while frontier:
        current = frontier.pop()
        r = rows[current]
        for column in ("parent_a", "parent_b"):
            parent = int(individuals[column][r])
            if parent == int(ch.NO_ID) or parent in ancestors:
                continue
            if parent not in rows:
                raise ch.InputFileError(f"parent {parent} of id {current} is not in the history")
            ancestors.add(parent)
            frontier.append(parent)
    return line, ancestors


def lineage_table(individuals, labels, line):
    """Rows (dicts) of the main line from generation 0 to the creature, with fitness change."""
    table = []
    previous = None
    for step, row in enumerate(reversed(line)):
        fitness = float(individuals["fitness"][row])
        parent_b = int(individuals["parent_b"][row])
        parent_a = int(individuals["parent_a"][row])
        table.append({
            "step": step,
            "generation": int(individuals["generation"][row]),
            "id": int(individuals["id"][row]),
            "operator": str(labels[row]),
            "fitness": fitness,
            "change": 0.0 if previous is None else fitness - previous,
            "parent_a": "" if parent_a == int(ch.NO_ID) else parent_a,
            "parent_b": "" if parent_b == int(ch.NO_ID) else parent_b,
        })
        previous = fitness
    return table


def format_table(table):
    """The lineage table as TSV text (header line first)."""
    lines = ["\t".join(COLUMNS)]
    for row in table:
        values = [row[c] for c in COLUMNS]
        lines.append("\t".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in values))
    return "\n".join(lines) + "\n"


def plot(table, generations, title, output, dpi):
    """Fitness along the main line, markers by operator, over the per-generation best."""
    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.plot(generations["generation"], generations["best"], color="0.75", linewidth=3, label="best of generation")
    x = [r["generation"] for r in table]
    y = [r["fitness"] for r in table]
    axes.plot(x, y, color="tab:blue", linewidth=1.2, label="lineage (parent_a)")
    # one scatter per operator so the legend names them
    for operator in sorted({r["operator"] for r in table}):
        pick = [r for r in table if r["operator"] == operator]
        axes.scatter([r["generation"] for r in pick], [r["fitness"] for r in pick],
                     marker=MARKERS.get(operator, "x"), s=46, zorder=3, label=operator)
    axes.set_xlabel("generation")
    axes.set_ylabel("fitness")
    axes.set_title(title)
    axes.grid(alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    attributes, individuals, generations, labels, _ = ch.open_or_exit(arguments.history, PROGRAM)
    # follow the requested creature or the best one
    start = arguments.id if arguments.id is not None else best_id(individuals)
    try:
        line, ancestors = trace(individuals, labels, start)
    except ch.InputFileError as error:
        print(f"{PROGRAM}: error: {arguments.history}: {error}", file=sys.stderr)
        return ch.EXIT_INPUT
    table = lineage_table(individuals, labels, line)
    text = format_table(table)
    # the table to stdout (and a file), then a one-line summary
    sys.stdout.write(text)
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write(text)
    operators = {}
    for row in table[1:]:
        operators[row["operator"]] = operators.get(row["operator"], 0) + 1
    steps = ", ".join(f"{k} {v}" for k, v in sorted(operators.items()))
    print(f"# id {start}: {len(table)} creatures on the main line from generation {table[0]['generation']}, "
          f"{len(ancestors)} ancestors in all; steps: {steps or 'none'}")
    title = arguments.title or f"lineage of id {start} ({os.path.basename(arguments.history)}, seed {attributes.get('seed')})"
    plot(table, generations, title, arguments.output, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
