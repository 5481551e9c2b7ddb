#!/usr/bin/env bash
# Where an evaluation's instructions go: callgrind on a 10 s walk of the 5-part walker and the
# 6-part snake (jobs/creatures), summed by shared object (analysis/callgrind_share.py).
# Needs valgrind (Debian package valgrind; not installed by jobs/setup/install-deps.sh).
# Usage: bash jobs/bench/bullet_share.sh [path/to/cambrian]   (default: build/release)
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=${1:-build/release/src/app/cambrian}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

profile() {
  local name=$1; shift
  valgrind --tool=callgrind --callgrind-out-file="$work/$name.out" "$cambrian" simulate "$@" \
    > "$work/$name.txt" 2> /dev/null
  echo "== $name: $(grep -E '^(body|status|steps)' "$work/$name.txt" | tr -s ' ' | paste -sd ';')"
  /usr/bin/python3 analysis/callgrind_share.py "$work/$name.out"
}

profile walker4 --genome jobs/creatures/walker4.genome --task walk
profile snake --genome jobs/creatures/snake.genome --task walk
# Walking with Dinosaurs: the Turtle (five boxes, the layered network) under its experiment file
profile wwd-turtle --genome jobs/creatures/wwd/turtle.genome \
  --config jobs/experiments/wwd/iterative-move.ini
