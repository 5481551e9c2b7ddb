#!/usr/bin/env bash
# Tells whether the first fault a fuzzer or sanitizer log reports (a timeout, a crash, a
# sanitizer error, a leak) lies in a given library: its innermost stack frame outside the C
# library, the sanitizer and fuzzer runtime and the allocator is in LIBRARY. Prints that frame;
# exits 0 when it is in LIBRARY, 1 when it is elsewhere (cambrian's own code, most likely) or the
# log has no fault.
# usage: library_fault.sh LOG LIBRARY
set -euo pipefail
log=$1 library=$2
innermost=$(awk '/ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer|LeakSanitizer)|Sanitizer: CHECK failed/ {
    seen = 1; next }
  seen && /^ *#[0-9]+ 0x/ {
    if ($0 ~ /libc\.so|sysdeps\/|libc_start|__sanitizer|__interceptor_|__asan|__ubsan|__lsan|fuzzer::/)
      next
    # the allocator (the allocation stack of a leak allocation stack, a bad free)
    if ($0 ~ / in (malloc|calloc|realloc|free|aligned_alloc|posix_memalign|operator new|operator delete)/)
      next
    sub(/^ +/, ""); print; exit
  }' "$log")
echo "${innermost:-no fault in $log}"
[ -n "$innermost" ] && [[ "$innermost" == *"$library"* ]]
