#!/usr/bin/python3
"""Share of instructions per shared object in a callgrind profile.

Reads a callgrind.out file and sums each function's *self* cost (Ir) by the object it lives
in, so the share of an evaluation spent inside Bullet can be read off directly.

    valgrind --tool=callgrind --callgrind-out-file=cg.out cambrian simulate ...
    analysis/callgrind_share.py cg.out
"""
import argparse
import re
import sys
from collections import defaultdict


def object_costs(path):
    """Returns {object name: self Ir} for one callgrind output file."""
    names = {"ob": {}, "fn": {}}
    costs = defaultdict(int)
    current_object = "???"
    skip_next_cost = False
    compressed = re.compile(r"^(ob|fn|cob|cfn|fl|fi|fe|cfi|cfl)=\((\d+)\)(?: (.*))?$")
    with open(path, encoding="utf-8", errors="replace") as stream:
        for line in stream:
            line = line.rstrip("\n")
            if not line:
                continue
            match = compressed.match(line)
            if match:
                kind, ident, name = match.groups()
                table = names.setdefault(kind.lstrip("c") if kind in ("cob", "cfn") else kind, {})
                if name is not None:
                    table[ident] = name
                if kind == "ob":
                    current_object = table.get(ident, "???")
                continue
            if line.startswith("ob="):
                current_object = line[3:]
                continue
            if line.startswith("calls="):
                skip_next_cost = True
                continue
            if line[0].isdigit() or line[0] in "+-*":
                fields = line.split()
                if len(fields) >= 2:
                    if skip_next_cost:
                        skip_next_cost = False
                        continue
                    costs[current_object] += int(fields[1])
    return costs


def classify(name):
    """Groups an object path into bullet / cambrian / libm / libc / other."""
    base = name.rsplit("/", 1)[-1]
    if "Bullet" in base or "LinearMath" in base:
        return "bullet"
    if base.startswith("libm"):
        return "libm"
    if base.startswith("libc"):
        return "libc"
    if base.startswith("libstdc++"):
        return "libstdc++"
    if base == "cambrian" or "cambrian" in base:
        return "cambrian"
    if base.startswith("ld-linux"):
        return "loader"
    return "other"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("profile", help="callgrind.out file")
    parser.add_argument("--objects", action="store_true", help="list every object, not groups")
    args = parser.parse_args()
    costs = object_costs(args.profile)
    total = sum(costs.values())
    if total == 0:
        print(f"{args.profile}: no costs found", file=sys.stderr)
        return 4
    groups = defaultdict(int)
    for name, cost in costs.items():
        groups[name if args.objects else classify(name)] += cost
    print(f"total instructions: {total}")
    for name, cost in sorted(groups.items(), key=lambda item: -item[1]):
        print(f"{100.0 * cost / total:6.2f} %  {cost:>14}  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
