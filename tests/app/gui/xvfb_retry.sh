#!/usr/bin/env bash
# xvfb-run "$@", run once more when it failed in LeakSanitizer rather than in the program: under ASan,
# LSan's own tracer can crash while it stops the threads at exit ("Tracer caught signal 11", then
# "LeakSanitizer has encountered a fatal error"; seen once in a loaded CI run of gui_key_taps). A leak
# report, a sanitizer error in the program or any other failure is not retried. The retry is announced.
set -u
out=$(mktemp) err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
for attempt in 1 2; do
  xvfb-run "$@" > "$out" 2> "$err"
  rc=$?
  if [ "$rc" -ne 0 ] && [ "$attempt" -eq 1 ] && grep -q "LeakSanitizer has encountered a fatal error" "$err"; then
    echo "xvfb_retry: LeakSanitizer's tracer failed (not a leak report); running again:" >&2
    sed 's/^/  first run: /' "$err" >&2
    continue
  fi
  break
done
cat "$out"
cat "$err" >&2
exit "$rc"
