#!/usr/bin/env bash
# Per-step cost of cambrian against a bare Bullet loop of the same chain body (2, 5, 10, 20
# parts): the table for cambrian's default physics, then for a second configuration. Builds
# nothing: runs bench/step_cost.cpp's program from a build folder.
# usage: bash jobs/bench/step_cost.sh [BUILD_DIR] [physics.KEY=VALUE ...] [-- BENCH_OPTIONS ...]
#   BUILD_DIR        default build/ci (its bench/cambrian_step_cost)
#   KEY=VALUE ...    the second configuration (default: physics.substeps=1
#                    physics.solver_iterations=10)
#   BENCH_OPTIONS    passed to both runs (--parts 5, --rounds 9, --tsv; see --help)
# Timings on shared machines are noisy: compare the ratios of one run (docs/performance.md).
set -euo pipefail
cd "$(dirname "$0")/../.."

if [ "${1:-}" = --help ] || [ "${1:-}" = -h ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
build=build/ci
if [ $# -gt 0 ] && [[ $1 != *=* ]] && [ "$1" != -- ]; then
  build=$1
  shift
fi
second=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do
  second+=("$1")
  shift
done
[ "${1:-}" = -- ] && shift
options=("$@")
[ ${#second[@]} -gt 0 ] || second=(physics.substeps=1 physics.solver_iterations=10)

bench=$build/bench/cambrian_step_cost
if [ ! -x "$bench" ]; then
  echo "step_cost.sh: $bench not found; build it first (cmake --preset ci && cmake --build --preset ci)" >&2
  exit 2
fi

status=0
echo "== cambrian's default physics"
"$bench" ${options[@]+"${options[@]}"} || status=$?
echo
echo "== ${second[*]}"
"$bench" ${options[@]+"${options[@]}"} "${second[@]}" || status=$?
exit "$status"
