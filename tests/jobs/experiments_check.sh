#!/usr/bin/env bash
# Every experiment file shipped in jobs/experiments/ loads: its keys exist, its values are in
# range and the files it names are found (a random creature is developed and evaluated under
# it, from the source tree as the README runs them). A file that does not prints cambrian's
# message, naming the file and key.
# usage: experiments_check.sh CAMBRIAN SOURCE_DIR
set -euo pipefail
cambrian=$1 source_dir=$2
cd "$source_dir"
mapfile -t files < <(find jobs/experiments -name '*.ini' | sort)
[ "${#files[@]}" -ge 20 ] || { echo "only ${#files[@]} experiment files found" >&2; exit 1; }
failed=0
for file in "${files[@]}"; do
  if out=$("$cambrian" simulate --random --seed 1 --config "$file" 2>&1) &&
     grep -q '^status ' <<< "$out"; then
    echo "ok      $file ($(grep '^status ' <<< "$out" | cut -c12-60))"
  else
    echo "$out"
    echo "FAILED  $file" >&2
    failed=$((failed + 1))
  fi
done
echo "${#files[@]} experiment files, $failed failed"
[ "$failed" -eq 0 ]
