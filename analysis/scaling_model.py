#!/usr/bin/env python3
"""A discrete-event model of one cambrian generation under MPI, to project scaling beyond the
machines we can measure on.

The model (docs/scaling.md):
- rank 0 holds E evaluations of cost c_1 >= c_2 >= ... (largest first, as MpiScheduler sends
  them) and W workers; it hands out one evaluation at a time, and each hand-out occupies rank 0
  for a time L (so hand-outs are serial on rank 0);
- every worker holds K evaluations, handed out round by round; each result is answered with
  the next for that worker, in the order the results arrive (self-scheduling). A worker starts
  its queued evaluation as soon as it finishes one, so the hand-out time is hidden while
  L < (K - 1) c. K is MpiScheduler's (DispatchPace): enough to queue 4 ms of work,
  1 + ceil(4 ms / mean cost), at least 2 and at most 64, and never more than 1 + (evaluations
  left to hand out) / (4 W). So creatures of 4 ms or more are held two at a time and, in the
  tail of the generation (fewer than 4 per worker left), one at a time, so none waits behind a
  long evaluation while others idle; creatures under 8 ms keep two to the end and go out in
  the order given (MpiScheduler's id order), longer ones largest first. --in-flight K fixes K
  instead (with the same tail rule);
- each evaluation occupies its worker for c + o, o a per-evaluation overhead outside the
  measured eval_seconds (receiving and decoding the request, sending the result);
- the generation ends when the last evaluation is done (the barrier), and rank 0 then spends
  its serial time S0 (breeding, statistics, history append, checkpoint) before the next one:
      T(W) = S0 + span(W);   speedup S(W) = T(1) / T(W);   efficiency S(W) / W.

Calibration, from a history (--history) or from parameters:
- per-evaluation costs: the empirical distribution of eval_seconds (evaluated rows only),
  resampled with replacement, or lognormal with --cost-mean and --cost-cv;
- S0: median rank0_serial_seconds over generations >= 1;
- L: rank 0's measured time per hand-out, rank0_dispatch_seconds / evaluations, median over
  generations (0 for a one-rank run; for older histories without that column, the upper bound
  (rank0_cpu_seconds - rank0_serial_seconds) / evaluations, which includes rank 0's wake-ups);
- o: the measured evaluation span of each generation minus the span this model gives with o = 0
  for that generation's own costs, divided by the evaluations per worker (E / W); median over
  generations. It holds whatever keeps a worker from evaluating that queuing does not hide
  (message and decoding time, waiting for a core on a shared machine);
- the share of the population evaluated per generation (elites are not): evaluations / count.

Projects speedup and efficiency for populations --populations (default 100 300 1000) and worker
counts 1, 2, 4, ... --max-workers (default 1024), naming for each point what bounds the
generation time: `work` (total cost / W), `dispatch` (rank 0 handing out E evaluations, E·L),
`barrier` (even with instant hand-outs the generation is over 25 % longer than total cost / W:
few evaluations per worker, the slowest creature), or `serial` (S0).
With --sweep, compares the model with the measured points of a sweep (model vs measured).

Islands (--island-workers w): from 2w workers on, the workers form W / w islands of w workers
each (each island's breeding rank besides them), every island breeding a population of its own
(--populations are per island). Each island's generations last as the model above gives for w
workers; after a migration event (every --interval generations, --topology ring, full or random
as [islands] does) an island breeds its next generation only once its sources have finished the
generation whose migrants it takes in, one interval earlier (archipelago_time). Speedup is the
archipelago's throughput against one island on one worker: K * T(1) / T_archipelago; the bound
`migration` means the waits for sources add more than 10 % to an island's own generation time.

Steady state (steady_time, evolution.mode = steady_state): the same hand-outs and queues without
the barrier: after each result rank 0 hands out the next creature to the worker holding fewest,
at most P / 2 out in all; after every P results it spends S0 (the history row), while the
workers go on with what they hold; the first generation is waited for (breeding starts once it
is in) and left out of the time per generation. jobs/bench/steady_state_scaling.sh compares it
with measured runs.

    python3 analysis/scaling_model.py --history runs/scaling/s/w1/r1/history.h5 --output model.png
    python3 analysis/scaling_model.py --cost-mean 0.01 --serial 0.002 --latency 1e-4 --output model.png
    python3 analysis/scaling_model.py --history h.h5 --sweep runs/scaling/s --output model.png

Exit codes: 0 ok, 2 usage, 4 bad input file.
"""

import argparse
import heapq
from collections import deque
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cambrian_history as ch  # noqa: E402
import scaling  # noqa: E402

PROGRAM = "scaling_model"
LIMITS = ("work", "dispatch", "barrier", "serial", "migration")
BARRIER_SLACK = 1.25  # zero-latency span / (total cost / W) above which the barrier is the bound
MARKERS = {"work": "o", "dispatch": "s", "barrier": "^", "serial": "D", "migration": "v", "cap": "x"}
MIGRATION_SLACK = 1.1  # archipelago / island generation time above which migration is the bound
ISLAND_GENERATIONS = 100  # generations simulated per archipelago point
ISLAND_SAMPLES = 20  # island generation times an archipelago point draws from (at least)
IN_FLIGHT = 2  # evaluations MpiScheduler keeps at each worker at least (src/parallel/scheduler.hpp)
QUEUE_WHILE_REMAINING = 4  # one more for every this many per worker left to hand out
QUEUED_SECONDS = 0.004  # DispatchPace::kQueuedSeconds: work a worker holds queued
SHORT_SECONDS = 2 * QUEUED_SECONDS  # DispatchPace::kShortSeconds
MAX_HELD = 64  # DispatchPace::kMaxHeld


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Discrete-event model of a cambrian generation (self-scheduling, largest "
        "first, one latency per hand-out, rank 0 serial time, generation barrier), calibrated "
        "from a history or from parameters; projects speedup and efficiency to --max-workers "
        "and compares with a measured sweep.",
        epilog="exit codes: 0 ok, 2 usage, 4 bad input file",
    )
    parser.add_argument("--history", default=None, help="calibrate from this history.h5")
    parser.add_argument("--sweep", nargs="*", default=None,
                        help="sweep directories or histories to compare with (and to calibrate from, "
                        "the run with the fewest workers, when --history is not given)")
    parser.add_argument("--mode", choices=("strong", "weak"), default="strong",
                        help="how the --sweep was run: speedups of the comparison are fixed-size (strong) or scaled (weak)")
    parser.add_argument("--cost-mean", type=float, default=None, help="mean evaluation cost, s (instead of the history's)")
    parser.add_argument("--cost-cv", type=float, default=0.0, help="coefficient of variation of the lognormal cost (default 0)")
    parser.add_argument("--serial", type=float, default=None, help="rank 0 serial seconds per generation")
    parser.add_argument("--latency", type=float, default=None, help="seconds of rank 0 per hand-out")
    parser.add_argument("--overhead", type=float, default=None,
                        help="seconds of worker time per evaluation outside eval_seconds")
    parser.add_argument("--in-flight", type=int, default=None,
                        help="evaluations each worker holds at once (default: as MpiScheduler, from the mean cost)")
    parser.add_argument("--evaluated-share", type=float, default=None,
                        help="share of the population evaluated per generation (default: from the history, else 0.8)")
    parser.add_argument("--populations", type=int, nargs="+", default=[100, 300, 1000], help="populations to project (default 100 300 1000)")
    parser.add_argument("--max-workers", type=int, default=1024, help="largest worker count, powers of 2 up to it (default 1024)")
    parser.add_argument("--samples", type=int, default=5, help="simulated generations per point, averaged (default 5)")
    parser.add_argument("--skip", type=int, default=1, help="generations left out of the calibration and the sweep (default 1)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the cost resampling (default 1)")
    parser.add_argument("--island-workers", type=int, default=None,
                        help="islands of this many workers each from twice as many workers on (default: one population)")
    parser.add_argument("--interval", type=int, default=10, help="islands: generations between migrations (default 10)")
    parser.add_argument("--topology", choices=("ring", "full", "random"), default="ring",
                        help="islands: where migrants go (default ring)")
    parser.add_argument("--steady-state", action="store_true",
                        help="project steady states (evolution.mode = steady_state), islands of them "
                        "with --island-workers")
    parser.add_argument("-o", "--output", default="scaling_model.png", help="PNG to write (default: scaling_model.png)")
    parser.add_argument("--table", default=None, help="also write the projection table to this TSV file")
    parser.add_argument("--dpi", type=int, default=120, help="resolution of the PNG (default: 120)")
    arguments = parser.parse_args(argv)
    if arguments.history is None and not arguments.sweep and arguments.cost_mean is None:
        parser.error("give --history, --sweep or --cost-mean")
    for name in ("cost_mean", "serial", "latency", "overhead"):
        value = getattr(arguments, name)
        if value is not None and value < 0:
            parser.error(f"--{name.replace('_', '-')} must be >= 0")
    if (arguments.island_workers is not None and arguments.island_workers < 1) or arguments.interval < 1:
        parser.error("--island-workers and --interval must be >= 1")
    if arguments.max_workers < 1 or arguments.samples < 1 or arguments.cost_cv < 0 or (arguments.in_flight is not None and arguments.in_flight < 1):
        parser.error("--max-workers, --samples and --in-flight must be >= 1, --cost-cv >= 0")
    return arguments


def held(mean, remaining, workers, in_flight=None):
    """Evaluations a worker holds when they cost `mean` on average and `remaining` are left to
    hand out (MpiScheduler's DispatchPace::held); `in_flight` fixes the depth instead."""
    share = 1 + remaining // (QUEUE_WHILE_REMAINING * workers)
    if in_flight is not None:
        return in_flight if share > 1 else 1
    depth = IN_FLIGHT
    if mean > 0:
        depth = max(min(1 + int(np.ceil(QUEUED_SECONDS / mean)), MAX_HELD), IN_FLIGHT)
    if 0 < mean < SHORT_SECONDS:
        share = max(share, IN_FLIGHT)
    return min(depth, share)


def simulate_span(costs, workers, latency, in_flight=None, overhead=0.0):
    """Evaluation span of one generation: costs handed out one at a time (largest first, short
    ones in the order given), each hand-out taking `latency` of rank 0; every worker holds
    held(...) evaluations, handed out round by round, then each result is answered with the
    next; an evaluation occupies its worker for cost + overhead."""
    order = np.asarray(costs, dtype=float)
    if len(order) == 0:
        return 0.0
    mean = float(np.mean(order))
    if not 0 < mean < SHORT_SECONDS:
        order = np.sort(order)[::-1]
    rank0_free = 0.0
    queues = [deque() for _ in range(workers)]  # (arrival time, cost) handed to each worker
    holding = [0] * workers  # evaluations at each worker, running or queued
    handed = 0

    def depth():
        return held(mean, len(order) - handed, workers, in_flight)

    def hand(worker, ready):
        nonlocal rank0_free, handed
        rank0_free = max(rank0_free, ready) + latency
        queues[worker].append((rank0_free, order[handed]))
        handed += 1
        holding[worker] += 1

    # round by round: every worker has its first evaluation before any gets a second
    for round_ in range(1, depth() + 1):
        for worker in range(workers):
            if handed < len(order) and holding[worker] < min(round_, depth()):
                hand(worker, 0.0)
    # each worker starts its first; every finish is answered, in finishing order
    finishes = []
    for worker in range(workers):
        if queues[worker]:
            arrival, cost = queues[worker].popleft()
            heapq.heappush(finishes, (arrival + cost + overhead, worker))
    span = 0.0
    while finishes:
        done, worker = heapq.heappop(finishes)
        span = max(span, done)
        holding[worker] -= 1
        while handed < len(order) and holding[worker] < depth():
            hand(worker, done)
        if queues[worker]:
            arrival, cost = queues[worker].popleft()
            heapq.heappush(finishes, (max(done, arrival) + cost + overhead, worker))
    return span


def generation_time(costs, workers, latency, serial, in_flight=None, overhead=0.0):
    """T(W) = rank 0 serial time + evaluation span."""
    return serial + simulate_span(costs, workers, latency, in_flight, overhead)


def limit_of(costs, workers, latency, serial, overhead=0.0):
    """What bounds the generation: the largest of total cost / W (`work`), E·L (`dispatch`),
    S0 (`serial`) and `barrier`: the span with instant hand-outs, counted only when it is more
    than BARRIER_SLACK above total cost / W (whole evaluations per worker, the slowest creature)."""
    work = (float(np.sum(costs)) + overhead * len(costs)) / workers
    span = simulate_span(costs, workers, 0.0, overhead=overhead)
    bounds = {"work": work, "dispatch": len(costs) * latency, "serial": serial,
              "barrier": span if span > BARRIER_SLACK * work else 0.0}
    return max(bounds, key=lambda k: bounds[k])


class Calibration:
    """Per-evaluation costs (a sampler), serial seconds, latency and evaluated share."""

    def __init__(self, costs=None, cost_mean=None, cost_cv=0.0, serial=0.0, latency=0.0, evaluated_share=0.8,
                 source="parameters", overhead=0.0, in_flight=None):
        self.costs = None if costs is None else np.asarray(costs, dtype=float)
        self.cost_mean, self.cost_cv = cost_mean, cost_cv
        self.serial, self.latency, self.evaluated_share, self.source = serial, latency, evaluated_share, source
        self.overhead, self.in_flight = overhead, in_flight

    def time(self, costs, workers):
        """Modelled generation time of `costs` on `workers`."""
        return generation_time(costs, workers, self.latency, self.serial, self.in_flight, self.overhead)

    def limit(self, costs, workers):
        """What bounds that generation (see limit_of)."""
        return limit_of(costs, workers, self.latency, self.serial, self.overhead)

    def draw(self, count, rng):
        """`count` evaluation costs: resampled from the history, or lognormal (or constant)."""
        if self.costs is not None and self.cost_mean is None:
            return rng.choice(self.costs, size=count, replace=True)
        if self.cost_cv == 0:
            return np.full(count, self.cost_mean)
        sigma2 = np.log(1.0 + self.cost_cv ** 2)
        return rng.lognormal(np.log(self.cost_mean) - sigma2 / 2.0, np.sqrt(sigma2), size=count)

    def describe(self):
        mean = self.cost_mean if self.cost_mean is not None else float(np.mean(self.costs))
        return (f"calibration ({self.source}): mean cost {mean:.6g} s, rank 0 serial {self.serial:.6g} s, "
                f"latency {self.latency:.6g} s per hand-out, overhead {self.overhead:.6g} s per evaluation, "
                f"{'as MpiScheduler' if self.in_flight is None else self.in_flight} in flight, evaluated share {self.evaluated_share:.3f}")


def calibrate(path, skip=1):
    """A Calibration from one history: costs, S0, inferred latency, evaluated share."""
    with ch.History(path) as history:
        t = history.individuals()
        g = history.generations()
        attributes = history.attributes
    evaluated = t["worker_rank"] >= 0
    costs = t["eval_seconds"][evaluated]
    if len(costs) == 0 or len(g["generation"]) == 0:
        raise ch.InputFileError(f"{path}: no evaluated individuals")
    later = g["generation"] >= skip if np.any(g["generation"] >= skip) else np.ones(len(g["generation"]), bool)
    serial = float(np.median(g["rank0_serial_seconds"][later]))
    share = float(np.median(g["evaluations"][later] / g["count"][later]))
    # latency: rank 0's measured dispatch time per hand-out (no messages in a one-rank run);
    # histories without it: its CPU time beyond the serial work, an upper bound (wake-ups included)
    latency = 0.0
    if int(attributes.get("rank_count", 1)) > 1 and np.any(later):
        if "rank0_dispatch_seconds" in g and np.any(g["rank0_dispatch_seconds"][later] > 0):
            busy = g["rank0_dispatch_seconds"][later]
        elif "rank0_cpu_seconds" in g:
            busy = np.maximum(0.0, g["rank0_cpu_seconds"][later] - g["rank0_serial_seconds"][later])
        else:
            busy = np.zeros(int(np.sum(later)))
        latency = float(np.median(busy / np.maximum(1.0, g["evaluations"][later])))
    # overhead: measured span beyond the model's span without it, per evaluation per worker
    estimates = []
    for i, generation in enumerate(g["generation"]):
        if not later[i]:
            continue
        mine = (t["generation"] == generation) & evaluated
        workers = int(g["workers"][i])
        count = int(mine.sum())
        if count == 0 or workers < 1:
            continue
        modelled = simulate_span(t["eval_seconds"][mine], workers, latency, IN_FLIGHT, 0.0)
        excess = float(g["evaluation_span_seconds"][i]) - modelled
        estimates.append(max(0.0, excess) / max(1.0, count / workers))
    overhead = float(np.median(estimates)) if estimates else 0.0
    return Calibration(costs=costs, serial=serial, latency=latency, evaluated_share=share, source=path,
                       overhead=overhead)


def migration_sources(island, islands, event, topology, rng):
    """The islands that send to `island` after migration event `event` (as evolution/migration.cpp:
    ring from the one before, full from every other, random one other drawn per event; the model
    draws the random topology from its own stream)."""
    if topology == "ring":
        return [(island - 1) % islands]
    if topology == "full":
        return [k for k in range(islands) if k != island]
    return [k for k in range(islands) if k != island and rng.integers(islands - 1) == 0] or \
        [int((island + 1 + rng.integers(islands - 1)) % islands)]


def archipelago_time(island_times, islands, interval, topology="ring", generations=ISLAND_GENERATIONS, rng=None):
    """Mean generation time of `islands` islands over `generations` generations, each island's
    generation lasting a draw from `island_times`. Island i breeds generation g + 1 when its
    generation g is done and, where generation g - interval was a migration event (after
    generation interval - 1, 2 interval - 1, ...), when its sources have finished that one (their
    migrants leave right after it): Archipelago::exchange."""
    rng = np.random.default_rng(0) if rng is None else rng
    times = np.asarray(island_times, dtype=float)
    end = np.zeros((islands, generations))
    for g in range(generations):
        event = g - 1 - interval  # the batches taken in before breeding generation g
        for i in range(islands):
            start = end[i, g - 1] if g > 0 else 0.0
            if islands > 1 and event >= 0 and (event + 1) % interval == 0:
                for source in migration_sources(i, islands, event, topology, rng):
                    start = max(start, end[source, event])
            end[i, g] = start + times[rng.integers(len(times))]
    return float(end[:, -1].max()) / generations


def steady_time(costs, workers, population, latency, serial, overhead=0.0, in_flight=None):
    """Mean time per generation (`population` results taken in) of a steady state
    (evolution.mode = steady_state) evaluating `costs` in the order given, after its first
    generation: rank 0 hands out one evaluation at a time, each taking `latency` of it, to the
    worker holding fewest; every worker holds held(mean, ...) evaluations of the middle of a
    generation, and at most max(1, population // 2) are out in all; after each result it hands
    out the next, and after each `population` results it spends `serial` (history row,
    checkpoint) while the workers go on with what they hold. Children are bred only once the
    first generation is in (its tail is the one barrier). Needs at least two generations of
    costs."""
    costs = np.asarray(costs, dtype=float)
    total = len(costs)
    if total < 2 * population:
        raise ValueError("steady_time: at least two generations of costs needed")
    mean = float(np.mean(costs))
    depth = held(mean, 10 ** 12, workers, in_flight)
    cap = min(depth * workers, max(1, population // 2))
    rank0_free = 0.0
    queues = [deque() for _ in range(workers)]
    holding = [0] * workers
    handed = taken = 0
    out = 0
    finishes = []
    first_generation_end = 0.0
    end = 0.0

    def hand(worker, ready):
        nonlocal rank0_free, handed, out
        rank0_free = max(rank0_free, ready) + latency
        queues[worker].append((rank0_free, costs[handed]))
        handed += 1
        out += 1
        holding[worker] += 1
        # a worker with nothing running starts at once
        if holding[worker] == 1:
            arrival, cost = queues[worker].popleft()
            heapq.heappush(finishes, (arrival + cost + overhead, worker))

    def may_hand():
        # children only once the first generation is in
        return handed < total and out < cap and (handed < population or taken >= population)

    def fill(ready):
        while may_hand():
            worker = min(range(workers), key=lambda w: (holding[w], w))
            if holding[worker] >= depth:
                break
            hand(worker, ready)

    fill(0.0)
    while finishes:
        done, worker = heapq.heappop(finishes)
        end = max(end, done)
        holding[worker] -= 1
        out -= 1
        taken += 1
        # the next queued evaluation of this worker starts
        if queues[worker]:
            arrival, cost = queues[worker].popleft()
            heapq.heappush(finishes, (max(done, arrival) + cost + overhead, worker))
        rank0_free = max(rank0_free, done)
        if taken % population == 0:
            rank0_free += serial
            if taken == population:
                first_generation_end = rank0_free
        fill(done)
    generations = total // population
    return (max(end, rank0_free) - first_generation_end) / (generations - 1)


def project(calibration, populations, worker_counts, samples=5, seed=1, island_workers=None, interval=10,
            topology="ring", steady=False):
    """Rows (dicts) population, workers, islands, evaluations, time, speedup, efficiency, limit.
    With `island_workers` w, worker counts of 2w and more are W // w islands of w workers (the
    population per island; time is the archipelago's mean generation time). `steady`: every
    population (island) a steady state, its generation `steady_time`'s over 8 generations of
    costs (all `population` evaluated; limit "cap" where a population has more workers than the
    population // 2 it keeps out, else "work")."""
    rows = []
    for population in populations:
        rng = np.random.default_rng([seed, population])
        count = population if steady else max(1, int(round(population * calibration.evaluated_share)))
        per_draw = 8 * population if steady else count
        draws = [calibration.draw(per_draw, rng) for _ in range(samples)]

        def generation(costs, workers):
            if steady:
                return steady_time(costs, workers, population, calibration.latency, calibration.serial,
                                   calibration.overhead)
            return calibration.time(costs, workers)

        base = np.mean([generation(c, 1) for c in draws])
        for workers in worker_counts:
            islands = workers // island_workers if island_workers and workers >= 2 * island_workers else 1
            per_island = workers // islands
            # an archipelago draws each island's generations from more generations than a point
            island_draws = draws + [calibration.draw(per_draw, rng) for _ in range(ISLAND_SAMPLES - samples)] \
                if islands > 1 else draws
            times = [generation(c, per_island) for c in island_draws]
            if steady:
                limit = "cap" if per_island > max(1, population // 2) else "work"
            else:
                limits = [calibration.limit(c, per_island) for c in draws]
                limit = max(set(limits), key=limits.count)
            time = float(np.mean(times))
            if islands > 1:
                # the islands' waits for each other, as a factor on the island's own time
                pool = float(np.mean(times))
                waits = archipelago_time(times, islands, interval, topology, rng=rng) / pool
                time = float(np.mean(times[:samples])) * waits
                if waits > MIGRATION_SLACK:
                    limit = "migration"
            speedup = islands * base / time
            rows.append({"population": population, "workers": islands * per_island, "islands": islands,
                         "evaluations": count, "time": float(time), "speedup": float(speedup),
                         "efficiency": float(speedup / (islands * per_island)), "limit": limit})
    return rows


def compare(calibration, runs, samples=5, seed=1, mode="strong"):
    """Model against every measured point of a sweep: list of dicts per worker count, each
    point simulated with its own evaluations per generation; speedups as scaling.points."""
    rows, _, _ = scaling.points(runs, mode)
    evaluations = {}
    for run in runs:
        evaluations.setdefault(run["workers"], []).append(run["evaluations"])
    rng = np.random.default_rng(seed)
    out = []
    for row in rows:
        count = max(1, int(round(np.median(evaluations[row["workers"]]))))
        draws = [calibration.draw(count, rng) for _ in range(samples)]
        model = float(np.mean([calibration.time(c, row["workers"]) for c in draws]))
        out.append({"workers": row["workers"], "measured": row["time_median"], "model": model,
                    "measured_speedup": row["speedup"]})
    for o in out:
        p0, t0 = out[0]["workers"], out[0]["model"]
        o["model_speedup"] = (p0 if mode == "strong" else o["workers"]) * t0 / o["model"]
        o["error"] = (o["model"] - o["measured"]) / o["measured"]
    return out


def plot(rows, measured, output, title, dpi):
    """Speedup and efficiency against workers per population, markers naming the bound."""
    figure, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, population in enumerate(sorted({r["population"] for r in rows})):
        mine = [r for r in rows if r["population"] == population]
        w = [r["workers"] for r in mine]
        colour = colours[i % len(colours)]
        axes[0].plot(w, [r["speedup"] for r in mine], color=colour, label=f"P = {population}")
        axes[1].plot(w, [r["efficiency"] for r in mine], color=colour)
        # one marker per bound
        for r in mine:
            for a, key in ((axes[0], "speedup"), (axes[1], "efficiency")):
                a.scatter(r["workers"], r[key], color=colour, marker=MARKERS[r["limit"]], s=28, zorder=3)
    top = max(r["workers"] for r in rows)
    axes[0].plot([1, top], [1, top], color="0.5", linestyle=":", label="ideal")
    if measured:
        axes[0].scatter([m["workers"] for m in measured], [m["measured_speedup"] for m in measured],
                        color="black", marker="x", s=60, zorder=4, label="measured")
    for limit, marker in MARKERS.items():
        axes[1].scatter([], [], color="0.3", marker=marker, label=f"bound: {limit}")
    axes[0].set_xscale("log", base=2)
    axes[0].set_yscale("log", base=2)
    axes[0].set_ylabel("speedup vs 1 worker")
    axes[1].set_xscale("log", base=2)
    axes[1].set_ylim(0, 1.05)
    axes[1].set_ylabel("efficiency")
    for a in axes:
        a.set_xlabel("workers")
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize="small")
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    # calibration: a history, the sweep's smallest run, or parameters
    runs = None
    try:
        if arguments.sweep:
            runs = scaling.load_sweep(arguments.sweep, arguments.skip)
        if arguments.history:
            calibration = calibrate(arguments.history, arguments.skip)
        elif runs:
            calibration = calibrate(min(runs, key=lambda r: (r["workers"], r["path"]))["path"], arguments.skip)
        else:
            calibration = Calibration(cost_mean=arguments.cost_mean, cost_cv=arguments.cost_cv)
    except (ch.HistoryError, ch.InputFileError, KeyError, OSError) as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return ch.EXIT_INPUT
    # parameters override what the history says
    if arguments.cost_mean is not None:
        calibration.cost_mean, calibration.cost_cv = arguments.cost_mean, arguments.cost_cv
    for name in ("serial", "latency", "overhead", "evaluated_share"):
        if getattr(arguments, name) is not None:
            setattr(calibration, name, getattr(arguments, name))
    calibration.in_flight = arguments.in_flight
    print(f"# {calibration.describe()}")
    # projection
    worker_counts = [2 ** k for k in range(int(np.log2(arguments.max_workers)) + 1)]
    rows = project(calibration, arguments.populations, worker_counts, arguments.samples, arguments.seed,
                   arguments.island_workers, arguments.interval, arguments.topology, arguments.steady_state)
    lines = ["population\tworkers\tislands\tevaluations\tgeneration_seconds\tspeedup\tefficiency\tlimit"]
    lines += [f"{r['population']}\t{r['workers']}\t{r['islands']}\t{r['evaluations']}\t{r['time']:.6g}\t"
              f"{r['speedup']:.4g}\t{r['efficiency']:.4f}\t{r['limit']}" for r in rows]
    print("\n".join(lines))
    if arguments.table:
        with open(arguments.table, "w") as handle:
            handle.write("\n".join(lines) + "\n")
    # where efficiency falls below one half
    for population in arguments.populations:
        below = [r for r in rows if r["population"] == population and r["efficiency"] < 0.5]
        where = f"{below[0]['workers']} workers (bound: {below[0]['limit']})" if below else f"not within {arguments.max_workers} workers"
        print(f"# P = {population}: efficiency below 50 % from {where}")
    # model against the measured sweep
    measured = None
    if runs:
        measured = compare(calibration, runs, arguments.samples, arguments.seed, arguments.mode)
        print("# model vs measured (median generation seconds, generations >= skip)")
        print("workers\tmeasured_seconds\tmodel_seconds\trelative_error\tmeasured_speedup\tmodel_speedup")
        for m in measured:
            print(f"{m['workers']}\t{m['measured']:.6g}\t{m['model']:.6g}\t{m['error']:+.3f}\t"
                  f"{m['measured_speedup']:.4g}\t{m['model_speedup']:.4g}")
    title = "scaling model: " + os.path.basename(calibration.source)
    if arguments.steady_state:
        title += ", steady states"
    if arguments.island_workers:
        title += f", islands of {arguments.island_workers} workers (every {arguments.interval}, {arguments.topology})"
    plot(rows, measured, arguments.output, title, arguments.dpi)
    print(f"# wrote {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
