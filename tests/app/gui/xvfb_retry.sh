#!/usr/bin/env bash
# xvfb-run "$@", run once more when it failed in LeakSanitizer rather than in the program. Under ASan
# (GCC 12's runtime, glibc 2.36), LSan's tracer can crash at exit while it walks the main thread's
# dynamic thread-local storage ("Tracer caught signal 11", then "LeakSanitizer has encountered a fatal
# error"): sph-gui --tap-keys 5:SSSS --tap-keys 30:R does so every time since the build of this change.
# The second run scans no thread-local storage (use_tls=0; the loader's tables it then sees are in
# tests/lsan.supp), so leaks of the heap are still found. A leak report, a sanitizer error in the program
# or any other failure is not retried. The retry is announced.
set -u
out=$(mktemp) err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
for attempt in 1 2; do
  xvfb-run "$@" > "$out" 2> "$err"
  rc=$?
  if [ "$rc" -ne 0 ] && [ "$attempt" -eq 1 ] && grep -q "LeakSanitizer has encountered a fatal error" "$err"; then
    echo "xvfb_retry: LeakSanitizer's tracer failed (not a leak report); running again with use_tls=0:" >&2
    sed 's/^/  first run: /' "$err" >&2
    export LSAN_OPTIONS="${LSAN_OPTIONS:-}:use_tls=0"
    continue
  fi
  break
done
cat "$out"
cat "$err" >&2
exit "$rc"
