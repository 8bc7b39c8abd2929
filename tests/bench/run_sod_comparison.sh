#!/usr/bin/env bash
# Speed against error on Sod at t = 0.15: this code (sod_bench) next to PySPH's stock Sod example
# (pysph_sod.py, needs `apt-get install python3-pysph`), at the same left-side particle counts,
# one thread each. Writes OUT/sod_t015.csv and OUT/sod_t015.md.
#   tests/bench/run_sod_comparison.sh BUILD_DIR OUT_DIR [nl list, default "320 640 1280 2560"]
set -euo pipefail
build=$1; out=$2; nls=${3:-"320 640 1280 2560"}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
csv="$out/sod_t015.csv"
echo "code,n_left,N_total,kernel,integrator,t_end,steps,wall_s,particle_steps_per_s,L1_rho,L1_v,L1_p" > "$csv"
for nl in $nls; do
  "$build/tests/bench/sod_bench" --t 0.15 --n "$nl" --kernels M4,M6 --integrators leapfrog --threads 1 |
    tee -a "$csv"
  if /usr/bin/python3 -c "import pysph" 2> /dev/null; then
    # pysph_sod.py prints code,nl,N_total,tf,run_seconds,L1_rho,L1_v,L1_p
    OMP_NUM_THREADS=1 /usr/bin/python3 "$here/pysph_sod.py" --nl "$nl" --tf 0.15 |
      awk -F, '{printf "%s,%s,%s,gaussian,PEC (dt=1e-4),%s,1500,%s,%.4g,%s,%s,%s\n", $1,$2,$3,$4,$5,1500*$3/$5,$6,$7,$8}' |
      tee -a "$csv"
  fi
done
{
  echo "| code | N left | N total | kernel | integrator | steps | wall [s] | particle-steps/s | L1(rho) | L1(v) | L1(p) |"
  echo "|---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|"
  tail -n +2 "$csv" | awk -F, '{printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1,$2,$3,$4,$5,$7,$8,$9,$10,$11,$12}'
} > "$out/sod_t015.md"
cat "$out/sod_t015.md"
