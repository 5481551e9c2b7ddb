#!/usr/bin/env python3
"""Points of improvement in a cambrian history: which operators make offspring better than
their parent(s), and which make a new best-so-far fitness.

For every offspring of `mutation`, `crossover` and `graft` (and of the reaper's
`gene_specification`, `gene_split`, `gene_purge`, `branch_specification`, `grow_stub` and
`graft_feature`) the outcome is classed against its better parent: `improved` (fitness above it), `same` (equal), `worse` (below) or `failed` (status
not ok). Crossover and graft children of two identical parents (same id or identical genome
bytes) are listed as `crossover (same parents)` / `graft (same parents)`: the operator then
could only act as a mutation (Krčah 2008 credits those to mutation).

A *point of improvement* is a generation whose best creature beats the champion of every
earlier generation; it is credited to the operator that made that creature.

Krčah's classes of mutants (Tables 4.10 and 4.13) are counted per operator too: offspring with
zero fitness (or a failed status), with the same fitness as their (better) parent, or with a
different non-zero fitness.

Prints per-operator counts and rates over the run, the points of improvement and the rates per
window of generations (TSV sections on stdout, headed by `# ` lines), and draws a bar chart.

    python3 analysis/improvements.py run/history.h5 --output improvements.png [--window 10]

Exit codes: 0 ok, 2 usage, 4 bad input file.
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

PROGRAM = "improvements"
# the operators that make offspring: the generational scheme's, then Minemonics' reaper's
BREEDING = ("mutation", "crossover", "graft", "gene_specification", "gene_split", "gene_purge",
            "branch_specification", "grow_stub", "graft_feature", "segment_crossover")
OUTCOMES = ("improved", "same", "worse", "failed")
MUTANT_CLASSES = ("zero", "same", "different")


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Count, per operator, offspring better than their parent(s) and the points of "
        "improvement (new best-so-far) of a cambrian history; per run and per window of "
        "generations; bar chart.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("history", help="history.h5 written by `cambrian evolve`")
    parser.add_argument("-o", "--output", default="improvements.png", help="PNG to write (default: improvements.png)")
    parser.add_argument("--window", type=int, default=0,
                        help="generations per window (default: about a fifth of the run, at least 1)")
    parser.add_argument("--table", default=None, help="also write the per-operator table to this TSV file")
    parser.add_argument("--windows-table", default=None, help="also write the per-window table to this TSV file")
    parser.add_argument("--mutants-table", default=None,
                        help="also write the mutant classes per operator (zero, same, different) to this TSV file")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    arguments = parser.parse_args(argv)
    if arguments.window < 0:
        parser.error("--window must be >= 0")
    return arguments


def classify(individuals, labels, statuses, genomes=None):
    """Per offspring row: (row, operator label, outcome, parent fitness). `genomes`, when given,
    maps a row to its genome bytes (for the identical-parents check)."""
    rows = ch.first_rows(individuals)
    ok = statuses.index("ok") if "ok" in statuses else 0
    out = []
    for row in np.nonzero(np.isin(labels, BREEDING))[0]:
        a, b = int(individuals["parent_a"][row]), int(individuals["parent_b"][row])
        if a not in rows:
            continue
        parents = [rows[a]] + ([rows[b]] if b != int(ch.NO_ID) and b in rows else [])
        label = str(labels[row])
        if len(parents) == 2 and (a == b or (genomes is not None and genomes(parents[0]) == genomes(parents[1]))):
            label += " (same parents)"
        reference = max(float(individuals["fitness"][p]) for p in parents)
        fitness = float(individuals["fitness"][row])
        if int(individuals["status"][row]) != ok:
            outcome = "failed"
        elif fitness > reference:
            outcome = "improved"
        elif fitness == reference:
            outcome = "same"
        else:
            outcome = "worse"
        out.append((int(row), label, outcome, reference))
    return out


def points_of_improvement(individuals, labels, classes=None):
    """Generations whose best beats every earlier generation: list of dicts (generation, id,
    operator, fitness, previous champion, gain). With `classes` (from classify) the operator
    is the classified label, e.g. `crossover (same parents)`."""
    labels = np.array(labels, dtype=object)
    for row, label, _, _ in classes or ():
        labels[row] = label
    generation = individuals["generation"]
    fitness = individuals["fitness"]
    points = []
    champion = None
    for g in np.unique(generation):
        mine = np.nonzero(generation == g)[0]
        best = fitness[mine].max()
        row = mine[fitness[mine] == best][np.argmin(individuals["id"][mine][fitness[mine] == best])]
        if champion is not None and best > champion:
            points.append({"generation": int(g), "id": int(individuals["id"][row]), "operator": str(labels[row]),
                           "fitness": float(best), "previous": float(champion), "gain": float(best - champion)})
        champion = best if champion is None else max(champion, best)
    return points


def summarise(classes, points, individuals, first=None, last=None):
    """dict operator -> counts (offspring, each outcome, points) for generations first..last."""
    generation = individuals["generation"]
    summary = {}
    for row, label, outcome, _ in classes:
        if first is not None and not first <= generation[row] <= last:
            continue
        entry = summary.setdefault(label, dict.fromkeys(("offspring", *OUTCOMES, "points"), 0))
        entry["offspring"] += 1
        entry[outcome] += 1
    for point in points:
        if first is not None and not first <= point["generation"] <= last:
            continue
        entry = summary.setdefault(point["operator"], dict.fromkeys(("offspring", *OUTCOMES, "points"), 0))
        entry["points"] += 1
    return summary


def mutant_classes(individuals, classes):
    """dict operator -> counts of Krčah's mutant classes: `zero` (fitness 0 or status not ok),
    `same` (the fitness of the better parent) and `different` (another non-zero fitness)."""
    counts = {}
    for row, label, outcome, reference in classes:
        fitness = float(individuals["fitness"][row])
        entry = counts.setdefault(label, dict.fromkeys(("offspring", *MUTANT_CLASSES), 0))
        entry["offspring"] += 1
        if outcome == "failed" or fitness == 0:
            entry["zero"] += 1
        elif fitness == reference:
            entry["same"] += 1
        else:
            entry["different"] += 1
    return counts


def mutant_rows(counts):
    """TSV lines of the mutant classes, operators sorted by name, with each class's share."""
    lines = ["operator\toffspring\tzero\tsame\tdifferent\tzero_share\tsame_share\tdifferent_share"]
    for label in sorted(counts):
        e = counts[label]
        shares = [e[k] / e["offspring"] if e["offspring"] else float("nan") for k in MUTANT_CLASSES]
        lines.append(f"{label}\t{e['offspring']}\t{e['zero']}\t{e['same']}\t{e['different']}\t"
                     + "\t".join(f"{x:.4f}" for x in shares))
    return lines


def rate(entry):
    """Share of offspring that improved on their parent(s); nan without offspring."""
    return entry["improved"] / entry["offspring"] if entry["offspring"] else float("nan")


def operator_rows(summary):
    """TSV lines of a summary, operators sorted by name."""
    lines = ["operator\toffspring\timproved\tsame\tworse\tfailed\timproved_rate\tpoints_of_improvement"]
    for label in sorted(summary):
        e = summary[label]
        lines.append(f"{label}\t{e['offspring']}\t{e['improved']}\t{e['same']}\t{e['worse']}\t{e['failed']}\t"
                     f"{rate(e):.4f}\t{e['points']}")
    return lines


def plot(summary, windows, output, title, dpi):
    """Improvement rate and points per operator, and the rate per window of generations."""
    labels = sorted(summary)
    figure, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    x = np.arange(len(labels))
    # rate of improving offspring per operator
    axes[0].bar(x, [rate(summary[k]) for k in labels], color="tab:blue")
    axes[0].set_ylabel("offspring better than parent(s)")
    axes[0].set_title("improvement rate")
    # points of improvement per operator
    axes[1].bar(x, [summary[k]["points"] for k in labels], color="tab:orange")
    axes[1].set_ylabel("new best-so-far (generations)")
    axes[1].set_title("points of improvement")
    for a in axes[:2]:
        a.set_xticks(x)
        a.set_xticklabels(labels, rotation=30, ha="right", fontsize="small")
        a.grid(axis="y", alpha=0.3)
    # rate per window, one bar group per window
    width = 0.8 / max(len(labels), 1)
    for i, label in enumerate(labels):
        values = [rate(w["summary"][label]) if label in w["summary"] else 0.0 for w in windows]
        axes[2].bar(np.arange(len(windows)) + i * width, values, width, label=label)
    axes[2].set_xticks(np.arange(len(windows)) + 0.4 - width / 2)
    axes[2].set_xticklabels([f"{w['first']}-{w['last']}" for w in windows], fontsize="small")
    axes[2].set_xlabel("generations")
    axes[2].set_title("improvement rate per window")
    axes[2].legend(fontsize="x-small")
    axes[2].grid(axis="y", alpha=0.3)
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    attributes, individuals, generations, labels, statuses = ch.open_or_exit(arguments.history, PROGRAM)
    # genome bytes for the identical-parents check
    with ch.History(arguments.history) as history:
        stream = ch.genome_stream(history)
    classes = classify(individuals, labels, statuses, lambda row: ch.genome_of(stream, individuals, row))
    points = points_of_improvement(individuals, labels, classes)
    summary = summarise(classes, points, individuals)
    # windows of generations
    last = int(individuals["generation"].max())
    window = arguments.window or max(1, (last + 1 + 4) // 5)
    windows = [{"first": s, "last": min(s + window - 1, last)} for s in range(0, last + 1, window)]
    for w in windows:
        w["summary"] = summarise(classes, points, individuals, w["first"], w["last"])
    # per operator, points, per window
    lines = [f"# {arguments.history}: offspring outcomes per operator, generations 0-{last}"]
    lines += operator_rows(summary)
    lines.append("# points of improvement (a generation's best beats every earlier generation)")
    lines.append("generation\tid\toperator\tfitness\tprevious\tgain")
    lines += [f"{p['generation']}\t{p['id']}\t{p['operator']}\t{p['fitness']:.6g}\t{p['previous']:.6g}\t{p['gain']:.6g}"
              for p in points]
    lines.append(f"# per window of {window} generations")
    window_lines = ["first\tlast\toperator\toffspring\timproved\timproved_rate\tpoints_of_improvement"]
    for w in windows:
        for label in sorted(w["summary"]):
            e = w["summary"][label]
            window_lines.append(f"{w['first']}\t{w['last']}\t{label}\t{e['offspring']}\t{e['improved']}\t"
                                f"{rate(e):.4f}\t{e['points']}")
    lines += window_lines
    mutants = mutant_rows(mutant_classes(individuals, classes))
    lines.append("# mutant classes (Krčah 2008, Tables 4.10 and 4.13): zero fitness or failed, the same "
                 "fitness as the (better) parent, a different non-zero fitness")
    lines += mutants
    print("\n".join(lines))
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write("\n".join(operator_rows(summary)) + "\n")
    if arguments.mutants_table:
        with open(arguments.mutants_table, "w") as handle:
            handle.write("\n".join(mutants) + "\n")
    if arguments.windows_table:
        with open(arguments.windows_table, "w") as handle:
            handle.write("\n".join(window_lines) + "\n")
    title = f"{os.path.basename(arguments.history)} (seed {attributes.get('seed')}): {len(points)} points of improvement"
    plot(summary, windows, arguments.output, title, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
