#!/usr/bin/env python3
"""Diversity of a cambrian population over generations: distinct genomes, the spread of fitness,
the spread of body size (parts) and a genotype distance.

Genotype distance (defined here, documented in docs/analysis.md): each genome's serialized bytes
(the `CMBG` stream of docs/genome.md) are cut into overlapping 4-byte shingles; the distance of
two genomes is the Jaccard distance of their shingle sets, 1 - |A ∩ B| / |A ∪ B|. It is 0 for
identical genomes, near 0 after a small mutation (only the shingles around a changed number
differ) and near 1 for genomes that share no structure. It needs no parser, so it keeps working
when the genome format grows. A generation's value is the mean over all pairs, or over --pairs
random pairs (seeded, so reruns agree) when there are more.

Also per generation: distinct fitness values, the largest group of identical fitness (a share
of the population: Krčah 2008's dominant group), the share of the population in small groups of
identical fitness (at most 5 members, Krčah's measure of diversity), nodes per genome (from the
genome header) and genome bytes. With --groups N it lists a generation's N largest groups
(size, share, fitness, distinct genomes), as Krčah's Table 4.6 does for the last one.

    python3 analysis/diversity.py run/history.h5 --output diversity.png [--table diversity.tsv]

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

PROGRAM = "diversity"
SHINGLE = 4  # bytes per shingle
SMALL_GROUP = 5  # members of an equal-fitness group counted as small (Krčah 2008, §4)
COLUMNS = ["generation", "count", "distinct_genomes", "distinct_fitness", "largest_group_share",
           "small_group_share", "fitness_std", "fitness_iqr", "parts_mean", "parts_std", "parts_min", "parts_max",
           "nodes_mean", "genome_bytes_mean", "genotype_distance"]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Diversity per generation of a cambrian history: distinct genomes, fitness "
        "spread, body size (parts) spread and a genotype distance (Jaccard distance of 4-byte "
        "shingles of the genome bytes); TSV on stdout and a PNG.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("history", help="history.h5 written by `cambrian evolve`")
    parser.add_argument("-o", "--output", default="diversity.png", help="PNG to write (default: diversity.png)")
    parser.add_argument("--table", default=None, help="also write the table to this TSV file")
    parser.add_argument("--pairs", type=int, default=2000,
                        help="genome pairs sampled per generation for the distance (default 2000; all pairs when fewer)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the pair sample (default 1)")
    parser.add_argument("--groups", type=int, default=0,
                        help="also list the N largest groups of equal fitness of a generation (default 0: none)")
    parser.add_argument("--groups-generation", type=int, default=None,
                        help="the generation --groups lists (default: the last)")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    arguments = parser.parse_args(argv)
    if arguments.pairs < 1:
        parser.error("--pairs must be >= 1")
    if arguments.groups < 0:
        parser.error("--groups must be >= 0")
    return arguments


def shingles(genome):
    """Sorted unique 4-byte shingles of a genome (uint32); a shorter genome is one shingle."""
    data = np.frombuffer(genome, dtype=np.uint8).astype(np.uint32)
    if len(data) < SHINGLE:
        data = np.concatenate([data, np.zeros(SHINGLE - len(data), dtype=np.uint32)])
    grams = (data[:-3] << 24) | (data[1:-2] << 16) | (data[2:-1] << 8) | data[3:]
    return np.unique(grams)


def jaccard_distance(a, b):
    """1 - |a ∩ b| / |a ∪ b| of two sorted unique shingle arrays."""
    common = len(np.intersect1d(a, b, assume_unique=True))
    union = len(a) + len(b) - common
    return 1.0 - common / union if union else 0.0


def mean_distance(genomes, pairs, rng):
    """Mean Jaccard distance over all pairs of the genomes, or over `pairs` random pairs."""
    n = len(genomes)
    if n < 2:
        return 0.0
    sets = [shingles(g) for g in genomes]
    total = n * (n - 1) // 2
    if total <= pairs:
        i, j = np.triu_indices(n, 1)
    else:
        i = rng.integers(0, n, pairs)
        j = (i + rng.integers(1, n, pairs)) % n  # never the same genome twice
    return float(np.mean([jaccard_distance(sets[a], sets[b]) for a, b in zip(i, j)]))


def largest_groups(fitness, genomes, count):
    """The `count` largest groups of equal fitness, largest first (ties: higher fitness first):
    dicts of size, share of the population, fitness and distinct genomes in the group."""
    fitness = np.asarray(fitness, dtype=float)
    values, sizes = np.unique(fitness, return_counts=True)
    order = sorted(range(len(values)), key=lambda k: (-sizes[k], -values[k]))[:count]
    groups = []
    for k in order:
        members = np.nonzero(fitness == values[k])[0]
        groups.append({"size": int(sizes[k]), "share": float(sizes[k] / len(fitness)),
                       "fitness": float(values[k]),
                       "distinct_genomes": len({genomes[m] for m in members})})
    return groups


def small_group_share(fitness):
    """Share of the individuals in groups of equal fitness with at most SMALL_GROUP members."""
    _, sizes = np.unique(np.asarray(fitness, dtype=float), return_counts=True)
    return float(sizes[sizes <= SMALL_GROUP].sum() / sizes.sum()) if len(sizes) else 0.0


def diversity(individuals, stream, pairs=2000, seed=1):
    """One dict per generation with every column of COLUMNS."""
    rng = np.random.default_rng(seed)
    rows = []
    for g in np.unique(individuals["generation"]):
        mine = np.nonzero(individuals["generation"] == g)[0]
        genomes = [ch.genome_of(stream, individuals, r) for r in mine]
        fitness = individuals["fitness"][mine]
        parts = individuals["parts"][mine].astype(float)
        _, group_sizes = np.unique(fitness, return_counts=True)
        q25, q75 = np.percentile(fitness, [25, 75])
        rows.append({
            "generation": int(g),
            "count": len(mine),
            "distinct_genomes": len(set(genomes)),
            "distinct_fitness": len(group_sizes),
            "largest_group_share": float(group_sizes.max() / len(mine)),
            "small_group_share": small_group_share(fitness),
            "fitness_std": float(fitness.std()),
            "fitness_iqr": float(q75 - q25),
            "parts_mean": float(parts.mean()),
            "parts_std": float(parts.std()),
            "parts_min": int(parts.min()),
            "parts_max": int(parts.max()),
            "nodes_mean": float(np.mean([ch.genome_node_count(x) for x in genomes])),
            "genome_bytes_mean": float(np.mean([len(x) for x in genomes])),
            "genotype_distance": mean_distance(genomes, pairs, rng),
        })
    return rows


def format_table(rows):
    """TSV text of the per-generation rows."""
    return "\n".join(ch.tsv_lines(rows, COLUMNS)) + "\n"


def plot(rows, output, title, dpi):
    """Four panels: distinct shares, fitness spread, body size, genotype distance."""
    g = [r["generation"] for r in rows]
    column = lambda name: np.array([r[name] for r in rows], dtype=float)  # noqa: E731
    figure, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    # distinct genomes and fitness values, as shares of the population
    a = axes[0, 0]
    a.plot(g, column("distinct_genomes") / column("count"), marker="o", label="distinct genomes")
    a.plot(g, column("distinct_fitness") / column("count"), marker=".", label="distinct fitness values")
    a.plot(g, column("largest_group_share"), linestyle="--", label="largest equal-fitness group")
    a.plot(g, column("small_group_share"), linestyle=":", label=f"in equal-fitness groups of ≤ {SMALL_GROUP}")
    a.set_ylabel("share of population")
    a.set_ylim(0, 1.05)
    a.legend(fontsize="small")
    # spread of fitness
    a = axes[0, 1]
    a.plot(g, column("fitness_std"), marker="o", label="standard deviation")
    a.plot(g, column("fitness_iqr"), marker=".", label="q75 - q25")
    a.set_ylabel("fitness spread")
    a.legend(fontsize="small")
    # body size
    a = axes[1, 0]
    a.fill_between(g, column("parts_min"), column("parts_max"), alpha=0.2, label="min..max")
    a.errorbar(g, column("parts_mean"), yerr=column("parts_std"), marker="o", capsize=3, label="mean ± sd")
    a.set_ylabel("parts per creature")
    a.set_xlabel("generation")
    a.legend(fontsize="small")
    # genotype distance
    a = axes[1, 1]
    a.plot(g, column("genotype_distance"), marker="o", color="tab:purple")
    a.set_ylabel("mean genotype distance (4-byte Jaccard)")
    a.set_ylim(0, 1.05)
    a.set_xlabel("generation")
    for a in axes.flat:
        a.grid(alpha=0.3)
    ch.save_figure(figure, title, output, dpi)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    attributes, individuals, generations, _, _ = ch.open_or_exit(arguments.history, PROGRAM)
    # every genome in one read
    with ch.History(arguments.history) as history:
        stream = ch.genome_stream(history)
    rows = diversity(individuals, stream, arguments.pairs, arguments.seed)
    # the largest groups of a generation, checked before anything is written
    group_lines = []
    if arguments.groups:
        generation = individuals["generation"]
        g = int(generation.max()) if arguments.groups_generation is None else arguments.groups_generation
        mine = np.nonzero(generation == g)[0]
        if len(mine) == 0:
            print(f"{PROGRAM}: --groups-generation {g}: the history has no generation {g}", file=sys.stderr)
            return ch.EXIT_USAGE
        genomes = [ch.genome_of(stream, individuals, r) for r in mine]
        groups = largest_groups(individuals["fitness"][mine], genomes, arguments.groups)
        group_lines.append(f"# the {len(groups)} largest groups of equal fitness in generation {g} "
                           "(Krčah 2008, Table 4.6)")
        group_lines.append("size\tshare\tfitness\tdistinct_genomes")
        group_lines += [f"{x['size']}\t{x['share']:.4f}\t{x['fitness']:.6g}\t{x['distinct_genomes']}"
                        for x in groups]
    text = format_table(rows)
    sys.stdout.write(text)
    if group_lines:
        print("\n".join(group_lines))
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write(text)
    title = f"diversity: {os.path.basename(arguments.history)} (seed {attributes.get('seed')})"
    plot(rows, arguments.output, title, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
