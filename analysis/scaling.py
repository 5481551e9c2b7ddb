#!/usr/bin/env python3
"""Strong and weak scaling of cambrian from the histories of a sweep.

Give one or more directories (searched recursively for history.h5, e.g.
runs/scaling/<name>/w<W>/r<R>/history.h5 as jobs/scaling/strong.sh writes them) or history
files. Each run's worker count comes from its history (the `workers` column; rank_count - 1);
runs with the same worker count are repeats of one point.

Per run: the median generation wall time over generations >= --skip (default 1: generation 0
evaluates every creature, later ones skip the elites, and it pays the start-up), and rank 0's
measured serial share sum(rank0_serial_seconds) / sum(wall_seconds) over the same generations, and
the CPU share sum(rank0_cpu_seconds) / sum(wall_seconds): how busy rank 0 really was (a rank 0 that
busy-polled would show 100 %).
Per point: the median over repeats (min and max for the spread), then

- strong (fixed population): speedup S(p) = T(1) / T(p), efficiency E = S / p, the Amdahl
  serial fraction s fitted by least squares on speedup, S = 1 / (s + (1 - s) / p), and the
  Karp–Flatt experimentally determined serial fraction e(p) = (1/S - 1/p) / (1 - 1/p);
- weak (population proportional to workers): scaled speedup S(p) = p · T(1) / T(p)
  (Gustafson), efficiency T(1) / T(p), the serial fraction fitted by least squares on
  S = p - s (p - 1), and per point the serial fraction that reproduces it, (p - S) / (p - 1).

When the smallest worker count p0 is not 1, speedups are relative: S(p) = p0 · T(p0) / T(p).

Writes a TSV table on stdout (and --table), a Markdown table (--markdown) and one PNG with
speedup (measured, ideal, fitted curve), efficiency and the serial fractions.

    python3 analysis/scaling.py runs/scaling/strong --output scaling.png --table scaling.tsv
    python3 analysis/scaling.py runs/scaling/weak --mode weak --output weak.png

Exit codes: 0 ok, 2 usage, 4 bad input file (names it).
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

PROGRAM = "scaling"
COLUMNS = ["workers", "repeats", "population", "generations", "time_median", "time_min", "time_max",
           "speedup", "speedup_min", "speedup_max", "efficiency", "serial_fraction", "rank0_share",
           "rank0_cpu_share", "evals_per_s_per_worker"]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Speedup, efficiency, Amdahl (strong) or Gustafson (weak) fit and Karp–Flatt "
        "serial fraction from the history.h5 files of a scaling sweep; TSV / Markdown table "
        "and a PNG.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("sweep", nargs="+", help="sweep directories (searched for history.h5) or history files")
    parser.add_argument("--mode", choices=("strong", "weak"), default="strong",
                        help="strong: fixed population (Amdahl); weak: population proportional to workers (Gustafson)")
    parser.add_argument("--skip", type=int, default=1,
                        help="leave out the first SKIP generations of every run (default 1: generation 0)")
    parser.add_argument("-o", "--output", default="scaling.png", help="PNG to write (default: scaling.png)")
    parser.add_argument("--table", default=None, help="also write the TSV table to this file")
    parser.add_argument("--markdown", default=None, help="also write a Markdown table to this file")
    parser.add_argument("--title", default=None, help="plot title")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    arguments = parser.parse_args(argv)
    if arguments.skip < 0:
        parser.error("--skip must be >= 0")
    return arguments


def find_histories(paths):
    """Every history.h5 under the given directories, plus the given files, sorted."""
    found = []
    for path in paths:
        if os.path.isdir(path):
            for root, _, files in os.walk(path):
                found += [os.path.join(root, f) for f in files if f == "history.h5"]
        else:
            found.append(path)  # a missing file is reported when it is opened
    return sorted(found)


def read_run(path, skip):
    """One run's figures: workers, population, median generation time, rank 0 share, ... ;
    raises HistoryError / InputFileError naming the file."""
    with ch.History(path) as history:
        attributes = history.attributes
        g = history.generations()
    if len(g["generation"]) <= skip:
        raise ch.InputFileError(f"{path}: {len(g['generation'])} generations, none left after --skip {skip}")
    wall = g["wall_seconds"][skip:]
    population = ch.config_value(attributes, "evolution", "population")
    return {
        "path": path,
        "workers": ch.worker_count(attributes, g),
        "population": int(population) if population else int(g["count"][0]),
        "generations": len(wall),
        "time": float(np.median(wall)),
        "times": wall,
        "rank0_share": float(np.sum(g["rank0_serial_seconds"][skip:]) / np.sum(wall)) if np.sum(wall) > 0 else 0.0,
        # CPU rank 0 used over the same wall time (NaN for histories written before the column)
        "rank0_cpu_share": (float(np.sum(g["rank0_cpu_seconds"][skip:]) / np.sum(wall))
                            if "rank0_cpu_seconds" in g and np.sum(wall) > 0 else float("nan")),
        "evaluations": float(np.mean(g["evaluations"][skip:])),
        "rank0_serial": float(np.median(g["rank0_serial_seconds"][skip:])),
    }


def load_sweep(paths, skip):
    """Every run of a sweep (list of read_run dicts); raises InputFileError when there is none."""
    files = find_histories(paths)
    if not files:
        raise ch.InputFileError(f"{' '.join(paths)}: no history.h5 found")
    return [read_run(f, skip) for f in files]


def amdahl_speedup(s, p):
    """Amdahl's speedup on p workers for serial fraction s."""
    p = np.asarray(p, dtype=float)
    return 1.0 / (s + (1.0 - s) / p)


def gustafson_speedup(s, p):
    """Gustafson's scaled speedup on p workers for serial fraction s."""
    p = np.asarray(p, dtype=float)
    return p - s * (p - 1.0)


def karp_flatt(speedup, p):
    """Experimentally determined serial fraction (1/S - 1/p) / (1 - 1/p); nan at p = 1."""
    speedup, p = np.asarray(speedup, dtype=float), np.asarray(p, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(p > 1, (1.0 / speedup - 1.0 / p) / (1.0 - 1.0 / p), np.nan)


def fit_amdahl(p, speedup):
    """Serial fraction s in [0, 1] minimising the squared speedup error (grid, then refined)."""
    p, speedup = np.asarray(p, dtype=float), np.asarray(speedup, dtype=float)
    error = lambda s: np.sum((amdahl_speedup(s, p) - speedup) ** 2)  # noqa: E731
    grid = np.linspace(0.0, 1.0, 2001)
    best = grid[np.argmin([error(s) for s in grid])]
    # refine around the grid minimum (golden section)
    lo, hi = max(0.0, best - 1e-3), min(1.0, best + 1e-3)
    ratio = (np.sqrt(5.0) - 1.0) / 2.0
    for _ in range(60):
        a, b = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        if error(a) < error(b):
            hi = b
        else:
            lo = a
    return float((lo + hi) / 2.0)


def fit_gustafson(p, speedup):
    """Serial fraction s of S = p - s (p - 1) by linear least squares, clipped to [0, 1]."""
    p, speedup = np.asarray(p, dtype=float), np.asarray(speedup, dtype=float)
    x = p - 1.0
    if np.sum(x * x) == 0:
        return 0.0
    return float(np.clip(np.sum((p - speedup) * x) / np.sum(x * x), 0.0, 1.0))


def points(runs, mode="strong"):
    """(rows, fitted serial fraction, base workers): one row per worker count, COLUMNS keys."""
    by_workers = {}
    for run in runs:
        by_workers.setdefault(run["workers"], []).append(run)
    rows = []
    for workers in sorted(by_workers):
        group = by_workers[workers]
        times = np.array([r["time"] for r in group])
        rows.append({
            "workers": workers,
            "repeats": len(group),
            "population": int(np.median([r["population"] for r in group])),
            "generations": int(np.sum([r["generations"] for r in group])),
            "time_median": float(np.median(times)),
            "time_min": float(times.min()),
            "time_max": float(times.max()),
            "rank0_share": float(np.median([r["rank0_share"] for r in group])),
            "rank0_cpu_share": float(np.median([r.get("rank0_cpu_share", float("nan")) for r in group])),
            "evals_per_s_per_worker": float(np.median([r["evaluations"] / r["time"] / workers for r in group])),
        })
    base = rows[0]
    p0, t0 = base["workers"], base["time_median"]
    for row in rows:
        p = row["workers"]
        if mode == "strong":
            row["speedup"] = p0 * t0 / row["time_median"]
            row["speedup_min"] = p0 * t0 / row["time_max"]
            row["speedup_max"] = p0 * t0 / row["time_min"]
            row["efficiency"] = row["speedup"] / p
            row["serial_fraction"] = float(karp_flatt(row["speedup"], p))
        else:
            row["speedup"] = p * t0 / row["time_median"]
            row["speedup_min"] = p * t0 / row["time_max"]
            row["speedup_max"] = p * t0 / row["time_min"]
            row["efficiency"] = t0 / row["time_median"]
            row["serial_fraction"] = (p - row["speedup"]) / (p - 1.0) if p > 1 else float("nan")
    p = [r["workers"] for r in rows]
    s = [r["speedup"] for r in rows]
    fitted = fit_amdahl(p, s) if mode == "strong" else fit_gustafson(p, s)
    return rows, fitted, p0


def check_sweep(runs, mode):
    """Warnings (list of str) about sweeps that do not look like the chosen mode."""
    warnings = []
    populations = {r["population"] for r in runs}
    if mode == "strong" and len(populations) > 1:
        warnings.append(f"strong mode but the runs have different populations {sorted(populations)}")
    if mode == "weak":
        ratios = {round(r["population"] / r["workers"], 6) for r in runs}
        if len(ratios) > 1:
            warnings.append(f"weak mode but population / workers differs between runs: {sorted(ratios)}")
    return warnings


def format_tsv(rows):
    """TSV text of the point rows."""
    lines = ["\t".join(COLUMNS)]
    for row in rows:
        lines.append("\t".join(f"{row[c]:.6g}" if isinstance(row[c], float) else str(row[c]) for c in COLUMNS))
    return "\n".join(lines) + "\n"


def format_markdown(rows, fitted, mode, skip):
    """A Markdown table of the points and the fit."""
    serial = "Karp–Flatt e" if mode == "strong" else "(p − S)/(p − 1)"
    lines = [f"| workers | repeats | population | generation time median (s) | min..max (s) | speedup | "
             f"efficiency | {serial} | rank 0 serial share | rank 0 CPU share |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        kf = "–" if np.isnan(r["serial_fraction"]) else f"{r['serial_fraction']:.4f}"
        cpu = r.get("rank0_cpu_share", float("nan"))
        cpu = "–" if np.isnan(cpu) else f"{100 * cpu:.3f} %"
        lines.append(f"| {r['workers']} | {r['repeats']} | {r['population']} | {r['time_median']:.4f} | "
                     f"{r['time_min']:.4f}..{r['time_max']:.4f} | {r['speedup']:.3f} | {100 * r['efficiency']:.1f} % | "
                     f"{kf} | {100 * r['rank0_share']:.3f} % | {cpu} |")
    law = "Amdahl" if mode == "strong" else "Gustafson"
    lines.append("")
    lines.append(f"{law} fit: serial fraction s = {fitted:.5f} (generations >= {skip}; medians over repeats).")
    return "\n".join(lines) + "\n"


def plot(rows, fitted, mode, output, title, dpi):
    """Speedup (measured, ideal, fitted), efficiency, and serial fractions against workers."""
    p = np.array([r["workers"] for r in rows], dtype=float)
    speedup = np.array([r["speedup"] for r in rows])
    figure, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    curve_p = np.geomspace(1, max(p.max(), 2), 200)
    # speedup with ideal and the fitted law
    a = axes[0]
    a.errorbar(p, speedup, yerr=[speedup - [r["speedup_min"] for r in rows], [r["speedup_max"] for r in rows] - speedup],
               marker="o", capsize=4, linestyle="none", label="measured (median, min..max)")
    a.plot(curve_p, curve_p, color="0.5", linestyle=":", label="ideal")
    law = amdahl_speedup(fitted, curve_p) if mode == "strong" else gustafson_speedup(fitted, curve_p)
    a.plot(curve_p, law, color="tab:red", label=f"{'Amdahl' if mode == 'strong' else 'Gustafson'} s = {fitted:.4f}")
    a.set_xscale("log", base=2)
    a.set_yscale("log", base=2)
    a.set_xlabel("workers")
    a.set_ylabel("speedup" if mode == "strong" else "scaled speedup")
    a.legend(fontsize="small")
    # efficiency
    a = axes[1]
    a.plot(p, [r["efficiency"] for r in rows], marker="o")
    a.axhline(1.0, color="0.5", linestyle=":")
    a.set_xscale("log", base=2)
    a.set_ylim(0, 1.1)
    a.set_xlabel("workers")
    a.set_ylabel("efficiency")
    # serial fractions: experimental, rank 0 measured, fitted
    a = axes[2]
    a.plot(p, [r["serial_fraction"] for r in rows], marker="o",
           label="Karp–Flatt e(p)" if mode == "strong" else "(p - S)/(p - 1)")
    a.plot(p, [r["rank0_share"] for r in rows], marker="s", label="rank 0 serial share (measured)")
    a.axhline(fitted, color="tab:red", linestyle="--", label="fitted s")
    a.set_xscale("log", base=2)
    a.set_xlabel("workers")
    a.set_ylabel("serial fraction")
    a.legend(fontsize="small")
    for a in axes:
        a.grid(alpha=0.3, which="both")
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        runs = load_sweep(arguments.sweep, arguments.skip)
    except (ch.HistoryError, ch.InputFileError, KeyError, OSError) as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return ch.EXIT_INPUT
    for warning in check_sweep(runs, arguments.mode):
        print(f"{PROGRAM}: warning: {warning}", file=sys.stderr)
    rows, fitted, base = points(runs, arguments.mode)
    # tables
    text = format_tsv(rows)
    law = "amdahl" if arguments.mode == "strong" else "gustafson"
    sys.stdout.write(f"# {arguments.mode} scaling, {len(runs)} runs, generations >= {arguments.skip}, "
                     f"speedup relative to {base} worker(s); serial_fraction = "
                     f"{'Karp-Flatt' if arguments.mode == 'strong' else '(p - S)/(p - 1)'}\n")
    sys.stdout.write(text)
    print(f"# {law}_serial_fraction {fitted:.6f}")
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write(text)
    if arguments.markdown:
        with open(arguments.markdown, "w") as handle:
            handle.write(format_markdown(rows, fitted, arguments.mode, arguments.skip))
    title = arguments.title or f"{arguments.mode} scaling: {', '.join(arguments.sweep)}"
    plot(rows, fitted, arguments.mode, arguments.output, title, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
