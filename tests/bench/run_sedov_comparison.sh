#!/usr/bin/env bash
# The 2D Sedov blast side by side with PySPH's stock example (pysph.examples.gas_dynamics.sedov: 10816
# particles from NDSPMHD's initial conditions, Gaussian kernel, h = 1.2 (m/rho)^(1/2), fixed dt = 1e-4,
# predict-evaluate-correct integrator: one force evaluation per step), one thread each, at the same
# particle count and neighbour count: this code's sedov scene with the Gaussian at eta = 1.2 on a
# hexagonal lattice of 10,8xx particles (the PySPH set is concentric rings). Particle-steps per second
# from each code's own timing of its steps (PySPH's "Run took", this code's "s wall"), and the ratio.
# Needs `apt-get install python3-pysph`.
#   tests/bench/run_sedov_comparison.sh BUILD_DIR OUT_DIR [TF, default 0.1]
set -euo pipefail
build=$1; out=$2; tf=${3:-0.1}
mkdir -p "$out"
sph="$build/app/headless/sph"
# n_side = 104: 10,864 particles on the hexagonal lattice of the square box (PySPH: 10,816)
"$sph" run sedov --set scene.n_side=104 --set kernel.type=gaussian --set kernel.eta=1.2 --threads 1 --until "$tf" \
  --out "$out/sph" > "$out/sph.log" 2>&1
line=$(grep "particle-steps/s" "$out/sph.log")
sph_n=$(echo "$line" | sed -E 's/.* ([0-9]+) particles.*/\1/')
sph_steps=$(echo "$line" | sed -E 's/.* after ([0-9]+) steps.*/\1/')
sph_wall=$(echo "$line" | sed -E 's/.* ([0-9.]+) s wall.*/\1/')
sph_rate=$(awk -v n="$sph_n" -v s="$sph_steps" -v w="$sph_wall" 'BEGIN { printf "%.4g", n * s / w }')
nb=$(awk -F, '/^step,/ { for (i = 1; i <= NF; ++i) if ($i == "neighbours_mean") c = i; next } c { v = $c } END { print v }' "$out/sph/diagnostics.csv")
echo "sph-sandbox: $sph_n particles, $sph_steps steps, $sph_wall s, $sph_rate particle-steps/s, $nb neighbours"
if ! /usr/bin/python3 -c "import pysph" 2> /dev/null; then
  echo "PySPH is not installed (apt-get install python3-pysph): no comparison"
  exit 0
fi
rm -rf "$out/pysph"
OMP_NUM_THREADS=1 /usr/bin/python3 -m pysph.examples.gas_dynamics.sedov -d "$out/pysph" --tf "$tf" --disable-output \
  > "$out/pysph.log" 2>&1
py_wall=$(grep -h "Run took" "$out/pysph.log" "$out/pysph"/*.log 2> /dev/null | head -1 | sed -E 's/.*Run took: *([0-9.]+).*/\1/')
py_steps=$(awk -v t="$tf" 'BEGIN { printf "%d", t / 1e-4 + 0.5 }')
py_rate=$(awk -v s="$py_steps" -v w="$py_wall" 'BEGIN { printf "%.4g", 10816 * s / w }')
echo "PySPH: 10816 particles, $py_steps steps, $py_wall s, $py_rate particle-steps/s"
awk -v a="$sph_rate" -v b="$py_rate" 'BEGIN { printf "ratio (this code / PySPH): %.2f\n", a / b }'
