#!/usr/bin/env bash
# N-body time steps that cannot silently fail (README "Exit codes"): `sph run kepler` of an eccentric
# orbit at the scene's fixed time.dt warns at the start naming time.dt, the pair and its pericentre, and
# ends non-zero (5 when the energy blows up, 8 when it ends beyond the bound; warnings.csv written either
# way, a blow-up's ending in its "diverged" row);
# the seed's orbit at its defaults exits 0 with an empty warnings.csv; the same eccentric orbit with
# adaptive steps (time.dt = 0, time.cfl = 0.003) exits 0 or 8 with its warning, never 0 with one.
# usage: kepler_timestep_test.sh SPH_BINARY
set -u
sph=$1
source "$(dirname "$0")/test_lib.sh"

"$sph" run kepler --set scene.e=0.9 --until 1 --every 0.5 --threads 1 --out "$work/e09" >/dev/null 2>"$work/e09.err"
rc=$?
ok "e = 0.9 at the default dt exits 5 or 8 (exit $rc)" test "$rc" -eq 5 -o "$rc" -eq 8
ok "e = 0.9: the warning names time.dt and the pericentre" \
  grep -q "time.dt = 0.002 is too large for the pericentre of bodies 0-1 (q = 0.0526 AU" "$work/e09.err"
ok "e = 0.9: warnings.csv names time.dt" grep -q "^timestep,.*time.dt" "$work/e09/warnings.csv"
if [ "$rc" -eq 5 ]; then
  ok "e = 0.9: warnings.csv ends with the divergence" sh -c "tail -n 1 '$work/e09/warnings.csv' | grep -q '^diverged,[0-9]*,.*energy grew'"
  ok "e = 0.9: warnings.csv is in the manifest" grep -q '"warnings.csv"' "$work/e09/manifest.json"
fi

"$sph" run kepler --until 2 --every 1 --threads 1 --out "$work/seed" >/dev/null 2>"$work/seed.err"
check "kepler at its defaults" 0 $?
ok "kepler at its defaults: no warning" test "$(wc -l < "$work/seed/warnings.csv")" -eq 1

"$sph" run kepler --set scene.e=0.9 --set time.dt=0 --set time.cfl=0.003 --until 1 --every 0.5 --threads 1 \
  --out "$work/adaptive" >/dev/null 2>"$work/adaptive.err"
rc=$?
ok "e = 0.9 adaptive exits 0 or 8 (exit $rc)" test "$rc" -eq 0 -o "$rc" -eq 8
lines=$(wc -l < "$work/adaptive/warnings.csv")
ok "e = 0.9 adaptive: exit 0 only without a warning" test "$rc" -ne 0 -o "$lines" -eq 1

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
