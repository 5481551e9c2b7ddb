#!/usr/bin/env bash
# Strong scaling sweep: the same experiment (population) at every worker count, R repeats each,
# one directory per run (runs/scaling/<name>/w<W>/r<R>/), then analysis/scaling.py.
# usage: jobs/scaling/strong.sh [--workers "1 2 4 8 16"] [--repeats 3] [--population 300] ... (--help)
set -euo pipefail
cd "$(dirname "$0")/../.."
MODE=strong
# shellcheck source=jobs/scaling/common.sh
source jobs/scaling/common.sh "$@"
