#!/usr/bin/env bash
# The elliptical drop (seed 001 §7.1) at dx = 0.025 to t = 0.0076, one thread each: this code's three
# formulations next to PySPH's own example (WCSPH, needs `apt-get install python3-pysph`). Whole-process
# wall times from /usr/bin/time; the semi-axes measured the same way for both (extent of the particles).
#   tests/bench/run_drop_comparison.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
mkdir -p "$out"
csv="$out/drop.csv"
echo "code,variant,N,wall_s,major,err_major,ab" > "$csv"
wall() { /usr/bin/time -f "%e" -o "$out/time.txt" "$@" > "$out/run.log" 2>&1; cat "$out/time.txt"; }
for variant in elliptical_drop elliptical_drop_standard elliptical_drop_corrected; do
  w=$(wall "$build/app/headless/sph" run "$root/assets/scenes/$variant.json" --threads 1)
  line=$(grep "major =" "$out/run.log")
  get() { echo "$line" | sed -E "s/.* $1 = ([^ ]+).*/\1/"; }
  echo "sph-sandbox,$variant,5025,$w,$(get major),$(get err_major),$(get ab)" | tee -a "$csv"
done
if /usr/bin/python3 -c "import pysph" 2> /dev/null; then
  rm -rf "$out/pysph"
  w=$(OMP_NUM_THREADS=1 wall /usr/bin/python3 -m pysph.examples.elliptical_drop -d "$out/pysph" --tf 0.0076)
  /usr/bin/python3 "$here/pysph_drop_axes.py" "$out/pysph" |
    awk -F, -v w="$w" '{printf "pysph,wcsph (Gaussian; h = 1.3 dx),%s,%s,%s,%s,%s\n", $2, w, $5, $6, $7}' | tee -a "$csv"
fi
column -s, -t < "$csv"
