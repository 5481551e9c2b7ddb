#!/usr/bin/env bash
# Builds the `cambrian` executable alone in another build type, for the golden tests.
# usage: other_build.sh SOURCE_DIR BUILD_DIR BUILD_TYPE GENERATOR WERROR
set -euo pipefail
source_dir=$1 build_dir=$2 build_type=$3 generator=$4 werror=$5
cmake -S "$source_dir" -B "$build_dir" -G "$generator" -DCMAKE_BUILD_TYPE="$build_type" \
  -DCAMBRIAN_BUILD_TESTS=OFF -DCAMBRIAN_WERROR="$werror" > "$build_dir.configure.log" 2>&1 ||
  { tail -n 20 "$build_dir.configure.log" >&2; exit 1; }
cmake --build "$build_dir" --target cambrian
