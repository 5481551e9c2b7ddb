#!/usr/bin/env bash
# Tests replay_finding.sh with stand-ins for a fuzz target: an input that does not fail again;
# an out-of-memory whose replay shows libhdf5 only without the ASan suppressions (as HDF5 1.10's
# overlapping copy does); one that shows cambrian's code; a crash inside libhdf5 at once.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the stand-in reads its behaviour from the finding's first word
cat > "$work/target" <<'TARGET'
#!/usr/bin/env bash
finding=${!#}
case $(head -c 20 "$finding") in
  passes*) exit 0 ;;
  overlap*)
    if [[ "${ASAN_OPTIONS:-}" == *suppressions=* ]]; then
      echo "==1== ERROR: libFuzzer: out-of-memory (used: 2201Mb; limit: 2048Mb)"
    else
      echo "==1==ERROR: AddressSanitizer: memcpy-param-overlap: memory ranges overlap"
      echo "    #0 0x1 in __asan_memcpy (/x/fuzz_history+0x1)"
      echo "    #1 0x2 in H5HG_read (/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x2)"
    fi
    exit 1 ;;
  ours*)
    echo "==1==ERROR: AddressSanitizer: heap-buffer-overflow"
    echo "    #0 0x1 in cambrian::readHistory() /src/store/history.cpp:10"
    exit 1 ;;
  crash*)
    echo "==1==ERROR: AddressSanitizer: SEGV on unknown address"
    echo "    #0 0x1 in H5F_open (/lib/x86_64-linux-gnu/libhdf5_serial.so.103+0x1)"
    exit 1 ;;
esac
TARGET
chmod +x "$work/target"
export ASAN_OPTIONS=detect_leaks=1:suppressions=/some/asan.supp
expect() {
  local want=$1 input=$2 got=0
  printf '%s' "$input" > "$work/finding"
  bash "$here/replay_finding.sh" "$work/target" "$work/finding" libhdf5 || got=$?
  if [ "$got" -ne "$want" ]; then
    echo "replay_finding.sh on '$input': exit $got, expected $want" >&2
    exit 1
  fi
}
expect 2 passes
expect 0 overlap
expect 1 ours
expect 0 crash
[ -s "$work/finding.replay.txt" ] || { echo "no replay log written" >&2; exit 1; }
echo "replay_finding_test: all cases as expected"
