#!/usr/bin/env bash
# Checkpoint and restart of `sph run` (README "Checkpoints"): a resumed run is bitwise the run that never
# stopped, in every output file; signals stop a run with a checkpoint; a run killed at random moments
# resumes to the same files, its frames and video too; damaged checkpoints are refused with exit 3 naming
# the file.
# usage: restart_test.sh matrix|signals|kill|frames|damaged PATH_TO_SPH
set -u
mode=$1; sph=$2
source "$(dirname "$0")/test_lib.sh"
export OMP_WAIT_POLICY=passive  # else sph sets it and re-executes itself (same pid, but a signal could land first)

# same DIR_A DIR_B: every output file of A is in B, byte for byte (the checkpoint aside); prints the odd ones
same() {
  local f rc=0
  for f in "$1"/*; do
    case $(basename "$f") in checkpoint.sph) continue ;; esac
    [ -d "$f" ] && continue  # a folder (frames) is compared by itself
    cmp -s "$f" "$2/$(basename "$f")" || { echo "  differs: $(basename "$f")"; rc=1; }
  done
  [ "$(ls "$1" | grep -vc '^checkpoint.sph$')" = "$(ls "$2" | grep -vc '^checkpoint.sph$')" ] ||
    { echo "  file lists differ; only in $2: $(comm -13 <(ls "$1") <(ls "$2") | grep -v '^checkpoint.sph$' | tr '\n' ' ')"; rc=1; }
  return $rc
}

# complete DIR: no temporary file left, every CSV ends with a newline and has as many fields per row as its header
complete() {
  local f
  [ -z "$(ls "$1" | grep -E '\.tmp(\.[0-9]+)?$|\.part$')" ] || { echo "  temporary files left: $(ls "$1" | grep -E '\.tmp(\.[0-9]+)?$|\.part$')"; return 1; }
  for f in "$1"/*.csv; do
    [ -e "$f" ] || continue  # a frame folder has none
    [ "$(tail -c 1 "$f" | od -An -c | tr -d ' ')" = '\n' ] || { echo "  $f does not end with a newline"; return 1; }
    case $f in */warnings.csv) python3 -c 'import csv, sys; r = list(csv.reader(open(sys.argv[1]))); assert all(len(x) == len(r[0]) for x in r)' "$f" || { echo "  $f: a row of another width"; return 1; }; continue ;; esac  # quoted messages
    awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad }' "$f" || { echo "  $f: a row of another width"; return 1; }
  done
}

case $mode in
matrix)
  # scene x integrator: to T uninterrupted; to T/2 with a checkpoint, resumed to T; T/2 is an output time.
  # Forward Euler takes the gravity scenes kepler and evrard beyond their energy bound: those runs end with
  # exit 8 and the warning (README "Exit codes"; the first half of evrard's still within it), the files
  # still identical.
  while read -r scene T sets; do
    for integ in euler leapfrog predictor_corrector rk4; do
      name="$scene/$integ"; a="$work/${scene}_${integ}_a"; b="$work/${scene}_${integ}_b"
      want=0; case $name in kepler/euler | evrard/euler) want=8 ;; esac
      "$sph" run "$scene" $sets --set time.integrator=$integ --until "$T" --threads 1 --quiet --out "$a" 2> /dev/null
      check "$name uninterrupted" $want $?
      half=$(awk -v t="$T" 'BEGIN { printf "%.17g", t / 2 }')
      "$sph" run "$scene" $sets --set time.integrator=$integ --until "$half" --checkpoint-every "$half" --threads 1 \
        --quiet --out "$b" 2> /dev/null
      rc=$?; ok "$name first half (exit $rc)" test "$rc" -eq 0 -o "$rc" -eq "$want"
      "$sph" resume "$b" --until "$T" --quiet 2> /dev/null; check "$name resumed" $want $?
      ok "$name: every file identical" same "$a" "$b"
      echo "$name: $(same "$a" "$b" > /dev/null && echo identical || echo DIFFERENT) ($(ls "$a" | wc -l) files)"
    done
  done << 'SCENES'
sod 0.1 --set scene.n_left=100 --set time.dt_out=0.025
dam_break 0.1 --set scene.dx=0.1 --set time.dt_out=0.025
evrard 0.2 --set scene.n=300 --set time.dt_out=0.05
kepler 0.1 --set time.dt=0.0005 --set time.dt_out=0.025
burgers_upwind 0.5 --set time.dt_out=0.125
SCENES
  # individual time steps (time.levels; leapfrog only): the block state comes back with the checkpoint
  sets=(--set scene.n_side=40 --set time.levels=5 --set time.dt_out=0.01)
  "$sph" run sedov "${sets[@]}" --until 0.02 --threads 1 --quiet --out "$work/L1" 2> /dev/null; check "sedov levels uninterrupted" 0 $?
  "$sph" run sedov "${sets[@]}" --until 0.01 --checkpoint-every 0.01 --threads 1 --quiet --out "$work/L2" 2> /dev/null
  check "sedov levels first half" 0 $?
  "$sph" resume "$work/L2" --until 0.02 --quiet 2> /dev/null; check "sedov levels resumed" 0 $?
  ok "sedov levels: every file identical" same "$work/L1" "$work/L2"
  # DFSPH (its own step, no time.integrator): the warm starts (fields kappa, kappa_v) come back with the checkpoint
  sets=(--set scene.dx=0.1 --set time.dt_out=0.025)
  "$sph" run dam_break_dfsph "${sets[@]}" --until 0.1 --threads 1 --quiet --out "$work/D1" 2> /dev/null; check "dam_break_dfsph uninterrupted" 0 $?
  "$sph" run dam_break_dfsph "${sets[@]}" --until 0.05 --checkpoint-every 0.05 --threads 1 --quiet --out "$work/D2" 2> /dev/null
  check "dam_break_dfsph first half" 0 $?
  "$sph" resume "$work/D2" --until 0.1 --quiet 2> /dev/null; check "dam_break_dfsph resumed" 0 $?
  ok "dam_break_dfsph: every file identical" same "$work/D1" "$work/D2"
  # above the size where loops go parallel (4096): run on 1 thread, resumed on 2, the same files
  sets=(--set scene.n_left=4000 --set time.dt_out=0.005)
  "$sph" run sod "${sets[@]}" --until 0.01 --threads 1 --quiet --out "$work/t1" 2> /dev/null; check "4500 particles, 1 thread" 0 $?
  "$sph" run sod "${sets[@]}" --until 0.005 --checkpoint-every 0.005 --threads 1 --quiet --out "$work/t2" 2> /dev/null
  check "4500 particles, first half" 0 $?
  "$sph" resume "$work/t2" --until 0.01 --threads 2 --quiet 2> /dev/null; check "4500 particles, resumed on 2 threads" 0 $?
  ok "resumed on 2 threads: every file identical" same "$work/t1" "$work/t2"
  ;;
signals)
  # the waits read diagnostics.csv.part: the file grows under that name until the run ends (README)
  run=(run dam_break --set scene.dx=0.05 --until 0.3 --threads 1 --quiet)
  "$sph" "${run[@]}" --out "$work/whole" 2> /dev/null; check "uninterrupted" 0 $?
  for sig in INT TERM; do
    d="$work/$sig"; want=$([ $sig = INT ] && echo 130 || echo 143)
    "$sph" "${run[@]}" --out "$d" 2> "$work/$sig.err" &
    pid=$!
    for _ in $(seq 200); do [ "$(wc -l 2> /dev/null < "$d/diagnostics.csv.part" || echo 0)" -gt 100 ] && break; sleep 0.02; done
    kill -$sig $pid; wait $pid; check "SIG$sig exit code" "$want" $?
    ok "SIG$sig: checkpoint written" test -s "$d/checkpoint.sph"
    ok "SIG$sig: says how to resume" grep -q "sph resume $d" "$work/$sig.err"
    ok "SIG$sig: says where it stopped" grep -q "stopped by SIG$sig at t = .* after step" "$work/$sig.err"
    ok "SIG$sig: stopped mid-run" test ! -e "$d/warnings.csv"
    threads=$([ $sig = INT ] && echo 1 || echo 2)  # results do not depend on the thread count
    "$sph" resume "$d" --quiet --threads $threads 2> /dev/null; check "SIG$sig resumed on $threads threads" 0 $?
    ok "SIG$sig: resumed files identical" same "$work/whole" "$d"
    ok "SIG$sig: complete files" complete "$d"
  done
  # a run without --out (frames only) has no checkpoint, and its message names no flag the run did not use
  f="$work/frames_only"
  "$sph" run dam_break --set scene.dx=0.05 --until 3 --threads 1 --quiet --frames "$f" --every 0.01 --size 64x48 \
    2> "$work/fo.err" &
  pid=$!
  for _ in $(seq 500); do [ "$(ls "$f" 2> /dev/null | grep -c '\.png$')" -gt 2 ] && break; sleep 0.02; done
  kill -INT $pid; wait $pid; check "frames only: SIGINT exit code" 130 $?
  ok "frames only: says a run with --out is checkpointed" grep -q "no checkpoint (a run with --out DIR" "$work/fo.err"
  ok "frames only: no word of --checkpoint-every" test -z "$(grep -e --checkpoint-every "$work/fo.err")"
  # a second signal stops at once: exit 130, and no partial checkpoint (only a complete one, or none)
  d="$work/twice"
  "$sph" "${run[@]}" --out "$d" 2> /dev/null &
  pid=$!
  for _ in $(seq 200); do [ "$(wc -l 2> /dev/null < "$d/diagnostics.csv.part" || echo 0)" -gt 100 ] && break; sleep 0.02; done
  kill -INT $pid; kill -INT $pid; wait $pid; check "second SIGINT exit code" 130 $?
  ok "second SIGINT: no temporary checkpoint" test ! -e "$d/checkpoint.sph.tmp"
  if [ -e "$d/checkpoint.sph" ]; then
    "$sph" resume "$d" --quiet 2> /dev/null; check "second SIGINT: resumed" 0 $?
    ok "second SIGINT: resumed files identical" same "$work/whole" "$d"
  fi
  ;;
kill | frames)
  # kill -9 at 20 moments drawn from a seeded generator; resume each from its last checkpoint. kill: with
  # the ParaView, SPLASH and HDF5 files too; frames: a PNG sequence and its GIF (--frames, --video) in a
  # folder of the run's. Odd runs wait for their first checkpoint before the random delay (halved), so at least 10
  # kills test a resume however loaded the machine is; even runs may die before it.
  if [ "$mode" = kill ]; then
    run=(run sod --set scene.n_left=400 --until 0.2 --threads 1 --quiet --checkpoint-every 0.01 --vtu --splash --hdf5)
    places() { echo "--out $1"; }
    folders=(.)
  else
    command -v ffmpeg > /dev/null || { echo "ffmpeg is not installed (apt-get install ffmpeg): skipped"; exit 77; }
    run=(run box_random --until 1.2 --threads 1 --quiet --checkpoint-every 0.15 --every 0.1 --size 160x120)
    places() { echo "--out $1 --frames $1/frames --video $1/frames/v.gif"; }  # frames inside the run folder
    folders=(. frames)
  fi
  # identical DIR: every folder of the run in DIR holds the uninterrupted run's files
  identical() { local f; for f in "${folders[@]}"; do same "$work/whole/$f" "$1/$f" || return 1; done; }
  start=$(date +%s%N)
  "$sph" "${run[@]}" $(places "$work/whole") 2> /dev/null; check "uninterrupted" 0 $?
  wall_ms=$(( ($(date +%s%N) - start) / 1000000 ))
  RANDOM=11
  resumed=0 killed=0
  for i in $(seq 20); do
    d="$work/k$i"
    # within 0.7 of the uninterrupted run's time: that run may have met a busier machine than this one
    # (11 of 20 kills landed mid-run when it took 1780 ms beside other tests and the later runs did not)
    delay=$(awk -v r=$RANDOM -v w=$wall_ms 'BEGIN { printf "%.3f", 0.7 * r / 32768 * w / 1000 }')
    "$sph" "${run[@]}" $(places "$d") 2> /dev/null &
    pid=$!
    if [ $((i % 2)) -eq 1 ]; then
      for _ in $(seq 1500); do [ -e "$d/checkpoint.sph" ] && break; sleep 0.02; done
      delay=$(awk -v d="$delay" 'BEGIN { printf "%.3f", d / 2 }')
    fi
    sleep "$delay"; kill -9 $pid 2> /dev/null; wait $pid 2> /dev/null
    [ $? -eq 137 ] && killed=$((killed + 1))  # else it had finished before the kill
    if [ -e "$d/checkpoint.sph" ]; then
      "$sph" resume "$d" --quiet 2> /dev/null; check "kill $i (after ${delay}s) resumed" 0 $?
      resumed=$((resumed + 1))
    else  # killed before its first checkpoint: start again
      "$sph" "${run[@]}" $(places "$d") 2> /dev/null; check "kill $i (after ${delay}s) rerun" 0 $?
    fi
    ok "kill $i (after ${delay}s): files identical" identical "$d"
    for f in "${folders[@]}"; do ok "kill $i: complete files in $f" complete "$d/$f"; done
  done
  echo "$killed of 20 runs killed mid-run, $resumed resumed from a checkpoint (the others had none yet); a run takes ${wall_ms} ms"
  ok "most kills landed mid-run" test $killed -ge 12
  ok "most kills resumed from a checkpoint" test $resumed -ge 10
  if [ "$mode" = frames ]; then  # a frame the checkpoint counts, gone: refused (exit 3) naming it, nothing written
    cp -r "$work/whole" "$work/lost"
    rm "$work/lost/frames/frame_00003.png"
    "$sph" resume "$work/lost" 2> "$work/lost.err"; check "a lost frame: exit 3" 3 $?
    ok "a lost frame: named" grep -q "frames/frame_00003.png, is missing" "$work/lost.err"
    ok "a lost frame: nothing written" test ! -e "$work/lost/frames/frame_00003.png"
  fi
  ;;
damaged)
  d="$work/good"
  "$sph" run sod --set scene.n_left=60 --until 0.05 --checkpoint-every 0.05 --quiet --out "$d" 2> /dev/null
  check "checkpointed run" 0 $?
  ck="$d/checkpoint.sph"; size=$(stat -c %s "$ck")
  # refused DAMAGE MESSAGE COMMAND: a copy of the run whose checkpoint COMMAND damaged (run in the copy)
  refused() {
    local x="$work/$1"
    rm -rf "$x"; cp -r "$d" "$x"; (cd "$x" && eval "$3")
    local before; before=$(cat "$x"/*.csv | md5sum)
    "$sph" resume "$x" 2> "$work/$1.err"; check "$1: exit 3" 3 $?
    ok "$1: the message names the file" grep -q "$x/checkpoint.sph" "$work/$1.err"
    ok "$1: the message says why ($2)" grep -q "$2" "$work/$1.err"
    ok "$1: one line" test "$(wc -l < "$work/$1.err")" -eq 1
    ok "$1: nothing written" test "$(cat "$x"/*.csv | md5sum)" = "$before"
  }
  refused truncated "truncated" "truncate -s $((size / 2)) checkpoint.sph"
  refused flipped "checksum" "printf '\\x55' | dd of=checkpoint.sph bs=1 seek=$((size / 2)) conv=notrunc status=none"
  refused version "version 7" "printf '\\x07' | dd of=checkpoint.sph bs=1 seek=8 conv=notrunc status=none"
  refused foreign "not a checkpoint" "cp particles_00000.csv checkpoint.sph"
  refused empty "empty" ": > checkpoint.sph"
  refused directory "directory" "rm checkpoint.sph && mkdir checkpoint.sph"
  refused missing "no such file" "rm checkpoint.sph"
  "$sph" resume "$work/nowhere" 2> "$work/nowhere.err"; check "no such directory: exit 3" 3 $?
  ok "no such directory: named" grep -q "$work/nowhere" "$work/nowhere.err"
  "$sph" resume "$d" --quiet; check "the undamaged checkpoint resumes" 0 $?
  # checkpoints need --out, and do not cover A/B comparisons: usage errors, nothing written
  "$sph" run sod --checkpoint-every 0.1 2> /dev/null; check "--checkpoint-every without --out" 2 $?
  "$sph" run sod --checkpoint-every 0.1 --compare-set kernel.type=M6 --out "$work/ab" 2> /dev/null
  check "--checkpoint-every with --compare-set" 2 $?
  ok "--compare-set refused before writing" test ! -e "$work/ab"
  ;;
esac

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
