#!/usr/bin/env bash
# Do two builds of `sph` give bitwise the same results? Runs every scene of NEW's `sph list` briefly with
# both binaries and compares the result files byte for byte: every file of the run folder (particles_*.csv,
# errors.csv, diagnostics.csv, warnings.csv, csv_meta.json) but scene.json (the parameters, compared
# apart) and manifest.json (its checksums include scene.json's); a diagnostics.csv column whose header
# names a wall time (none today) is left out. Prints one line per scene:
#   NAME  identical            (result files equal; "(scene.json differs)" if only the parameters do)
#   NAME  DIFFERS: FILE ...    (result files that differ or exist on one side only)
#   NAME  FAILED: old=RC new=RC (a run's exit code was not 0, or differs)
# Exit 0 if every scene is identical, 1 otherwise, 2 on bad usage.
# usage: compare_binaries.sh OLD_SPH NEW_SPH OUTDIR [SCENE...]
#   Each run stops at T = t_end / 20 (from the scene's own scene.json) with a particle file at T/2 and T,
#   on one thread; SCENE_ARGS below shrinks the heavy scenes (a run takes ~10 s at most). Extra flags
#   for every run: COMPARE_SET="key=value ..." (e.g. COMPARE_SET="kernel.type=M6"). COMPARE_FULL=1 runs every
#   scene at its defaults to its t_end instead (about 10 minutes a binary on one core).
set -u
if [ $# -lt 3 ]; then
  sed -n '2,16p' "$0" >&2
  exit 2
fi
old=$1; new=$2; out=$3; shift 3
for b in "$old" "$new"; do
  [ -x "$b" ] || { echo "compare_binaries: $b is not an executable" >&2; exit 2; }
done
mkdir -p "$out" || exit 2

# Smaller versions of the scenes that would take more than ~10 s to reach t_end / 20.
scene_args() {
  case $1 in
    sedov) echo "--set scene.n_side=48" ;;
    sedov3d) echo "--set scene.n_side=12" ;;
    noh) echo "--set scene.n_side=60" ;;
    kelvin_helmholtz) echo "--set scene.n_side=48" ;;
    gresho) echo "--set scene.n_side=32" ;;
    polytrope | evrard | dust_sphere) echo "--set scene.n=500" ;;
    dust_collision) echo "--set scene.n=300" ;;
    colliding_polytropes) echo "--set scene.n=200 --set scene.relax=0.2" ;;
    shocktube_castellanos) echo "--set scene.n_left=320" ;;
    *) echo "" ;;
  esac
}

# The time of a scene's run: t_end / 20 as its scene.json (written by a run to t = 0) says.
run_time() {
  local dir=$out/.probe_$1
  rm -rf "$dir"
  "$old" run "$1" --until 0 --quiet --out "$dir" > /dev/null 2>&1 || { echo ""; return; }
  sed -n 's/^ *"time.t_end": *\([0-9.eE+-]*\),\{0,1\}$/\1/p' "$dir/scene.json" | awk '{ printf "%.6g\n", $1 / 20 }'
  rm -rf "$dir"
}

# The result files of a run folder.
results() {
  (cd "$1" && ls | grep -v -x -e scene.json -e manifest.json)
}
strip_timing() {  # columns whose header names a wall time (wall, time_ms, seconds, ...)
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) skip[i] = ($i ~ /wall|_ms$|_s$|seconds|elapsed/) }
           { line = ""; for (i = 1; i <= NF; i++) if (!skip[i]) line = line (line == "" ? "" : ",") $i; print line }' "$1"
}

status=0
scenes=$("$new" list | awk '{ print $1 }')
[ $# -gt 0 ] && scenes="$*"
for scene in $scenes; do
  T=$(run_time "$scene")
  if [ -z "$T" ]; then
    printf '%-24s FAILED: the old binary does not run it\n' "$scene"; status=1; continue
  fi
  half=$(awk -v t="$T" 'BEGIN { printf "%.6g", t / 2 }')
  # shellcheck disable=SC2046,SC2086
  args=(run "$scene" --until "$T" --set "time.dt_out=$half" --threads 1 --quiet $(scene_args "$scene"))
  [ -n "${COMPARE_FULL:-}" ] && args=(run "$scene" --threads 1 --quiet)
  for kv in ${COMPARE_SET:-}; do args+=(--set "$kv"); done
  rm -rf "$out/old/$scene" "$out/new/$scene"
  "$old" "${args[@]}" --out "$out/old/$scene" > "$out/old_$scene.log" 2>&1; rc_old=$?
  "$new" "${args[@]}" --out "$out/new/$scene" > "$out/new_$scene.log" 2>&1; rc_new=$?
  if [ $rc_old -ne 0 ] || [ $rc_new -ne 0 ]; then
    printf '%-24s FAILED: old=%d new=%d (logs in %s)\n' "$scene" $rc_old $rc_new "$out"; status=1; continue
  fi
  differs=""
  for f in $( (results "$out/old/$scene"; results "$out/new/$scene") | sort -u); do
    a=$out/old/$scene/$f; b=$out/new/$scene/$f
    if [ ! -e "$a" ] || [ ! -e "$b" ]; then differs="$differs $f(one side only)"; continue; fi
    if [ "$f" = diagnostics.csv ]; then
      cmp -s <(strip_timing "$a") <(strip_timing "$b") || differs="$differs $f"
    else
      cmp -s "$a" "$b" || differs="$differs $f"
    fi
  done
  if [ -n "$differs" ]; then
    printf '%-24s DIFFERS:%s\n' "$scene" "$differs"; status=1
  else
    note=""
    cmp -s "$out/old/$scene/scene.json" "$out/new/$scene/scene.json" || note=" (scene.json differs)"
    printf '%-24s identical%s\n' "$scene" "$note"
  fi
done
exit $status
