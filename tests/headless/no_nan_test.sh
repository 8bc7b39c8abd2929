#!/usr/bin/env bash
# No "nan" in what `sph run` prints for a scene (its summary line and reference values, warnings, messages),
# at t = 0 and at its t_end, at the scene file's defaults: a value not defined yet is shown as a dash.
# Usage: no_nan_test.sh SPH SCENE_FILE [END]  (END: run to this time instead of t_end, for scenes too long for CI)
set -u
sph=$1
scene=$2
end=${3:-}
name=$(basename "$scene" .json)
status=0
for until in 0 end; do
  if [ "$until" = 0 ]; then out=$("$sph" run "$scene" --threads 1 --until 0 2>&1); rc=$?
  elif [ -n "$end" ]; then out=$("$sph" run "$scene" --threads 1 --until "$end" 2>&1); rc=$?
  else out=$("$sph" run "$scene" --threads 1 2>&1); rc=$?; fi
  echo "== $name to t = $until (exit $rc)"
  echo "$out"
  if [ "$rc" -ne 0 ]; then echo "FAIL: $name to t = $until exited $rc"; status=1; fi
  if echo "$out" | grep -Eiq '(^|[^a-z_])nan([^a-z_]|$)'; then
    echo "FAIL: $name to t = $until printed nan:"; echo "$out" | grep -Ei '(^|[^a-z_])nan([^a-z_]|$)'; status=1
  fi
done
exit $status
