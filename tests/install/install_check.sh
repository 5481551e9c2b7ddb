#!/usr/bin/env bash
# Installs a built cambrian tree into a temporary prefix and checks that a project outside the
# tree finds it with find_package(cambrian), builds against cambrian::cambrian and evaluates a
# creature; also that a too-new version request is refused and that the prefix can be moved.
# Run by CTest (label install).
# usage: install_check.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail

if [ "${1:-}" = "--help" ] || [ $# -ne 3 ]; then
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
build=$1 source=$2 work=$3
consumer_src=$source/tests/install/consumer
fail() { echo "install_check: FAIL: $*" >&2; exit 1; }

# a clean work directory
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix

# install the build into the prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || {
  cat "$work/install.log"; fail "cmake --install $build failed"; }

# the files a user and an embedder need
for f in bin/cambrian include/cambrian/evaluate.hpp include/cambrian/encodings.hpp \
         include/cambrian/version.hpp lib/libcambrian_core.a lib/libcambrian_tasks.a \
         lib/cmake/cambrian/cambrianConfig.cmake lib/cmake/cambrian/cambrianConfigVersion.cmake \
         lib/cmake/cambrian/cambrianTargets.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f (installed: $(cd "$prefix" && find . -type f | sort | tr '\n' ' '))"
done
echo "installed: $(cd "$prefix" && find . -type f | wc -l) files under $prefix"

# the installed executable runs and reports the build's version
"$prefix/bin/cambrian" version | tee "$work/version.txt"
grep -q '^cambrian [0-9]' "$work/version.txt" || fail "installed cambrian version printed nothing useful"

generator=()
if command -v ninja > /dev/null; then generator=(-G Ninja); fi

# configure, build and run the consumer against a prefix: configure_consumer PREFIX BUILD [ARGS]
configure_consumer() {
  local p=$1 b=$2; shift 2
  cmake -S "$consumer_src" -B "$b" "${generator[@]}" -DCMAKE_PREFIX_PATH="$p" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@"
}
build_and_run() {
  local p=$1 b=$2
  configure_consumer "$p" "$b" > "$b.configure.log" 2>&1 || {
    cat "$b.configure.log"; fail "find_package(cambrian) failed with prefix $p"; }
  cmake --build "$b" > "$b.build.log" 2>&1 || {
    cat "$b.build.log"; fail "the consumer did not build against $p"; }
  # a known creature: the pole develops to 2 parts and evaluates cleanly
  "$b/consumer" "$source/jobs/creatures/pole.genome" | tee "$b.pole.txt"
  grep -q 'status ok fitness [0-9.]* parts 2 ' "$b.pole.txt" || fail "pole.genome: unexpected outcome"
  # a random genome: evaluates to some status without crashing (exit 0 for ok, 1 otherwise)
  set +e
  "$b/consumer" > "$b.random.txt" 2>&1
  local rc=$?
  set -e
  cat "$b.random.txt"
  [ $rc -le 1 ] && grep -q '^cambrian .*: status ' "$b.random.txt" ||
    fail "random genome: exit $rc"
}

# 1. find_package from the install prefix
build_and_run "$prefix" "$work/consumer"

# 2. the version file refuses a version this package is not compatible with
if configure_consumer "$prefix" "$work/consumer-too-new" -DCONSUMER_CAMBRIAN_VERSION=99.0 \
     > "$work/too-new.log" 2>&1; then
  fail "find_package(cambrian 99.0) succeeded against version $(cat "$work/version.txt")"
fi
grep -q 'compatible with requested version "99.0"' "$work/too-new.log" ||
  { cat "$work/too-new.log"; fail "find_package(cambrian 99.0) failed for another reason"; }
echo "find_package(cambrian 99.0) refused, as it should be"

# 3. the installed tree is relocatable: move the prefix and build again
mv "$prefix" "$work/moved"
build_and_run "$work/moved" "$work/consumer-moved"

echo "install_check: OK"
