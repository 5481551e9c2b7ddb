#!/usr/bin/env bash
# Weak scaling sweep: population = --per-worker × workers, R repeats each, one directory per run
# (runs/scaling/<name>/w<W>/r<R>/), then analysis/scaling.py --mode weak (Gustafson).
# usage: jobs/scaling/weak.sh [--workers "1 2 4 8 16"] [--repeats 3] [--per-worker 100] ... (--help)
set -euo pipefail
cd "$(dirname "$0")/../.."
MODE=weak
# shellcheck source=jobs/scaling/common.sh
source jobs/scaling/common.sh "$@"
