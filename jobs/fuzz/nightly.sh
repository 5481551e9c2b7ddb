#!/usr/bin/env bash
# Runs every fuzz target (tests/fuzz) for longer than CI does: FUZZ_SECONDS each (default 3600),
# FUZZ_JOBS targets at a time (default 1), each in libFuzzer's fork mode so that it goes on
# after a crash. Builds preset asan first. Grows a corpus per target in OUT/corpus/ (the
# repository's corpus is only read), saves every crash, leak, timeout and out-of-memory input in
# OUT/crashes/TARGET/, prints each target's executions and findings (those in libhdf5 apart), and
# says how to turn a finding into a regression test. Exits 1 when anything outside a known
# faulty library was found.
# usage: FUZZ_SECONDS=3600 FUZZ_JOBS=2 bash jobs/fuzz/nightly.sh [OUT] [TARGET...]
#   OUT defaults to build/fuzz-nightly; TARGETs (genome_bytes, history, ...) default to all
set -euo pipefail

if [ "${1:-}" = --help ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/../.."
source_dir=$PWD
out=$(realpath -m "${1:-build/fuzz-nightly}")
shift || true
seconds=${FUZZ_SECONDS:-3600} jobs=${FUZZ_JOBS:-1}
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(sed -n 's/^cambrian_fuzz_target(\([a-z_]*\) .*/\1/p' tests/fuzz/CMakeLists.txt)
fi

cmake --preset asan > /dev/null
cmake --build --preset asan --target "${targets[@]/#/fuzz_}"

# one target: fork mode, crashes ignored (saved) so that the run goes on
fuzz() {
  local target=$1
  mkdir -p "$out/corpus/$target" "$out/crashes/$target"
  ( cd "$out/crashes/$target" &&
    "$source_dir/build/asan/tests/fuzz/fuzz_$target" -fork=1 -ignore_crashes=1 -ignore_ooms=1 \
      -ignore_timeouts=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$out/crashes/$target/" "$out/corpus/$target" \
      "$source_dir/tests/fuzz/corpus/$target" > "$out/$target.log" 2>&1 ) || true
}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:intercept_tls_get_addr=0} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$source_dir/tests/sanitizers/lsan.supp}
# the readers read in this process (no child first); libhdf5's own errors on damaged files
export CAMBRIAN_READ_SECONDS=0
export ASAN_OPTIONS="$ASAN_OPTIONS:suppressions=$source_dir/tests/sanitizers/asan.supp"
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  echo "nightly: fuzzing $target for $seconds s"
  fuzz "$target" &
done
wait

# what each target did and found; a finding whose fault lies in the target's known faulty
# library (libhdf5 for the HDF5 readers: tests/fuzz/CMakeLists.txt) is counted apart: cambrian's
# readers meet those in a child process (docs/fuzzing-and-sanitizers.md); so is one that does
# not fail again when replayed alone
found=0
printf '%-16s %14s %8s %12s %16s\n' target executions findings "in library" "not reproduced"
for target in "${targets[@]}"; do
  execs=$(grep -o '^#[0-9]*' "$out/$target.log" | tail -n 1 | tr -d '#')
  library=$(sed -n "s/^cambrian_fuzz_target($target .*KNOWN_FAULTY_LIBRARY \([a-z0-9_]*\)).*/\1/p" \
    tests/fuzz/CMakeLists.txt)
  crashes=0 in_library=0 not_reproduced=0
  while IFS= read -r -d '' finding; do
    crashes=$((crashes + 1))
    [ -n "$library" ] || continue
    # replay it once to see where it fails (fork mode also saves inputs that fail only in
    # their job's context, such as an empty one after a job's endless loop)
    replayed=0
    bash tests/fuzz/replay_finding.sh "$source_dir/build/asan/tests/fuzz/fuzz_$target" \
      "$finding" "$library" || replayed=$?
    case $replayed in
      0) in_library=$((in_library + 1)) ;;
      2) not_reproduced=$((not_reproduced + 1)) ;;
    esac
  done < <(find "$out/crashes/$target" -maxdepth 1 -type f \
    \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) \
    ! -name '*.replay*.txt' -print0)
  printf '%-16s %14s %8s %12s %16s\n' "$target" "${execs:-?}" "$crashes" "$in_library" \
    "$not_reproduced"
  found=$((found + crashes - in_library - not_reproduced))
done
if [ "$found" -gt 0 ]; then
  cat <<TEXT
nightly: $found finding(s) outside the known faulty libraries in $out/crashes/TARGET/
(for a target with a known faulty library, FILE.replay.txt beside each finding holds its stack).
For each:
  1. reproduce: build/asan/tests/fuzz/fuzz_TARGET FILE (prints the report and the stack)
  2. fix the cause in src/, and add a unit test in tests/<module>/ with the input's essence
  3. copy FILE to tests/fuzz/corpus/TARGET/ (named for what it breaks), so that every CI run
     replays it (ctest --preset asan -L fuzz)
TEXT
  exit 1
fi
echo "nightly: nothing found outside the known faulty libraries ($out)"
