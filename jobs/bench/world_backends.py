#!/usr/bin/python3
"""Cost and stability of the two physics worlds (physics.world = featherstone | rigid_bodies) on
the same creatures: the hand-written walker and snake, the Minemonics model organisms and N random
genomes, each simulated walking in both worlds, interleaved, with the rest check on.

Reports per world: steps per second over the creatures both worlds evaluate (and the ratio),
the statuses, how far the two worlds' fitnesses lie apart on the same creature, and how far each
creature travels with no strength at all (physics.strength_per_area = 0: motion from nothing).

usage: /usr/bin/python3 jobs/bench/world_backends.py [--cambrian PATH] [--random N] [--rounds R]
                                                      [--time S] [-- SETTINGS ...]
Timings on shared machines are noisy: compare the ratios of one run (docs/performance.md)."""
import argparse
import collections
import statistics
import subprocess
import sys

WORLDS = ("featherstone", "rigid_bodies")


def simulate(cambrian, creature, world, seconds, extra):
    """The fields `cambrian simulate` prints, as a dict (status, fitness, steps, wall)."""
    command = [cambrian, "simulate", *creature, "--task", "walk", "--task.evaluation_time",
               str(seconds), "--task.rest_check", "true", "--physics.world", world, *extra]
    out = subprocess.run(command, capture_output=True, text=True).stdout
    fields = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) < 2:
            continue
        if parts[0] == "status":
            fields["status"] = parts[1].rstrip(":")
        elif parts[0] == "fitness":
            fields["fitness"] = float(parts[1])
        elif parts[0] == "steps":
            fields["steps"] = int(parts[1])
        elif parts[0] == "wall" and parts[1] == "time":
            fields["wall"] = float(parts[2])
    return fields


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cambrian", default="build/release/src/app/cambrian")
    parser.add_argument("--random", type=int, default=40, help="random genomes (seeds 1..N)")
    parser.add_argument("--rounds", type=int, default=2, help="timed rounds")
    parser.add_argument("--time", type=float, default=10, help="evaluation time, s")
    parser.add_argument("settings", nargs="*", help="more --key value settings for every run")
    args = parser.parse_args()

    creatures = [["--genome", f"jobs/creatures/{name}.genome"] for name in ("walker4", "snake")]
    creatures += [["--genome", f"jobs/creatures/minemonics/{name}.genome"]
                  for name in ("leg", "snake", "pod", "ragdoll")]
    creatures += [["--random", "--seed", str(seed)] for seed in range(1, args.random + 1)]

    runs = {world: [] for world in WORLDS}
    for _ in range(args.rounds):
        for creature in creatures:
            for world in WORLDS:
                runs[world].append(simulate(args.cambrian, creature, world, args.time,
                                            args.settings))
    count = len(creatures)
    first = {world: runs[world][:count] for world in WORLDS}
    both = [i for i in range(count)
            if all(first[w][i].get("status") == "ok" for w in WORLDS)]

    print(f"{count} creatures ({args.random} random), {args.time:g} s walking, rest check on, "
          f"{args.rounds} rounds interleaved")
    print("\n== cost over the creatures both worlds evaluate (ok in both)")
    rate = {}
    for world in WORLDS:
        steps = sum(r["steps"] for k, r in enumerate(runs[world]) if k % count in both)
        wall = sum(r["wall"] for k, r in enumerate(runs[world]) if k % count in both)
        rate[world] = steps / wall if wall > 0 else float("nan")
        print(f"{world:14s} {rate[world]:10.0f} steps/s")
    print(f"rigid_bodies / featherstone cost per step: {rate[WORLDS[0]] / rate[WORLDS[1]]:.2f}")

    print("\n== statuses")
    for world in WORLDS:
        counts = collections.Counter(r.get("status", "?") for r in first[world])
        print(f"{world:14s} " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))

    print("\n== the same creature in both worlds (ok in both)")
    gaps = [abs(first[WORLDS[1]][i]["fitness"] - first[WORLDS[0]][i]["fitness"]) /
            max(abs(first[WORLDS[0]][i]["fitness"]), 0.05) for i in both]
    if gaps:
        gaps.sort()
        print(f"{len(gaps)} creatures; |fitness difference| / max(|featherstone|, 0.05 m): "
              f"median {statistics.median(gaps):.3f}, "
              f"90th percentile {gaps[int(0.9 * (len(gaps) - 1))]:.3f}, max {gaps[-1]:.3f}")

    print("\n== motion from nothing (physics.strength_per_area = 0): distance travelled, m")
    for world in WORLDS:
        passive = [simulate(args.cambrian, c, world, args.time,
                            args.settings + ["--physics.strength_per_area", "0"]) for c in creatures]
        moved = sorted(r["fitness"] for r in passive if r.get("status") == "ok")
        if moved:
            print(f"{world:14s} {len(moved)} ok: median {statistics.median(moved):.2e}, "
                  f"max {moved[-1]:.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
