#!/usr/bin/env bash
# Sets up (Debian packages), builds and runs the whole test suite. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

bash jobs/setup/install-deps.sh

# Open MPI refuses root unless told; CI and containers run as root
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

# each step's wall time, printed when it is done
timed() {
  local start=$SECONDS
  "$@"
  echo "test.sh: '$*' took $((SECONDS - start)) s"
}

# the release build with warnings as errors (gcc), and its suite
timed cmake --preset ci
timed cmake --build --preset ci
timed ctest --preset ci -j "$(nproc)"

# the same suite built by clang under AddressSanitizer and UBSan, with each fuzz target run over
# its corpus for a bounded time (docs/fuzzing-and-sanitizers.md)
timed cmake --preset asan
timed cmake --build --preset asan
timed ctest --preset asan -j "$(nproc)"
