#!/usr/bin/env bash
# Sets up (Debian packages), builds and runs the whole test suite. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

bash jobs/setup/install-deps.sh

# Open MPI refuses root unless told; CI and containers run as root
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

cmake --preset ci
cmake --build --preset ci
ctest --preset ci -j "$(nproc)"
