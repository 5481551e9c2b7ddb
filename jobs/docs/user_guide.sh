#!/usr/bin/env bash
# Regenerates the settings reference of docs/user-guide.md from the option definitions
# (`cambrian evolve --help-markdown`), so the guide cannot drift from the code.
# usage: jobs/docs/user_guide.sh [--check] [CAMBRIAN]
#   --check    exit 1 (and show the difference) when the guide is out of date; write nothing
#   CAMBRIAN   the binary (default build/release/src/app/cambrian)
set -euo pipefail
cd "$(dirname "$0")/../.."

check=false
if [ "${1:-}" = "--check" ]; then
  check=true
  shift
fi
cambrian=${1:-build/release/src/app/cambrian}
guide=docs/user-guide.md
begin='<!-- BEGIN GENERATED: cambrian evolve --help-markdown -->'
end='<!-- END GENERATED -->'

# the guide with the generated block replaced
reference=$(mktemp)
updated=$(mktemp)
trap 'rm -f "$reference" "$updated"' EXIT
"$cambrian" evolve --help-markdown > "$reference"
grep -qxF "$begin" "$guide" && grep -qxF "$end" "$guide" || {
  echo "$guide: the markers '$begin' and '$end' are missing" >&2
  exit 1
}
awk -v begin="$begin" -v end="$end" -v reference="$reference" '
  $0 == begin { print; print ""; while ((getline line < reference) > 0) print line; print "";
                skipping = 1; next }
  $0 == end   { skipping = 0 }
  !skipping   { print }' "$guide" > "$updated"

# check or write
if $check; then
  if ! diff -u "$guide" "$updated"; then
    echo "$guide is out of date: run bash jobs/docs/user_guide.sh" >&2
    exit 1
  fi
  echo "$guide is up to date"
else
  cp "$updated" "$guide"
  echo "wrote $guide"
fi
