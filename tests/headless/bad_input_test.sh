#!/usr/bin/env bash
# The bad-input matrix of `sph` (README "Bad input, fuzzing and sanitizers"): scene files, flags and
# output paths that must be refused. Each case asserts its documented exit code (README "Exit codes": 2
# usage, 3 invalid scene, 4 I/O), one clear message naming the file, key or flag (a grep pattern), no
# partial output (the output folder absent or without particle files), no crash (exit < 128), no hang
# (timeout 20 s) and no runaway memory (every case runs under `ulimit -v` 4 GiB; an enormous particle
# count or frame is refused up front with the memory it would need).
# usage: bad_input_test.sh SPH_BINARY
set -u
sph=$1
source "$(dirname "$0")/test_lib.sh"
cases=0
# Under AddressSanitizer (a -DSPH_SANITIZE=address build: ctest sets ASAN_OPTIONS) the program cannot start
# under `ulimit -v` (its shadow memory is reserved up front): no limit then, and the cases whose refusal
# needs the 4 GiB limit are skipped.
limit=4194304
if [ -n "${ASAN_OPTIONS:-}" ]; then limit=unlimited; fi
limited() { [ "$limit" != unlimited ] || { echo "skipped under ASan: $2"; return 0; }; "$@"; }

# bad NAME EXPECTED_RC PATTERN ARGS...: runs `sph ARGS` (OUT in ARGS is replaced by the case's output folder)
bad() {
  local name=$1 want=$2 pattern=$3; shift 3
  local out="$work/out_$cases" err="$work/err_$cases" args=() a
  for a in "$@"; do args+=("${a//OUT/$out}"); done
  cases=$((cases + 1))
  timeout -s KILL 20 bash -c 'ulimit -v "$0"; exec "$@"' "$limit" "$sph" "${args[@]}" >/dev/null 2>"$err"
  local rc=$?
  if [ "$rc" -ne "$want" ]; then
    echo "FAIL [$name]: exit $rc, expected $want (stderr: $(head -c 300 "$err"))"; fails=$((fails + 1)); return
  fi
  if [ "$rc" -ge 128 ]; then echo "FAIL [$name]: crashed or hung (exit $rc)"; fails=$((fails + 1)); return; fi
  if ! grep -qF -- "$pattern" "$err"; then
    echo "FAIL [$name]: message does not name '$pattern': $(head -c 300 "$err")"; fails=$((fails + 1)); return
  fi
  if [ "$(grep -c '^sph: \|^The following\|^Could not\|^--' "$err")" -gt 1 ]; then
    echo "FAIL [$name]: more than one message: $(head -c 400 "$err")"; fails=$((fails + 1)); return
  fi
  if [ -d "$out" ] && ls "$out" | grep -q 'particles_\|frame_'; then
    echo "FAIL [$name]: partial output in $out: $(ls "$out" | head -5)"; fails=$((fails + 1)); return
  fi
  passes=$((passes + 1))
}

s="$work/scenes"; mkdir -p "$s"
w() { printf '%s' "$2" > "$s/$1"; }  # w FILE TEXT: a scene file
w malformed.json '{"scene": "sod",'
w trailing.json '{"scene": "sod"} and more'
w scene_number.json '{"scene": 5}'
w param_bool.json '{"scene": "sod", "params": {"kernel.type": true}}'
w params_array.json '{"scene": "sod", "params": [1, 2]}'
w nan_number.json '{"scene": "sod", "params": {"time.t_end": NaN}}'
w nan_string.json '{"scene": "sod", "params": {"time.t_end": "nan"}}'
w inf_string.json '{"scene": "sod", "params": {"time.t_end": "inf"}}'
w inf_number.json '{"scene": "sod", "params": {"time.t_end": Infinity}}'
w huge_number.json '{"scene": "sod", "params": {"time.t_end": 1e400}}'
w huge_count.json '{"scene": "box_random", "params": {"scene.count": 1e15}}'
w big_count.json '{"scene": "polytrope", "params": {"scene.n": 10000000}}'
w big_lattice.json '{"scene": "sedov3d", "params": {"scene.n_side": 4000}}'
w negative_count.json '{"scene": "sod", "params": {"scene.n_left": -5}}'
w fraction_count.json '{"scene": "sod", "params": {"scene.n_left": 10.5}}'
w empty.json ''
w utf8_key.json '{"scène": "sod"}'
w utf8_param.json '{"scene": "sod", "params": {"kérnel.type": "M4"}}'
w no_scene.json '{"params": {"time.t_end": 0.1}}'
w array.json '[1, 2, 3]'
w unknown_scene.json '{"scene": "no_such_scene"}'
w null_param.json '{"scene": "sod", "params": {"time.t_end": null}}'
w object_param.json '{"scene": "sod", "params": {"time.t_end": {"a": 1}}}'
w bad_enum.json '{"scene": "sod", "params": {"kernel.type": "M99"}}'
w bad_utf8.json $'{"scene": "sod\xff\xfe"}'
mkdir -p "$s/folder.json"
head -c 4096 /dev/urandom > "$s/binary.json"
printf '\x89PNG\r\n\x1a\n\0\0\0' > "$s/png.json"
python3 -c "print('[' * 100000 + ']' * 100000)" > "$s/deep.json"

# --- scene files: exit 3, the file and the key named -----------------------------------------------------
bad "malformed JSON" 3 "malformed.json" run "$s/malformed.json" --out OUT
bad "trailing text" 3 "trailing.json" run "$s/trailing.json" --out OUT
bad "scene is a number" 3 "'scene'" run "$s/scene_number.json" --out OUT
bad "param is a boolean" 3 "kernel.type" run "$s/param_bool.json" --out OUT
bad "params is an array" 3 "'params'" run "$s/params_array.json" --out OUT
bad "NaN as a number" 3 "nan_number.json" run "$s/nan_number.json" --out OUT
bad "NaN as a string" 3 "time.t_end" run "$s/nan_string.json" --out OUT
bad "inf as a string" 3 "time.t_end" run "$s/inf_string.json" --out OUT
bad "Infinity as a number" 3 "inf_number.json" run "$s/inf_number.json" --out OUT
bad "huge number 1e400" 3 "huge_number.json" run "$s/huge_number.json" --out OUT
bad "count 1e15" 3 "scene.count" run "$s/huge_count.json" --out OUT
bad "3D count 1e7: memory refused up front" 3 "GiB" run "$s/big_count.json" --out OUT
bad "3D lattice 4000^3: memory refused up front" 3 "scene.n_side" run "$s/big_lattice.json" --out OUT
bad "negative count" 3 "scene.n_left" run "$s/negative_count.json" --out OUT
bad "fractional count" 3 "scene.n_left" run "$s/fraction_count.json" --out OUT
bad "empty file" 3 "empty.json" run "$s/empty.json" --out OUT
bad "a directory" 3 "folder.json" run "$s/folder.json" --out OUT
bad "binary file" 3 "binary.json" run "$s/binary.json" --out OUT
bad "PNG bytes" 3 "png.json" run "$s/png.json" --out OUT
bad "UTF-8 top-level key" 3 "scène" run "$s/utf8_key.json" --out OUT
bad "UTF-8 param key" 3 "kérnel.type" run "$s/utf8_param.json" --out OUT
bad "invalid UTF-8" 3 "bad_utf8.json" run "$s/bad_utf8.json" --out OUT
bad "missing scene" 3 "'scene'" run "$s/no_scene.json" --out OUT
bad "top level is an array" 3 "array.json" run "$s/array.json" --out OUT
bad "unknown scene" 3 "no_such_scene" run "$s/unknown_scene.json" --out OUT
bad "null value" 3 "time.t_end" run "$s/null_param.json" --out OUT
bad "object value" 3 "time.t_end" run "$s/object_param.json" --out OUT
bad "unknown kernel" 3 "kernel.type" run "$s/bad_enum.json" --out OUT
bad "100000 nested brackets" 3 "deep.json" run "$s/deep.json" --out OUT
bad "no such file" 3 "nosuch.json" run "$s/nosuch.json" --out OUT
bad "check: malformed" 3 "malformed.json" check "$s/malformed.json"

# --- flags: exit 2 (usage) or 3 (a --set value), the flag named -----------------------------------------
bad "unknown flag" 2 "--bogus" run sod --bogus --out OUT
bad "unknown command" 2 "runn" runn sod
bad "repeated --until" 2 "--until" run sod --until 0.1 --until 0.2 --out OUT
bad "repeated --out" 2 "--out" run sod --out OUT --out OUT
bad "missing value of --until" 2 "--until" run sod --out OUT --until
bad "missing value of --threads" 2 "--threads" run sod --out OUT --threads
bad "--threads 0" 2 "--threads" run sod --threads 0 --out OUT
bad "--threads huge" 2 "--threads" run sod --threads 99999999999 --out OUT
bad "--threads text" 2 "--threads" run sod --threads many --out OUT
bad "--until -1" 2 "--until" run sod --until -1 --out OUT
bad "--until -3" 2 "--until" run sod --until -3 --out OUT
bad "--until nan" 2 "--until" run sod --until nan --out OUT
bad "--until inf" 2 "--until" run sod --until inf --out OUT
bad "--until 1e400" 2 "--until" run sod --until 1e400 --out OUT
bad "--set without =" 3 "--set kernel.type" run sod --set kernel.type --out OUT
bad "--set unknown key" 3 "no.such" run sod --set no.such=1 --out OUT
bad "--set NaN" 3 "time.t_end" run sod --set time.t_end=nan --out OUT
bad "--set empty value" 3 "time.t_end" run sod --set time.t_end= --out OUT
bad "--set count 1e12" 3 "scene.count" run box_random --set scene.count=1e12 --out OUT
limited bad "--set count 1e7: memory refused" 3 "GiB" run box_random --set scene.count=10000000 --out OUT
bad "export-ics: memory refused" 3 "GiB" export-ics sedov3d --set scene.n_side=4000 --out OUT/a.hdf5
bad "--size 0x0" 2 "--size" run sod --frames OUT/frames --size 0x0 --out OUT
bad "--size odd" 2 "--size" run sod --frames OUT/frames --size 641x481 --out OUT
bad "--size enormous" 2 "--size" run sod --frames OUT/frames --size 1000000x1000000 --out OUT
limited bad "--size 16384x16384: memory refused" 2 "--size" run sod --frames OUT/frames --size 16384x16384 --out OUT
bad "--size text" 2 "--size" run sod --frames OUT/frames --size big --out OUT
bad "--size overflow" 2 "--size" run sod --frames OUT/frames --size 99999999999999999999x2 --out OUT
bad "--every 0" 2 "--every" run sod --frames OUT/frames --every 0 --out OUT
bad "--every -1" 2 "--every" run sod --frames OUT/frames --every -1 --out OUT
bad "--color-by unknown" 2 "--color-by" run sod --frames OUT/frames --color-by nosuch --out OUT
bad "--cmap unknown" 2 "--cmap" run sod --frames OUT/frames --cmap rainbow --out OUT
bad "--range 5:1" 2 "--range" run sod --frames OUT/frames --range 5:1 --out OUT
bad "--range p50:10" 2 "--range" run sod --frames OUT/frames --range p50:10 --out OUT
bad "--range text" 2 "--range" run sod --frames OUT/frames --range a:b --out OUT
bad "--range trailing text" 2 "--range" run sod --frames OUT/frames --range 1:2x --out OUT
bad "--fps 0" 2 "--fps" run sod --frames OUT/frames --fps 0 --out OUT
bad "--video .avi" 2 "--video" run sod --video OUT/v.avi --out OUT
bad "--vtu without --out" 2 "--vtu" run sod --vtu
bad "converge --size 0x5" 2 "--size" converge sod --size 0x5 --out OUT
bad "converge --size signed" 2 "--size" converge sod --size +64x-48 --out OUT
bad "converge --values text" 3 "--values" converge sod --values 1,x --out OUT
bad "export-ics --format" 2 "--format" export-ics sod --format gadget9 --out OUT/a.hdf5

# --- output paths: exit 4, the path named ----------------------------------------------------------------
touch "$work/plain"
bad "--out is a file" 4 "$work/plain" run sod --until 0.01 --out "$work/plain"
bad "--out under a file" 4 "$work/plain/sub" run sod --until 0.01 --out "$work/plain/sub"
bad "--frames is a file" 4 "$work/plain" run sod --until 0.01 --frames "$work/plain" --size 64x48
if [ "$(id -u)" -eq 0 ]; then  # chmod does not stop root: /proc takes no new folders
  bad "--out unwritable" 4 "/proc/sph_out" run sod --until 0.01 --out /proc/sph_out
else
  mkdir -p "$work/ro"; chmod 500 "$work/ro"
  bad "--out unwritable" 4 "$work/ro/out" run sod --until 0.01 --out "$work/ro/out"
fi
# a full disk: a file size limit (SIGXFSZ ignored, so write(2) fails with EFBIG)
cases=$((cases + 1))
(trap '' XFSZ; ulimit -f 16; exec timeout 20 "$sph" run sod --until 0.05 --out "$work/full") >/dev/null 2>"$work/full.err"
rc=$?
if [ "$rc" -eq 4 ] && grep -q "cannot write $work/full/particles_00000.csv" "$work/full.err" &&
   ! ls "$work/full" | grep -q 'particles_\|\.part$\|\.tmp\.'; then passes=$((passes + 1))
else echo "FAIL [full disk]: exit $rc: $(cat "$work/full.err")"; fails=$((fails + 1)); fi

echo "$cases cases: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
