#!/usr/bin/env python3
"""Which physics settings are right? A convergence study of the walk evaluation.

A fixed set of creatures (genome files: hand-written, random, evolved) is evaluated with
`cambrian simulate` under a grid of physics variants (time step, Bullet substeps, solver
iterations, actuation model) and under a fine reference (1 kHz, 100 iterations). Contact
dynamics are chaotic — a walker's distance can change by a factor of three when it settles 5 ms
longer — so every creature is run K times with gravity nudged by a millionth each time (9.81,
9.81 (1 + 1e-6), ...: a perturbation far below any modelling error that lets chaos show), and a
variant is compared with the reference through the mean distance over those K runs (and its
spread), never through one run. From the exported trajectories the study also measures how long
the centre of mass stays within 5 cm of the reference's path (same nudge) in the measured phase.

    convergence.py run --cambrian build/ci/src/app/cambrian --creatures DIR [--creatures DIR]
        --out runs/convergence
    convergence.py report --out runs/convergence [--figure convergence.png]

`run` skips evaluations whose results are already in OUT/results.tsv (an interrupted study
continues). `report` prints a Markdown table per variant: the median and 90th percentile of the
relative error of the mean distance, the share of creatures within 10 % of the reference, the
share that *agree* with it (within 10 % or within two standard errors of the difference of the
means: a creature whose own chaos spreads its distance cannot be pinned closer), the median
time the path stays with the reference's under the same nudge (for the reference itself: how
long a nudged run stays with the unnudged one — chaos alone), failures, and the cost per
evaluation relative to the variant named `default`. Exit codes: 0 ok, 2 usage, 4 bad input.
"""

import argparse
import concurrent.futures
import csv
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from animate import TrajectoryError, load_trajectory  # noqa: E402

MEASURE_PHASE = 3  # EvalPhase::measure
FLOOR = 0.1  # m: distances below this are compared as if they were 0.1 m (non-walkers)
TOLERANCE = 0.10  # relative error of the mean distance counted as converged
PATH_LIMIT = 0.05  # m: the path has left the reference's once farther than this
P90_LIMIT = 0.30  # converged: 90th-percentile relative error at most this ...
AGREE_LIMIT = 0.90  # ... and at least this share of the creatures agree

# name -> settings; "reference" is the fine solution, "default" today's defaults
VARIANTS = {
    "reference": {"physics.time_step": "0.001", "physics.substeps": "1", "physics.solver_iterations": "100"},
    "default": {},
    "240Hz x2, 20 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "2", "physics.solver_iterations": "20"},
    "240Hz x2, 10 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "2", "physics.solver_iterations": "10"},
    "240Hz x1, 50 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "1", "physics.solver_iterations": "50"},
    "240Hz x1, 20 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "1", "physics.solver_iterations": "20"},
    "240Hz x1, 10 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "1", "physics.solver_iterations": "10"},
    "240Hz x1, 5 it": {"physics.time_step": "0.004166666666666667", "physics.substeps": "1", "physics.solver_iterations": "5"},
    "480Hz x1, 10 it": {"physics.time_step": "0.0020833333333333333", "physics.substeps": "1", "physics.solver_iterations": "10"},
    "480Hz x1, 20 it": {"physics.time_step": "0.0020833333333333333", "physics.substeps": "1", "physics.solver_iterations": "20"},
    "1kHz x1, 10 it": {"physics.time_step": "0.001", "physics.substeps": "1", "physics.solver_iterations": "10"},
    "1kHz x1, 20 it": {"physics.time_step": "0.001", "physics.substeps": "1", "physics.solver_iterations": "20"},
    "240Hz x2, 20 it, tol 1e-3": {"physics.time_step": "0.004166666666666667", "physics.substeps": "2", "physics.solver_iterations": "20", "physics.solver_tolerance": "0.001"},
    "240Hz x2, 20 it, tol 1e-4": {"physics.time_step": "0.004166666666666667", "physics.substeps": "2", "physics.solver_iterations": "20", "physics.solver_tolerance": "0.0001"},
    "240Hz x1, 20 it, tol 1e-3": {"physics.time_step": "0.004166666666666667", "physics.substeps": "1", "physics.solver_iterations": "20", "physics.solver_tolerance": "0.001"},
    "60Hz x1, 20 it": {"physics.time_step": "0.016666666666666666", "physics.substeps": "1", "physics.solver_iterations": "20"},
    "60Hz x4, 20 it": {"physics.time_step": "0.016666666666666666", "physics.substeps": "4", "physics.solver_iterations": "20"},
}
VARIANTS["240Hz x1, 10 it, tol 1e-3"] = {**VARIANTS["240Hz x1, 10 it"], "physics.solver_tolerance": "0.001"}
# one Bullet step a time step, at rates between 240 Hz and 480 Hz, at the default tolerance
for rate in (300, 360):
    VARIANTS[f"{rate}Hz x1, 20 it, tol 1e-4"] = {
        "physics.time_step": repr(1 / rate), "physics.substeps": "1",
        "physics.solver_iterations": "20", "physics.solver_tolerance": "0.0001"}
# the fine solution at the default's controller rate: the controller (the creature's brain, whose
# signals take one time step per neuron) runs at 240 Hz as in every 1/240 s variant, and only the
# physics is refined (5 Bullet steps of 1/1200 s per time step, 100 iterations)
VARIANTS["reference, 240 Hz controller"] = {
    "physics.time_step": "0.004166666666666667", "physics.substeps": "5",
    "physics.solver_iterations": "100"}
# the same, twice as fine: is the reference itself converged?
VARIANTS["reference, 240 Hz controller, x10"] = {
    **VARIANTS["reference, 240 Hz controller"], "physics.substeps": "10"}
# more substeps or a tighter solve at the default's controller rate
for substeps in (3, 4):
    VARIANTS[f"240Hz x{substeps}, 20 it, tol 1e-4"] = {
        "physics.time_step": "0.004166666666666667", "physics.substeps": str(substeps),
        "physics.solver_iterations": "20", "physics.solver_tolerance": "0.0001"}
VARIANTS["240Hz x1, 20 it, tol 1e-4"] = {
    "physics.time_step": "0.004166666666666667", "physics.substeps": "1",
    "physics.solver_iterations": "20", "physics.solver_tolerance": "0.0001"}
VARIANTS["240Hz x2, 50 it, tol 1e-5"] = {
    "physics.time_step": "0.004166666666666667", "physics.substeps": "2",
    "physics.solver_iterations": "50", "physics.solver_tolerance": "0.00001"}
# the joint damping model of before physics.implicit_damping, at the default steps
VARIANTS["default, explicit damping"] = {"physics.implicit_damping": "false",
                                          "physics.solver_tolerance": "0.0001"}
# a variant that names no tolerance iterates fully (0), whatever today's default
for settings in VARIANTS.values():
    if settings:
        settings.setdefault("physics.solver_tolerance", "0")
# the ground contact model of before physics.ground_contact_corners, at the default steps
VARIANTS["240Hz x1, 20 it, tol 1e-3, one new ground point a step"] = {
    **VARIANTS["240Hz x1, 20 it, tol 1e-3"], "physics.ground_contact_corners": "false"}
VARIANTS["240Hz x2, 20 it, tol 1e-3, one new ground point a step"] = {
    **VARIANTS["240Hz x2, 20 it, tol 1e-3"], "physics.ground_contact_corners": "false"}
# the actuation model: explicit torques (Sims) against their own reference
TORQUE = {"physics.actuation": "torque"}
for name in ("reference", "240Hz x2, 20 it", "240Hz x1, 10 it"):
    VARIANTS["torque: " + name] = {**VARIANTS[name], **TORQUE}

RESULT_FIELDS = ["creature", "variant", "nudge", "status", "fitness", "steps", "wall_seconds", "trajectory"]


class StudyError(Exception):
    """A bad input; the message names the file or the value."""


GRAVITY = 9.81


def nudges(count):
    """The K nudges: 0, 1, ..., K - 1 millionths of gravity."""
    return list(range(count))


def nudged_gravity(nudge):
    return repr(GRAVITY * (1 + 1e-6 * nudge))


def trajectory_name(creature, variant, nudge):
    slug = re.sub(r"[^A-Za-z0-9]+", "_", variant).strip("_")
    return f"{creature}__{slug}__{nudge}.h5"


def simulate(cambrian, genome, variant, nudge, trajectory, extra):
    """One evaluation: returns (status, fitness, steps, wall seconds)."""
    command = [cambrian, "simulate", "--genome", genome, "--physics.gravity", nudged_gravity(nudge),
               "--export", trajectory, "--frame-rate", "20"]
    for key, value in {**extra, **VARIANTS[variant]}.items():
        command += ["--" + key, value]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise StudyError(f"{' '.join(command)}: exit {done.returncode}: {done.stderr.strip()}")
    fields = {}
    for line in done.stdout.splitlines():
        parts = line.split(None, 1)
        if len(parts) == 2:
            fields.setdefault(parts[0], parts[1])
    status = fields["status"].split(":")[0]
    wall = float(fields["wall"].split()[1])
    return status, float(fields["fitness"]), int(fields["steps"]), wall


def read_results(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as file:
        return list(csv.DictReader(file, delimiter="\t"))


def run(args):
    genomes = {}
    for directory in args.creatures:
        if not os.path.isdir(directory):
            raise StudyError(f"--creatures {directory}: not a directory")
        for name in sorted(os.listdir(directory)):
            if name.endswith(".genome"):
                genomes.setdefault(name[:-len(".genome")], os.path.join(directory, name))
    if not genomes:
        raise StudyError(f"{', '.join(args.creatures)}: no *.genome files")
    variants = args.variant or list(VARIANTS)
    for name in variants:
        if name not in VARIANTS:
            raise StudyError(f"--variant {name!r}: not one of {', '.join(VARIANTS)}")
    extra = dict(item.split("=", 1) for item in args.set)
    os.makedirs(os.path.join(args.out, "trajectories"), exist_ok=True)
    results_path = os.path.join(args.out, "results.tsv")
    done = {(r["creature"], r["variant"], r["nudge"]) for r in read_results(results_path)}
    jobs = [(c, v, n) for c in genomes for v in variants for n in nudges(args.perturbations)
            if (c, v, str(n)) not in done]
    new_file = not os.path.exists(results_path)
    with open(results_path, "a", newline="") as file, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        writer = csv.writer(file, delimiter="\t")
        if new_file:
            writer.writerow(RESULT_FIELDS)
        futures = {}
        for creature, variant, nudge in jobs:
            trajectory = os.path.join(args.out, "trajectories", trajectory_name(creature, variant, nudge))
            genome = genomes[creature]
            futures[pool.submit(simulate, args.cambrian, genome, variant, nudge, trajectory, extra)] = (
                creature, variant, nudge, trajectory)
        for k, future in enumerate(concurrent.futures.as_completed(futures)):
            creature, variant, nudge, trajectory = futures[future]
            status, fitness, steps, wall = future.result()
            writer.writerow([creature, variant, str(nudge), status, repr(fitness), steps, wall,
                             os.path.relpath(trajectory, args.out)])
            file.flush()
            if not args.quiet and (k + 1) % 50 == 0:
                print(f"{k + 1}/{len(jobs)} evaluations", flush=True)


def measured_path(trajectory):
    """The centre of mass's horizontal path in the measured phase, time from its start."""
    measured = trajectory["phase"] == MEASURE_PHASE
    time = trajectory["time"][measured]
    com = trajectory["center_of_mass"][measured][:, :2]
    return time - time[0], com


def time_with_reference(path, reference, limit=PATH_LIMIT):
    """Seconds from the start of the measured phase until the path first leaves the reference's
    by more than `limit` m (the whole phase when it never does). Paths are compared relative to
    their own start."""
    time, com = path
    ref_time, ref_com = reference
    end = min(time[-1], ref_time[-1])
    if end <= 0:
        return 0.0
    grid = np.arange(0.0, end + 1e-9, 0.05)
    here = np.stack([np.interp(grid, time, com[:, i] - com[0, i]) for i in range(2)], axis=1)
    there = np.stack([np.interp(grid, ref_time, ref_com[:, i] - ref_com[0, i]) for i in range(2)], axis=1)
    apart = np.linalg.norm(here - there, axis=1) > limit
    return float(grid[np.argmax(apart)]) if apart.any() else float(end)


def relative_error(mean, reference_mean, floor=FLOOR):
    """|mean - reference| relative to the reference distance (at least `floor` m)."""
    return abs(mean - reference_mean) / max(abs(reference_mean), floor)


def agrees(values, reference_values, tolerance=TOLERANCE, floor=FLOOR):
    """Whether a variant's mean distance agrees with the reference's: within `tolerance` of it,
    or within two standard errors of the difference (the runs' own chaos)."""
    values, reference_values = np.asarray(values, float), np.asarray(reference_values, float)
    difference = abs(values.mean() - reference_values.mean())
    standard_error = np.sqrt(values.var(ddof=1) / len(values) +
                             reference_values.var(ddof=1) / len(reference_values)) \
        if len(values) > 1 and len(reference_values) > 1 else 0.0
    return bool(difference <= max(tolerance * max(abs(reference_values.mean()), floor),
                                  2 * standard_error))


def summarise(rows, out_dir, load_paths=True, reference_name="reference"):
    """Per variant: the aggregate figures (dicts) against the variant `reference_name`, and per
    creature the reference figures."""
    by = {}
    for row in rows:
        fitness = float(row["fitness"]) if row["status"] == "ok" else 0.0
        by.setdefault((row["creature"], row["variant"]), []).append((int(row["nudge"]), row, fitness))
    creatures = sorted({c for c, _ in by})
    reference = {}
    for creature in creatures:
        runs = by.get((creature, reference_name), [])
        if runs:
            values = np.array([f for _, _, f in runs])
            reference[creature] = {"mean": float(values.mean()), "spread": float(values.std()),
                                   "runs": {n: r for n, r, _ in runs}}
    torque_reference = {c: by.get((c, "torque: reference")) for c in creatures}
    default_cost = np.median([float(r["wall_seconds"]) for _, r, _ in sum(
        (by.get((c, "default"), []) for c in creatures), [])] or [np.nan])
    summary = []
    variants = [v for v in VARIANTS if any((c, v) in by for c in creatures)]
    for variant in variants:
        errors, horizons, failed, costs, spreads, agree = [], [], 0, [], [], []
        for creature in creatures:
            runs = by.get((creature, variant))
            torque = variant.startswith("torque:")
            ref_runs = torque_reference[creature] if torque else by.get((creature, reference_name))
            if not runs or not ref_runs:
                continue
            values = np.array([f for _, _, f in runs])
            ref_values = np.array([f for _, _, f in ref_runs])
            errors.append(relative_error(values.mean(), ref_values.mean()))
            spreads.append(ref_values.std() / max(abs(ref_values.mean()), FLOOR))
            agree.append(agrees(values, ref_values))
            failed += sum(1 for _, r, _ in runs if r["status"] != "ok")
            costs += [float(r["wall_seconds"]) for _, r, _ in runs]
            if load_paths:
                # the reference against itself: each nudge against the unnudged run (how soon
                # chaos alone parts two paths)
                ref_by_nudge = {n: r for n, r, _ in ref_runs}
                own = variant in (reference_name, "torque: reference")
                for nudge, row, _ in runs:
                    if own and nudge == 0:
                        continue
                    ref_row = ref_by_nudge.get(0 if own else nudge)
                    if ref_row is None or row["status"] != "ok" or ref_row["status"] != "ok":
                        continue
                    try:
                        here = measured_path(load_trajectory(os.path.join(out_dir, row["trajectory"])))
                        there = measured_path(load_trajectory(os.path.join(out_dir, ref_row["trajectory"])))
                    except TrajectoryError as error:
                        raise StudyError(str(error)) from error
                    horizons.append(time_with_reference(here, there))
        if not errors:
            continue
        errors = np.array(errors)
        summary.append({
            "variant": variant,
            "creatures": len(errors),
            "median_error": float(np.median(errors)),
            "p90_error": float(np.percentile(errors, 90)),
            "within": float(np.mean(errors <= TOLERANCE)),
            "agree": float(np.mean(agree)),
            "reference_spread": float(np.median(spreads)),
            "path_seconds": float(np.median(horizons)) if horizons else float("nan"),
            "failed": failed,
            "cost": float(np.median(costs) / default_cost) if default_cost == default_cost else float("nan"),
        })
    return summary, reference


def bootstrap_agreement(rows, variant, reference_name, resamples, seed=1):
    """5th, 50th and 95th percentile of the share of creatures that agree with the reference
    when each creature's nudges are resampled with replacement (both the variant's and the
    reference's): how well the agreement of a few creatures is resolved."""
    by = {}
    for row in rows:
        fitness = float(row["fitness"]) if row["status"] == "ok" else 0.0
        by.setdefault((row["creature"], row["variant"]), []).append(fitness)
    creatures = sorted(c for c, v in by if v == variant and (c, reference_name) in by)
    if not creatures:
        return None
    rng = np.random.default_rng(seed)
    shares = []
    for _ in range(resamples):
        agreeing = 0
        for creature in creatures:
            values, ref_values = np.array(by[(creature, variant)]), np.array(by[(creature, reference_name)])
            agreeing += agrees(rng.choice(values, len(values)), rng.choice(ref_values, len(ref_values)))
        shares.append(agreeing / len(creatures))
    return tuple(float(q) for q in np.percentile(shares, [5, 50, 95]))


def markdown(summary):
    lines = ["| variant | creatures | median error | 90 % error | within 10 % | agree | "
             "path with reference (s) | failed runs | cost vs default |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for s in summary:
        lines.append(f"| {s['variant']} | {s['creatures']} | {100 * s['median_error']:.1f} % | "
                     f"{100 * s['p90_error']:.1f} % | {100 * s['within']:.0f} % | {100 * s['agree']:.0f} % | "
                     f"{s['path_seconds']:.2f} | {s['failed']} | {s['cost']:.2f} |")
    return "\n".join(lines)


def figure(summary, path, reference_name="reference"):
    """90th-percentile error and agreement against cost, with the convergence criterion."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8))
    panels = ((axes[0], "p90_error", 100, "90th-percentile relative error of the mean distance, %",
               100 * P90_LIMIT),
              (axes[1], "agree", 100, "creatures that agree with the reference, %", 100 * AGREE_LIMIT))
    for ax, key, scale, label, limit in panels:
        for s in summary:
            if s["variant"] in (reference_name, "torque: reference"):
                continue
            marker = "s" if s["variant"].startswith("torque") else "o"
            colour = "black" if s["variant"] == "default" else None
            ax.scatter(s["cost"], scale * s[key], marker=marker, color=colour)
            ax.annotate(s["variant"], (s["cost"], scale * s[key]), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
        ax.axhline(limit, color="grey", linestyle="--", linewidth=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("cost per evaluation, relative to the default")
        ax.set_ylabel(label)
    fig.suptitle(f"walk evaluation against the variant '{reference_name}' "
                 "(dashed: the convergence criterion)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def report(args):
    rows = read_results(os.path.join(args.out, "results.tsv"))
    if not rows:
        raise StudyError(f"{args.out}/results.tsv: no results (run the study first)")
    if args.reference not in VARIANTS:
        raise StudyError(f"--reference {args.reference!r}: not one of {', '.join(VARIANTS)}")
    summary, reference = summarise(rows, args.out, load_paths=not args.no_paths,
                                   reference_name=args.reference)
    if not reference:
        raise StudyError(f"{args.out}/results.tsv: no runs of the reference {args.reference!r}")
    print(markdown(summary))
    print()
    print("| creature | reference mean distance (m) | spread over nudges (m) |")
    print("| --- | --- | --- |")
    for creature, r in sorted(reference.items()):
        print(f"| {creature} | {r['mean']:.3f} | {r['spread']:.3f} |")
    if args.bootstrap:
        print()
        print(f"| variant | agree, 5th / 50th / 95th percentile over {args.bootstrap} resamples of the nudges |")
        print("| --- | --- |")
        for s in summary:
            spread = bootstrap_agreement(rows, s["variant"], args.reference, args.bootstrap)
            if spread:
                print(f"| {s['variant']} | {' / '.join(f'{100 * q:.0f} %' for q in spread)} |")
    if args.figure:
        figure(summary, args.figure, args.reference)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="evaluate every creature under every variant")
    r.add_argument("--cambrian", required=True, help="the cambrian binary")
    r.add_argument("--creatures", required=True, action="append",
                   help="a directory of *.genome files (repeatable)")
    r.add_argument("--out", required=True, help="results directory")
    r.add_argument("--perturbations", type=int, default=6, help="gravity nudges per creature")
    r.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="evaluations at once")
    r.add_argument("--variant", action="append", help="only this variant (repeatable)")
    r.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="a setting for every run, e.g. task.evaluation_time=5")
    r.add_argument("--quiet", action="store_true")
    p = sub.add_parser("report", help="tables (and a figure) from OUT/results.tsv")
    p.add_argument("--out", required=True)
    p.add_argument("--figure", help="write the error-against-cost figure here")
    p.add_argument("--no-paths", action="store_true", help="skip the trajectory comparison")
    p.add_argument("--bootstrap", type=int, default=0, metavar="N",
                   help="also the agreement's spread over N resamples of the nudges")
    p.add_argument("--reference", default="reference",
                   help="the variant the others are compared with (default: reference)")
    args = parser.parse_args(argv)
    if args.command == "run":
        if args.perturbations < 1 or args.jobs < 1:
            parser.error("--perturbations and --jobs must be >= 1")
        for item in args.set:
            if "=" not in item:
                parser.error(f"--set {item!r}: expected KEY=VALUE")
    return args


def main(argv=None):
    args = parse_arguments(argv)
    try:
        run(args) if args.command == "run" else report(args)
    except StudyError as error:
        print(f"convergence.py: error: {error}", file=sys.stderr)
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
