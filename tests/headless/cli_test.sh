#!/usr/bin/env bash
# The sph command line: output files, exit codes, and that bad input writes nothing (README "Exit codes").
# usage: cli_test.sh PATH_TO_SPH REPO_ROOT
set -u
sph=$1; root=$2
source "$(dirname "$0")/test_lib.sh"

# a run writes every file, the last particle file at the end time
"$sph" run sod --set scene.n_left=100 --out "$work/sod" > "$work/sod.log"; check "run sod" 0 $?
for f in scene.json diagnostics.csv errors.csv particles_00000.csv particles_00004.csv csv_meta.json; do
  ok "sod writes $f" test -s "$work/sod/$f"
done
ok "no particle file past the end" test ! -e "$work/sod/particles_00005.csv"
ok "last particle file is at t = 0.2" grep -A1 '"file": "particles_00004.csv"' "$work/sod/csv_meta.json" | grep -q '"t": 0.2,'
# plain CSVs: the first line is the header (the comment lines went to csv_meta.json)
ok "diagnostics header" test "$(head -1 "$work/sod/diagnostics.csv" | cut -d, -f1-13)" = "step,t,dt,E_kin,E_int,E_pot,E_tot,px,py,pz,Lx,Ly,Lz"
ok "particle header" test "$(head -1 "$work/sod/particles_00004.csv")" = "id,x,y,z,vx,vy,vz,m,rho,p,u,h"
ok "errors header" test "$(head -1 "$work/sod/errors.csv" | cut -d, -f1-3)" = "t,count,L1_rho"
ok "no comment line in any CSV" test -z "$(grep -l '^#' "$work/sod"/*.csv)"
ok "csv_meta.json says what L1 is" grep -q '"errors.csv": "L1 = mean over particles' "$work/sod/csv_meta.json"
"$sph" run sod --set scene.n_left=100 --until 0.05 --csv-comments --out "$work/comments" > /dev/null; check "--csv-comments" 0 $?
ok "--csv-comments: the time line" grep -q "^# t = 0.05," "$work/comments/particles_00001.csv"
ok "--csv-comments: what L1 is" grep -q "^# L1 = mean over particles" "$work/comments/errors.csv"
ok "--csv-comments: no csv_meta.json" test ! -e "$work/comments/csv_meta.json"
ok "summary prints L1" grep -q "L1_rho = " "$work/sod.log"
ok "summary: a value the reference does not define is a dash" grep -q "rho_min = —" "$work/sod.log"
ok "summary: no nan" test -z "$(grep -i "= nan" "$work/sod.log")"
# scene.json is a complete scene file: running it again gives the same result
"$sph" run "$work/sod/scene.json" --out "$work/again" > /dev/null; check "rerun scene.json" 0 $?
ok "same particles from scene.json" cmp -s "$work/sod/particles_00004.csv" "$work/again/particles_00004.csv"
# same particle files with 1 and 2 threads (6000 particles: above the size where thread teams start)
for t in 1 2; do
  "$sph" run box_random --set scene.count=6000 --until 0.02 --set dt_out=0.01 --threads $t --out "$work/threads$t" > /dev/null
  check "box_random --threads $t" 0 $?
done
ok "1 and 2 threads: identical particle files" cmp -s "$work/threads1/particles_00002.csv" "$work/threads2/particles_00002.csv"
# idle threads spin briefly, then sleep, unless the user chose otherwise (sph/thread_wait.h: the program
# restarts itself once)
env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$sph" run sod --set scene.n_left=50 --until 0.01 --threads 2 --out "$work/wait" > "$work/wait.log"
check "run without OMP_WAIT_POLICY" 0 $?
ok "threads spin 20000 turns by default" grep -q "idle threads: spin 20000 turns, then sleep)" "$work/wait.log"
OMP_WAIT_POLICY=active "$sph" run sod --set scene.n_left=50 --until 0.01 --threads 2 --out "$work/wait2" > "$work/wait2.log"
ok "a wait policy the user set is kept" grep -q "idle threads: active)" "$work/wait2.log"
env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=7 "$sph" run sod --set scene.n_left=50 --until 0.01 --threads 2 --out "$work/wait3" > "$work/wait3.log"
ok "a spin count the user set is kept" grep -q "idle threads: spin 7 turns, then sleep)" "$work/wait3.log"
# a liquid scene with walls: its own columns (no u), the kind of each particle, its reference's columns
"$sph" run hydrostatic_tank --set scene.dx=0.1 --until 0.02 --set dt_out=0.01 --out "$work/tank" > /dev/null
check "run hydrostatic_tank" 0 $?
ok "liquid particle header" grep -q "^id,x,y,z,vx,vy,vz,m,rho,p,h,kind$" "$work/tank/particles_00002.csv"
ok "liquid errors header" grep -q "^t,p_mid,p_mid_exact,err_mid,L1_p_rel,valid$" "$work/tank/errors.csv"
ok "wall particles are marked" grep -q ",1$" "$work/tank/particles_00002.csv"
# scene.json lists only the parameters of the stages the scene runs
"$sph" run box_lattice --until 0 --out "$work/lat" > /dev/null; check "run box_lattice" 0 $?
ok "no viscosity keys without a viscosity stage" test -z "$(grep 'visc\.' "$work/lat/scene.json")"
ok "gas keys for a gas" grep -q '"gas.gamma"' "$work/lat/scene.json"
ok "no gas keys for a liquid" test -z "$(grep '"gas\.' "$work/tank/scene.json")"
ok "sod has its viscosity" grep -q '"visc.alpha"' "$work/sod/scene.json"

# every shipped scene file is valid
for f in "$root"/assets/scenes/*.json; do "$sph" check "$f" > /dev/null; check "check $f" 0 $?; done
# the shipped scene files are generated: scene-json prints one, write-assets writes all (scenes/scene_assets_test
# checks they equal the compiled defaults)
"$sph" scene-json sod > "$work/sod_asset.json"; check "scene-json sod" 0 $?
ok "scene-json is the shipped file" cmp -s "$work/sod_asset.json" "$root/assets/scenes/sod.json"
"$sph" scene-json no_such_scene > "$work/none.json" 2> "$work/none.err"; check "scene-json of an unknown name" 3 $?
ok "scene-json names the unknown scene" grep -q "unknown scene 'no_such_scene'" "$work/none.err"
ok "scene-json prints nothing for it" test ! -s "$work/none.json"
mkdir -p "$work/assets"
"$sph" write-assets "$work/assets" > /dev/null; check "write-assets" 0 $?
ok "write-assets writes a file per scene" test "$(ls "$work/assets" | wc -l)" = "$("$sph" list | grep -cE '^[a-z0-9_]+ +[123]D  ')"
ok "list names the seed documents it cites" grep -q "^  seed 003: F. Castellanos Fuentes (2010)" <("$sph" list)
ok "write-assets writes what scene-json prints" cmp -s "$work/assets/sod.json" "$work/sod_asset.json"
"$sph" write-assets "$work/no_such_folder" 2> /dev/null; check "write-assets into a missing folder" 4 $?

# bad input: exit 3 (invalid scene) or 2 (usage), a message naming the key, nothing written
bad() {  # bad NAME EXPECTED_RC WORD_IN_MESSAGE ARGS...
  local name=$1 rc=$2 word=$3; shift 3
  "$sph" "$@" --out "$work/$name" 2> "$work/$name.err" > /dev/null; check "$name" "$rc" $?
  ok "$name: message names '$word'" grep -q -- "$word" "$work/$name.err"
  ok "$name: nothing written" test ! -e "$work/$name"
}
bad unknown_key 3 "nope" run sod --set nope=1
bad out_of_range 3 "eta" run sod --set eta=9
bad not_a_number 3 "alpha" run sod --set alpha=abc
bad unknown_scene_key 3 "scene.zz" run sod --set scene.zz=3
bad unknown_scene 3 "no_such" run no_such
echo '{"scene": "sod", "params": {"kernel": "M9"}}' > "$work/k.json"
bad bad_kernel_file 3 "k.json" run "$work/k.json"
echo '{"scene": "sod",' > "$work/m.json"
bad malformed_file 3 "m.json" run "$work/m.json"
ok "malformed_file: the parser's position, not its internal id" grep -q "malformed JSON: parse error at line 2" "$work/malformed_file.err"
ok "malformed_file: no [json.exception...] id" test -z "$(grep json.exception "$work/malformed_file.err")"
bad choice_case 3 "did you mean M6?" run sod --set kernel.type=m6
bad choice_typo 3 "did you mean leapfrog?" run sod --set time.integrator=leapfrg
bad scene_range 3 "out of range \[4, 1000000\]" run sod --set scene.n_left=2
echo '{"scene": "sod", "extra": 1}' > "$work/e.json"
bad unknown_top_key 3 "extra" run "$work/e.json"
bad bad_threads 2 "threads" run sod --threads 0
bad no_viscosity_stage 3 "physics.viscosity = none" run box_lattice --set alpha=5
bad inactive_new_key 3 "visc.alpha" run box_lattice --set visc.alpha=5
bad liquid_key_on_gas 3 "liquid.c0" run sod --set liquid.c0=10
bad slot_not_for_scene 3 "physics.eos" run sod --set physics.eos=tait
bad nonsense_combination 3 "physics.energy" run box_lattice --set physics.eos=isothermal
bad negative_until 2 "until" run sod --until -3
bad h_solve_fails_at_start 5 "kernel.eta" run sod --set eta=0.6

# I/O error
"$sph" run sod --set scene.n_left=50 --until 0.01 --out /proc/sph-cannot-write 2> "$work/io.err" > /dev/null
check "io error" 4 $?

# divergence: an explicit Euler step far beyond the CFL limit blows up; exit 5 names particle and step
"$sph" run sod --set integrator=euler --set dt=0.05 --out "$work/div" 2> "$work/div.err" > /dev/null
check "diverged" 5 $?
ok "diverged message" grep -q "particle [0-9]* has a non-finite .* at step [0-9]*" "$work/div.err"
ok "no particle file of the diverged state" test ! -e "$work/div/particles_00004.csv"
ok "diverged: warnings.csv's last row names it" \
  sh -c "tail -n 1 '$work/div/warnings.csv' | grep -q '^diverged,[0-9]*,[0-9.e-]*,[0-9]*,1,\"simulation diverged: particle [0-9]* has a non-finite'"
ok "diverged: the message points to warnings.csv" grep -q "warnings.csv records the divergence" "$work/div.err"
# a timestep far too long for the h solve: exit 5, the message names what failed (no "particle -1")
"$sph" run sod --set dt=0.01 --out "$work/dt" 2> "$work/dt.err" > /dev/null
check "dt too long" 5 $?
ok "dt too long: names the smoothing length" grep -q "smoothing length" "$work/dt.err"
ok "dt too long: no particle -1" bash -c "! grep -q 'particle -1' '$work/dt.err'"

# headless frames (OSMesa build): no DISPLAY needed; at least two 640x480 PNGs for a 2D and a 1D scene
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $3*256+$4 "x" $7*256+$8}'; }
if "$sph" run --help | grep -q -- "--frames"; then
  for scene in box_random sod; do
    env -u DISPLAY "$sph" run $scene --until 0.2 --frames "$work/fr_$scene" --every 0.1 --size 640x480 > /dev/null
    check "frames $scene" 0 $?
    ok "frames $scene: at least two" test -s "$work/fr_$scene/frame_00001.png"
    ok "frames $scene: 640x480" test "$(png_size "$work/fr_$scene/frame_00001.png")" = "640x480"
  done
  env -u DISPLAY "$sph" run sod --until 0 --frames "$work/pct" --range p1:99 --size 640x480 > /dev/null
  check "frames with a percentile range" 0 $?
  ok "percentile range frame" test -s "$work/pct/frame_00000.png"
  bad reversed_percentiles 2 "pLO:HI" run sod --frames "$work/bp" --range p50:10
  bad odd_size 2 "size" run sod --frames "$work/odd" --size 641x480
  bad junk_size 2 "size" run sod --frames "$work/junk" --size 640x480junk
  bad unknown_field 2 "nope" run sod --frames "$work/nf" --color-by nope
  bad tree_probe_without_tree 2 "tree-probe" run sod --frames "$work/tp" --tree-probe 3
  bad tree_probe_out_of_range 2 "tree-probe" run dust_sphere --set scene.n=100 --frames "$work/tp" --color-by phi --tree-probe 100
  env -u DISPLAY "$sph" run dust_sphere --set scene.n=300 --until 0.05 --frames "$work/tp" --every 0.05 --color-by phi \
    --tree-probe 3 --size 640x480 > /dev/null
  check "frames with the tree overlay" 0 $?
  ok "tree overlay frame" test -s "$work/tp/frame_00001.png"
  bad cut_axis 2 "--cut w=0: expected AXIS=VALUE" run dust_sphere --set scene.n=100 --frames "$work/cw" --cut w=0
  bad cut_value 2 "--cut z=a" run dust_sphere --set scene.n=100 --frames "$work/cv" --cut z=a
  bad cut_beyond_float 2 "--cut z=1e300" run dust_sphere --set scene.n=100 --frames "$work/cf" --cut z=1e300
  env -u DISPLAY "$sph" run dust_sphere --set scene.n=300 --until 0 --frames "$work/cut" --cut z=0 --size 640x480 \
    > /dev/null
  check "a 3D cutaway frame" 0 $?
  ok "cutaway frame" test -s "$work/cut/frame_00000.png"
fi

# convergence studies: a table with observed orders; bad input is refused before anything runs
"$sph" converge burgers_upwind --values 60,120,240 --out "$work/conv" --quiet
check "converge" 0 $?
ok "converge csv" test "$(grep -c '^[0-9]' "$work/conv/converge.csv")" = 3
ok "converge csv: the spacing is dx, not h (the smoothing length)" grep -q "^value,dx,error,order" "$work/conv/converge.csv"
ok "converge md" grep -q "| 240 |" "$work/conv/converge.md"
if "$sph" run --help | grep -q -- "--frames"; then
  ok "converge plot" test "$(png_size "$work/conv/converge.png")" = "1280x720"
fi
bad converge_no_reference 3 "reference" converge box_lattice
bad converge_unknown_column 3 "nope" converge burgers_upwind --column nope
bad converge_one_value 3 "two values" converge burgers_upwind --values 60
bad converge_junk_value 3 "abc" converge burgers_upwind --values 60,abc
bad converge_bad_key 3 "scene.nope" converge burgers_upwind --key scene.nope --values 1,2
bad converge_diverged 5 "diverged" converge sod --set time.integrator=euler --set time.dt=0.05 --values 40,80


# runs that never go bad silently: a clean run has an empty warnings.csv; a degraded one says so by
# name (stderr and warnings.csv) and still exits 0; an unstable one stops with exit 5 naming a particle.
# The coarse run above (n_left = 100) is outside what the reference's bounds assume, and beyond one.
"$sph" run sod --out "$work/sod400" > /dev/null 2>&1; check "run sod at its defaults" 0 $?
ok "clean run: warnings.csv header only" test "$(wc -l < "$work/sod400/warnings.csv")" -eq 1
ok "coarse run: the assumption named" grep -q '^assumption,.*scene.n_left = 100' "$work/sod/warnings.csv"
ok "coarse run: the error beyond its bound named" grep -q '^accuracy:L1_rho,.*L1_rho = ' "$work/sod/warnings.csv"
"$sph" run sod --set time.integrator=euler --out "$work/euler" > /dev/null 2> "$work/euler.err"; check "euler sod" 0 $?
ok "euler: warnings section" grep -q "^warnings (2):" "$work/euler.err"
ok "euler: the error beyond its bound" grep -q '^accuracy:L1_rho,' "$work/euler/warnings.csv"
ok "euler: names the integrator" grep -q "forward Euler is unstable" "$work/euler.err"
ok "euler: warnings.csv row" grep -q '^energy,' "$work/euler/warnings.csv"
"$sph" run sod --set time.cfl=0.7 --out "$work/cfl7" > /dev/null 2> "$work/cfl7.err"; check "cfl 0.7 sod" 0 $?
ok "cfl 0.7: names time.cfl" grep -q "lower time.cfl" "$work/cfl7.err"
# (what was written before the stop is the good start and steps within 10% of the energy scale)
"$sph" run sod --set time.cfl=0.9 --out "$work/cfl9" > /dev/null 2> "$work/cfl9.err"; check "cfl 0.9 sod" 5 $?
ok "cfl 0.9: says why" grep -q "total energy grew" "$work/cfl9.err"
ok "cfl 0.9: names a particle" grep -q "particle [0-9]* has the largest acceleration" "$work/cfl9.err"
ok "cfl 0.9: no runaway energy written" awk -F, 'NR > 1 { if ($7 > 1.6 || $7 < 1.2) bad = 1 } END { exit bad }' "$work/cfl9/diagnostics.csv"
"$sph" run toro1 --set scene.x_lo=0 --set scene.n_left=300 --out "$work/t1" > /dev/null 2> "$work/t1.err"; check "toro1 on [0,1]" 0 $?
ok "toro1 on [0,1]: reference warning" grep -q "\[reference\]" "$work/t1.err"
ok "toro1 on [0,1]: errors.csv marks invalid rows" test "$(tail -1 "$work/t1/errors.csv" | awk -F, '{print $NF}')" = 0
ok "toro1 on [0,1]: first rows valid" test "$(sed -n 2p "$work/t1/errors.csv" | awk -F, '{print $NF}')" = 1
# numeric flags: NaN, inf and out-of-range values are usage errors naming the flag
bad until_nan 2 "until" run sod --until nan
bad until_negative 2 "until" run sod --until -3
bad until_inf 2 "until" run sod --until inf
if "$sph" run --help | grep -q -- "--frames"; then
  bad every_zero 2 "every" run sod --frames "$work/fz" --every 0
  bad every_nan 2 "every" run sod --frames "$work/fn" --every nan
fi
bad converge_until_zero 2 "until" converge sod --until 0

# sph bench: every run in bench.csv (error, wall time), a table, and a plot per scene
"$sph" bench sod --values 50,100 --kernels M4,wendland_c2 --integrators leapfrog --out "$work/bench" --quiet
check "bench sod" 0 $?
ok "bench csv rows" test "$(grep -c '^sod,' "$work/bench/bench.csv")" = 4
ok "bench csv valid runs" test -z "$(grep '^sod,' "$work/bench/bench.csv" | awk -F, '$10 != 1')"
ok "bench md" grep -q "| wendland_c2 / leapfrog | 100 |" "$work/bench/bench.md"
if "$sph" run --help | grep -q -- "--frames"; then
  ok "bench plot" test "$(png_size "$work/bench/bench_sod.png")" = "1280x720"
fi
# a timestep study (kepler's energy error against time.dt): leapfrog is second order, --kernels ignored
"$sph" bench kepler --values 0.008,0.004 --kernels M6 --integrators leapfrog --out "$work/bk" --quiet; check "bench kepler" 0 $?
ok "bench kepler: order 2" grep -q "| - / leapfrog | 0.004 | 2 | .* | 1.9[0-9] |" "$work/bk/bench.md"
# DFSPH steps by its own scheme: --integrators does not apply to it (one series, integrator "dfsph")
"$sph" bench dam_break_dfsph --values 0.1,0.05 --kernels M4 --integrators leapfrog,rk4 --out "$work/bd" --quiet
check "bench dam_break_dfsph" 0 $?
ok "bench dfsph: one series" test "$(grep -c '^dam_break_dfsph,M4,dfsph,scene.dx,' "$work/bd/bench.csv")" = 2
bad bench_bad_kernel 3 "M9" bench sod --kernels M9 --values 50,100
bad bench_bad_integrator 3 "verlet" bench sod --integrators verlet --values 50,100
bad bench_no_reference 3 "reference" bench box_lattice
bad bench_junk_value 3 "abc" bench sod --values 50,abc

# A/B comparison: run B stepped to A's times, its files in OUT/B, its L1 beside A's in the summary
"$sph" run sod --set scene.n_left=100 --compare-set kernel.type=M6 --out "$work/ab" > "$work/ab.log"
check "compare" 0 $?
ok "compare: B's files" test -s "$work/ab/B/particles_00004.csv"
ok "compare: B's scene is M6" grep -q '"kernel.type": "M6"' "$work/ab/B/scene.json"
ok "compare: A stays M4" grep -q '"kernel.type": "M4"' "$work/ab/scene.json"
ok "compare: B at A's end time" grep -q '"t": 0.2,' "$work/ab/B/csv_meta.json"
ok "compare: B's summary with its L1" grep -q "^run B: kernel.type=M6: t = 0.2 .*L1_rho = " "$work/ab.log"
ok "compare: A's files as without B" cmp -s "$work/ab/particles_00004.csv" "$work/sod/particles_00004.csv"
# a scene file as run B: its differences name it
"$sph" run sod --set scene.n_left=100 --until 0 --compare "$root/assets/scenes/sod.json" --compare-set visc.alpha=0.5 \
  --set visc.alpha=1 > "$work/abf.log"; check "compare with a file" 0 $?
ok "compare with a file: label" grep -q "^run B: visc.alpha=0.5, scene.n_left=400" "$work/abf.log"
bad compare_other_scene 3 "same scene" run sod --compare lax
bad compare_bad_key 3 "nope" run sod --compare-set nope=1
bad compare_not_kv 3 "key=value" run sod --compare-set M6
# a parameter sweep: each run stepped to A's times with its errors in the summary; A's files as without it
"$sph" run sod --set scene.n_left=100 --sweep kernel.eta=1,1.5 --out "$work/sw" > "$work/sw.log"
check "sweep" 0 $?
ok "sweep: each run's L1 in the summary" grep -q "^sweep run kernel.eta=1.5: t = 0.2 after [0-9]* steps .*L1_rho = " "$work/sw.log"
ok "sweep: one line a run" test "$(grep -c '^sweep run' "$work/sw.log")" = 2
ok "sweep: A's files as without it" cmp -s "$work/sw/particles_00004.csv" "$work/sod/particles_00004.csv"
bad sweep_not_kv 2 "KEY=V1,V2" run sod --sweep kernel.eta
bad sweep_six 2 "at most 5" run sod --sweep kernel.eta=1,1.1,1.2,1.3,1.4,1.5
bad sweep_bad_value 3 "kernel.eta = 9" run sod --sweep kernel.eta=1,9
bad sweep_and_compare 2 "not with --compare" run sod --sweep kernel.eta=1 --compare-set visc.alpha=0
if "$sph" run --help | grep -q -- "--frames"; then
  env -u DISPLAY "$sph" run sod --set scene.n_left=100 --sweep kernel.eta=1,1.5 --frames "$work/swfr" --every 0.2 \
    --panels rho,v --size 640x480 > /dev/null
  check "sweep frames with panels" 0 $?
  ok "sweep frames" test "$(png_size "$work/swfr/frame_00001.png")" = "640x480"
  env -u DISPLAY "$sph" run sod --set scene.n_left=100 --compare-set visc.alpha=0 --frames "$work/abfr" --every 0.2 \
    --panels rho,v,p,u --size 640x480 > /dev/null
  check "compare frames with panels" 0 $?
  ok "compare frames" test "$(png_size "$work/abfr/frame_00001.png")" = "640x480"
  bad bad_panel 2 "nope" run sod --frames "$work/bp" --panels rho,nope
fi

# help that teaches: a scene's stages and parameters, every key, and the nearest valid name for a typo
"$sph" help sod > "$work/help.txt"; check "help sod" 0 $?
for word in "physics.density" "kernel.type" "gas.gamma" "visc.alpha" "scene.n_left" "L1_rho" "seed 000 eq. 3.3.23" "range ["; do
  ok "help sod mentions $word" grep -qF "$word" "$work/help.txt"
done
"$sph" help > "$work/scenes.txt"; check "help" 0 $?
ok "help lists the scenes" grep -q "^  kelvin_helmholtz " "$work/scenes.txt"
"$sph" params > "$work/params.txt"; check "params" 0 $?
ok "params lists every key" test "$(grep -c '^  [a-z_]*\.[a-z_0-9]* ' "$work/params.txt")" -ge 40
bad typo_key 3 "did you mean scene.n_left?" run sod --set scene.n_lef=100
bad typo_key_no_group 3 "did you mean scene.n_left?" run sod --set n_left=100
bad typo_run_key 3 "did you mean visc.alpha?" run sod --set visc.alpah=1
bad typo_scene 3 "did you mean sod?" run sodd
bad typo_flag 2 "did you mean --vtu?" run sod --vtk
bad typo_command 2 "did you mean run?" rnu sod
"$sph" help keplr > /dev/null 2> "$work/help_typo.err"; check "help of a typo'd scene" 3 $?
ok "help keplr: suggestion" grep -q "did you mean kepler?" "$work/help_typo.err"
"$sph" run sod --set scene.n_left=50 --until 0 --vtu 2> "$work/vtu.err" > /dev/null; check "--vtu without --out" 2 $?
ok "--vtu without --out: says why" grep -q -- "--vtu needs --out" "$work/vtu.err"
bad hdf5_of_fpm 2 "finite pointset" run burgers_upwind --hdf5
bad probe_no_reference 2 "no reference" run box_lattice --probe-every 0.01

# --probe-every: errors.csv every DT of simulated time, the particle files at time.dt_out as before
"$sph" run dam_break --set scene.dx=0.1 --until 0.1 --probe-every 0.01 --out "$work/probe" --quiet; check "--probe-every" 0 $?
ok "--probe-every: a row at t = 0 and every 0.01 s (11 rows)" test "$(tail -n +2 "$work/probe/errors.csv" | wc -l)" = 11
ok "--probe-every: the row at t = 0.05 s" grep -q "^0.05," "$work/probe/errors.csv"
ok "--probe-every: particle files at time.dt_out (0.05) only" test "$(ls "$work/probe" | grep -c '^particles_')" = 3
"$sph" export-ics sod --format swfit --out "$work/x.hdf5" 2> "$work/exf.err"; check "export-ics bad format" 2 $?
ok "export-ics bad format: suggestion" grep -q "did you mean swift?" "$work/exf.err"
ok "export-ics bad format: nothing written" test ! -e "$work/x.hdf5"
"$sph" export-ics burgers_upwind --out "$work/b.hdf5" 2> "$work/exb.err"; check "export-ics of an FPM scene" 3 $?
ok "export-ics of an FPM scene: nothing written" test ! -e "$work/b.hdf5"

# --hide-walls: the 3D tank's water, otherwise hidden behind its walls, drawn without them
for w in shown hidden; do
  flag=""; [ "$w" = hidden ] && flag="--hide-walls"
  "$sph" run hydrostatic_tank_3d --until 0.001 --frames "$work/walls_$w" --every 1 --size 640x360 $flag --quiet \
    > /dev/null 2>&1; check "frames, walls $w" 0 $?
done
read -r worst differ < <(python3 "$root/tests/headless/png_pixels.py" --diff "$work/walls_shown/frame_00000.png" "$work/walls_hidden/frame_00000.png")
ok "--hide-walls changes a tenth of the 3D tank's frame at least ($differ pixels differ)" test "$differ" -gt 23040

# the EGL backend draws the frames a machine without OSMesa would (Mesa 25.1 removed OSMesa)
if "$sph" run --help | grep -q -- "--gl"; then
  for gl in osmesa egl; do
    env -u DISPLAY "$sph" run sod --set scene.n_left=100 --until 0.1 --frames "$work/gl_$gl" --every 0.1 --size 640x360 \
      --gl $gl > /dev/null; check "frames --gl $gl" 0 $?
  done
  read -r worst differ < <(python3 "$root/tests/headless/png_pixels.py" --diff "$work/gl_osmesa/frame_00001.png" "$work/gl_egl/frame_00001.png")
  ok "EGL frame = OSMesa frame within 2/255 (largest difference $worst, $differ pixels differ)" test "$worst" -le 2
  bad typo_gl 2 "did you mean egl?" run sod --frames "$work/gl_bad" --gl egll
  bad typo_color_by 2 "did you mean rho?" run sod --frames "$work/cb" --color-by rhoo
fi

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
