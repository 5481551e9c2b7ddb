#!/usr/bin/env python3
"""Load balance of a cambrian run across its worker ranks.

From the individuals table: evaluations and busy seconds (sum of eval_seconds) per worker_rank,
and the distribution of eval_seconds. From the generations table: utilisation per generation,
worker_busy_seconds / (workers * evaluation_span_seconds), i.e. the share of the evaluation
span the workers spent evaluating; the rest is idle time (waiting for a hand-out, or for the
slowest creature at the generation barrier). Elite copies (worker_rank -1, not evaluated) are
left out.

Prints a per-worker TSV table and a per-generation TSV table (sections headed by `# ` lines)
and draws four panels: evaluations per worker, busy seconds per worker, utilisation per
generation, histogram of eval_seconds.

    python3 analysis/load_balance.py run/history.h5 --output load_balance.png

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

PROGRAM = "load_balance"


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Per-worker load balance of a cambrian history: evaluations and busy seconds "
        "per worker_rank, utilisation per generation (busy / (workers * span)), distribution "
        "of eval_seconds; TSV on stdout and a PNG.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("history", help="history.h5 written by `cambrian evolve`")
    parser.add_argument("-o", "--output", default="load_balance.png", help="PNG to write (default: load_balance.png)")
    parser.add_argument("--table", default=None, help="also write the per-generation table to this TSV file")
    parser.add_argument("--bins", type=int, default=30, help="histogram bins for eval_seconds (default 30)")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    arguments = parser.parse_args(argv)
    if arguments.bins < 1:
        parser.error("--bins must be >= 1")
    return arguments


def per_worker(individuals):
    """dict worker_rank -> (evaluations, busy seconds, mean, max eval seconds); copies left out."""
    ranks = individuals["worker_rank"]
    seconds = individuals["eval_seconds"]
    out = {}
    for rank in np.unique(ranks[ranks >= 0]):
        mine = seconds[ranks == rank]
        out[int(rank)] = (len(mine), float(mine.sum()), float(mine.mean()), float(mine.max()))
    return out


def per_generation(individuals, generations):
    """One dict per generation: utilisation from the generations table, and the imbalance of
    busy seconds across workers (max / mean) computed from the individuals."""
    rows = []
    ranks = individuals["worker_rank"]
    for i, g in enumerate(generations["generation"]):
        workers = int(generations["workers"][i])
        span = float(generations["evaluation_span_seconds"][i])
        busy = float(generations["worker_busy_seconds"][i])
        mine = (individuals["generation"] == g) & (ranks >= 0)
        loads = [individuals["eval_seconds"][mine & (ranks == r)].sum() for r in np.unique(ranks[mine])]
        loads += [0.0] * max(0, workers - len(loads))  # a worker that got nothing
        mean_load = float(np.mean(loads)) if loads else 0.0
        rows.append({
            "generation": int(g),
            "workers": workers,
            "evaluations": int(generations["evaluations"][i]),
            "span_seconds": span,
            "busy_seconds": busy,
            "idle_seconds": float(generations["worker_idle_seconds"][i]),
            "utilisation": busy / (workers * span) if workers > 0 and span > 0 else float("nan"),
            "imbalance": max(loads) / mean_load if mean_load > 0 else float("nan"),
        })
    return rows


def plot(workers, rows, seconds, output, title, bins, dpi):
    """Evaluations and busy time per worker, utilisation per generation, eval_seconds histogram."""
    figure, axes = plt.subplots(2, 2, figsize=(10, 7))
    ranks = sorted(workers)
    x = np.arange(len(ranks))
    # evaluations per worker
    axes[0, 0].bar(x, [workers[r][0] for r in ranks], color="tab:blue")
    axes[0, 0].set_ylabel("evaluations")
    # busy seconds per worker
    axes[0, 1].bar(x, [workers[r][1] for r in ranks], color="tab:orange")
    axes[0, 1].set_ylabel("busy seconds (sum of eval_seconds)")
    for a in axes[0]:
        a.set_xticks(x)
        a.set_xticklabels([str(r) for r in ranks])
        a.set_xlabel("worker rank")
        a.grid(axis="y", alpha=0.3)
    # utilisation per generation
    a = axes[1, 0]
    a.plot([r["generation"] for r in rows], [r["utilisation"] for r in rows], marker="o")
    a.axhline(1.0, color="0.6", linestyle=":")
    a.set_ylim(0, 1.05)
    a.set_xlabel("generation")
    a.set_ylabel("utilisation busy / (workers × span)")
    a.grid(alpha=0.3)
    # distribution of eval_seconds
    a = axes[1, 1]
    a.hist(seconds * 1e3, bins=bins, color="tab:green")
    a.set_xlabel("eval_seconds (ms)")
    a.set_ylabel("evaluations")
    a.grid(alpha=0.3)
    ch.save_figure(figure, title, output, dpi)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    attributes, individuals, generations, _, _ = ch.open_or_exit(arguments.history, PROGRAM)
    workers = per_worker(individuals)
    rows = per_generation(individuals, generations)
    evaluated = individuals["worker_rank"] >= 0
    seconds = individuals["eval_seconds"][evaluated]
    # per worker
    total = sum(w[1] for w in workers.values())
    print(f"# {arguments.history}: {len(workers)} worker ranks, {int(evaluated.sum())} evaluations, "
          f"rank_count {attributes.get('rank_count')}")
    print("worker_rank\tevaluations\tbusy_seconds\tbusy_share\tmean_eval_seconds\tmax_eval_seconds")
    for rank in sorted(workers):
        n, busy, mean, peak = workers[rank]
        print(f"{rank}\t{n}\t{busy:.6g}\t{busy / total if total else 0:.4f}\t{mean:.6g}\t{peak:.6g}")
    # per generation
    columns = ["generation", "workers", "evaluations", "span_seconds", "busy_seconds", "idle_seconds",
               "utilisation", "imbalance"]
    lines = ch.tsv_lines(rows, columns)
    print("# per generation (utilisation = busy / (workers * span); imbalance = max / mean busy per worker)")
    print("\n".join(lines))
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write("\n".join(lines) + "\n")
    # eval_seconds distribution
    q = np.percentile(seconds, [0, 25, 50, 75, 100]) if len(seconds) else [float("nan")] * 5
    print(f"# eval_seconds: min {q[0]:.6g} q25 {q[1]:.6g} median {q[2]:.6g} q75 {q[3]:.6g} max {q[4]:.6g}; "
          f"overall utilisation {np.sum(generations['worker_busy_seconds']) / max(np.sum(generations['workers'] * generations['evaluation_span_seconds']), 1e-300):.4f}")
    title = f"load balance: {os.path.basename(arguments.history)} ({len(workers)} workers)"
    plot(workers, rows, seconds, arguments.output, title, arguments.bins, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
