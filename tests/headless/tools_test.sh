#!/usr/bin/env bash
# The output formats opened by the field's own tools: TOOL is paraview (a --vtu series read by ParaView's
# Python), splash (SPLASH draws a PNG from a --splash file, headless), hdf5 (h5py reads --hdf5 snapshots
# and exported SWIFT/GADGET-4 ICs; export -> sph run FILE.hdf5 gives the same initial state; a SWIFT-style
# IC runs), video (ffmpeg makes the MP4, the GIF and the last frame). A tool that is not installed makes
# the test skip (exit 77) with the package to install.
# usage: tools_test.sh TOOL PATH_TO_SPH REPO_ROOT
set -u
tool=$1; sph=$2; root=$3; here="$root/tests/headless"
source "$(dirname "$0")/test_lib.sh"
skip() { echo "SKIP: $1"; exit 77; }
py=/usr/bin/python3  # Debian's Python, where python3-h5py and python3-paraview install their modules

case $tool in
paraview)
  if command -v pvpython > /dev/null; then pv=(pvpython --force-offscreen-rendering)
  elif $py -c "import paraview.simple" 2> /dev/null; then pv=($py)
  else skip "ParaView's Python is not installed (apt-get install paraview python3-paraview)"; fi
  "$sph" run sod --set scene.n_left=100 --vtu --out "$work/sod" > /dev/null; check "sod --vtu" 0 $?
  ok "sod: one .vtu per particle file" test "$(ls "$work/sod"/particles_*.vtu | wc -l)" = "$(ls "$work/sod"/particles_*.csv | wc -l)"
  env -u DISPLAY "${pv[@]}" "$here/read_pvd.py" "$work/sod" > "$work/pv_sod.log" 2>&1; check "ParaView reads the 1D series" 0 $?
  "$sph" run hydrostatic_tank --set scene.dx=0.1 --until 0.02 --set dt_out=0.01 --vtu --out "$work/tank" > /dev/null
  check "tank --vtu" 0 $?
  env -u DISPLAY "${pv[@]}" "$here/read_pvd.py" "$work/tank" > "$work/pv_tank.log" 2>&1; check "ParaView reads the 2D series with walls" 0 $?
  cat "$work"/pv_*.log | grep -v "^t = " ;;
splash)
  command -v splash > /dev/null || skip "SPLASH is not installed (apt-get install splash)"
  "$sph" run sod --set scene.n_left=200 --splash --out "$work/sod" > /dev/null; check "sod --splash" 0 $?
  # headless: the PNG device, no questions asked (stdin closed); column 1 x, 3 rho (x, vx, m, rho, ...)
  (cd "$work/sod" && splash -ascii -x 1 -y 4 -dev /png particles_00004.dat < /dev/null > splash.log 2>&1); check "splash 1D" 0 $?
  ok "splash read the time" grep -q "setting time =.*0.2" "$work/sod/splash.log"
  ok "splash read gamma" grep -Eq "setting gamma = +1\.(4|39999)" "$work/sod/splash.log"
  ok "splash found density, mass and h" grep -q "density in column  4, mass in  3, h in  5" "$work/sod/splash.log"
  ok "splash drew a PNG" test -s "$work/sod/splash.png"
  read -r w h dark colours < <($py "$here/png_pixels.py" "$work/sod/splash.png")
  ok "1D PNG size ${w}x${h}" test "$w" -gt 100 -a "$h" -gt 100
  # 225 particles drawn as dots, plus the axes' frame and labels: far more dark pixels than the frame alone
  ok "1D PNG has the particles ($dark dark pixels)" test "$dark" -gt 2500
  "$sph" run box_random --set scene.count=400 --until 0.5 --set dt_out=0.5 --splash --out "$work/box" > /dev/null
  check "box --splash" 0 $?
  (cd "$work/box" && splash -ascii -x 1 -y 2 -r 6 -dev /png particles_00001.dat < /dev/null > splash.log 2>&1)
  check "splash renders 2D density" 0 $?
  read -r w h dark colours < <($py "$here/png_pixels.py" "$work/box/splash.png")
  ok "2D rendering has a colour map ($colours colours)" test "$colours" -gt 50 ;;
hdf5)
  $py -c "import h5py" 2> /dev/null || skip "h5py is not installed (apt-get install python3-h5py)"
  "$sph" run sod --set scene.n_left=100 --hdf5 --out "$work/sod" > /dev/null; check "sod --hdf5" 0 $?
  # SWIFT's h for M4 in 1D: the support 2h over gamma_K = 1.732051
  $py "$here/check_hdf5.py" "$work/sod/particles_00004.hdf5" "$work/sod/particles_00004.csv" swift 2/1.732051 0.2
  check "h5py reads a --hdf5 snapshot" 0 $?
  "$sph" export-ics sod --set scene.n_left=100 --format swift --out "$work/ics/sod.hdf5" > /dev/null 2> "$work/export.err"
  check "export-ics sod swift" 0 $?
  ok "SWIFT parameter file" grep -q "file_name: ./sod.hdf5" "$work/ics/sod.yml"
  ok "SWIFT kernel and dimension" grep -q "with-hydro-dimension=1 --with-kernel=cubic-spline" "$work/ics/sod.yml"
  ok "export names what SWIFT cannot do" grep -q "mirror walls on axis x" "$work/export.err"
  "$sph" run sod --set scene.n_left=100 --until 0 --out "$work/sod0" > /dev/null
  $py "$here/check_hdf5.py" "$work/ics/sod.hdf5" "$work/sod0/particles_00000.csv" swift 2/1.732051 0
  check "h5py reads an exported SWIFT IC" 0 $?
  "$sph" export-ics sod --set scene.n_left=100 --format gadget4 --out "$work/ics/sod_g4.hdf5" > /dev/null 2>&1
  check "export-ics sod gadget4" 0 $?
  ok "GADGET-4 parameter file" grep -q "^ICFormat  *3" "$work/ics/sod_g4-param.txt"
  ok "GADGET-4 Config.sh options" grep -q "^%   ONEDIMS" "$work/ics/sod_g4-param.txt"
  $py "$here/check_hdf5.py" "$work/ics/sod_g4.hdf5" "$work/sod0/particles_00000.csv" gadget4 2 0
  check "h5py reads an exported GADGET-4 IC" 0 $?
  "$sph" export-ics kepler --format swift --out "$work/ics/kepler.hdf5" > /dev/null 2>&1; check "export-ics kepler" 0 $?
  "$sph" run kepler --until 0 --out "$work/kepler0" > /dev/null
  $py "$here/check_hdf5.py" "$work/ics/kepler.hdf5" "$work/kepler0/particles_00000.csv" swift 1 0
  check "N-body particles in PartType1" 0 $?
  # round trip: the exported IC runs here with the same initial state as the scene itself
  for ic in sod sod_g4; do
    "$sph" run "$work/ics/$ic.hdf5" --until 0 --out "$work/rt_$ic" > /dev/null; check "sph run $ic.hdf5" 0 $?
    $py "$here/compare_csv.py" "$work/sod0/particles_00000.csv" "$work/rt_$ic/particles_00000.csv" 1e-9
    check "$ic.hdf5 starts where sod starts" 0 $?
  done
  "$sph" run "$work/ics/sod.hdf5" --out "$work/rt_run" > "$work/rt_run.log"; check "the IC runs to t_end" 0 $?
  ok "the IC keeps sod's reference" grep -q "L1_rho = " "$work/rt_run.log"
  # a SWIFT example's IC (its layout: float datasets, ids from 1, a periodic box, gamma 5/3) runs here
  $py "$here/make_swift_sod.py" "$work/swift_sod.hdf5" 200 > /dev/null
  "$sph" run "$work/swift_sod.hdf5" --until 0.1 --set dt_out=0.1 --out "$work/swift" > "$work/swift.log"
  check "sph run a SWIFT-layout Sod IC" 0 $?
  $py "$here/compare_csv.py" --plateaus "$work/swift/particles_00000.csv" > "$work/plateaus.log"
  check "its summation density has SWIFT's plateaus 1 and 0.125" 0 $?
  cat "$work/plateaus.log"
  # what cannot run is refused by name, nothing written
  $py -c "import h5py; f = h5py.File('$work/entropy.hdf5', 'w'); f.create_group('Header').attrs['Flag_Entropy_ICs'] = 1" 
  "$sph" run "$work/entropy.hdf5" --out "$work/no" 2> "$work/entropy.err"; check "entropy IC refused" 3 $?
  ok "entropy IC: names the flag" grep -q "Flag_Entropy_ICs" "$work/entropy.err"
  ok "entropy IC: nothing written" test ! -e "$work/no" ;;
video)
  command -v ffmpeg > /dev/null || skip "ffmpeg is not installed (apt-get install ffmpeg)"
  env -u DISPLAY "$sph" run sod --set scene.n_left=100 --frames "$work/fr" --every 0.02 --size 640x360 \
    --video "$work/sod.mp4" --fps 12 > "$work/video.log"; check "sod --video" 0 $?
  frames=$(ls "$work/fr"/frame_*.png | wc -l)  # beside them: manifest.json
  ok "11 frames (t = 0 ... 0.2 every 0.02)" test "$frames" = 11
  probe() { ffprobe -v error -select_streams v:0 -count_frames -show_entries "stream=$1" -of csv=p=0 "$2"; }
  ok "the MP4 has every frame" test "$(probe nb_read_frames "$work/sod.mp4")" = "$frames"
  ok "the MP4 runs at 12 frames/s" test "$(probe r_frame_rate "$work/sod.mp4")" = "12/1"
  ok "the MP4 is 640x360" test "$(probe width,height "$work/sod.mp4")" = "640,360"
  ok "still of the last frame" cmp -s "$work/sod_last.png" "$work/fr/frame_00010.png"
  env -u DISPLAY "$sph" run sod --set scene.n_left=100 --every 0.05 --size 640x360 --video "$work/lesson.gif" --fps 4 \
    > /dev/null; check "sod --video lesson.gif" 0 $?
  ok "an animated GIF" test "$(head -c 6 "$work/lesson.gif")" = "GIF89a"
  ok "the GIF has every frame of lesson_frames/" test "$(probe nb_read_frames "$work/lesson.gif")" = "$(ls "$work/lesson_frames"/frame_*.png | wc -l)"
  "$sph" run sod --video "$work/x.avi" > /dev/null 2> "$work/avi.err"; check "unknown video type refused" 2 $?
  ok "names --video" grep -q -- "--video" "$work/avi.err" ;;
*) echo "unknown tool $tool"; exit 2 ;;
esac
echo "$tool: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
