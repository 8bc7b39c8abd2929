#!/usr/bin/env bash
# Faults where users meet them, in the GUI: sph-gui recording Sod's frames and saving its state (Ctrl+S,
# every few frames) is killed with SIGKILL at 20 random moments; each time it is started again from the
# saved state with the same recording folder. After every kill the frames are whole PNGs and the state
# loads (the next start would exit 3 otherwise); at the end the frames are numbered without a gap or a
# repeat, every one is whole, and no temporary is left. It starts its own Xvfb (no xvfb-run).
# usage: gui_kill_test.sh SPH_GUI [SEED]
set -u
gui=$(realpath "$1")
seed=${2:-$RANDOM}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../headless/test_lib.sh"
echo "seed $seed (replay: gui_kill_test.sh SPH_GUI $seed)"
RANDOM=$seed

exec 3> "$work/display"
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
exec 3>&-
trap 'kill $xvfb 2>/dev/null; wait $xvfb 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.05; done
export DISPLAY=":$(cat "$work/display")"

rec="$work/rec" state="$work/state.sph"
# Ctrl+S (tap "!") every 4 frames from the second; frames recorded every 0.002 of simulated time at 64x48
taps=()
for f in $(seq 2 4 400); do taps+=(--tap-keys "$f:!"); done
start() {  # start [more options]: sph-gui in the background, from the saved state when there is one
  local load=()
  [ -e "$state" ] && load=(--load-state "$state")
  (cd "$work" && exec "$gui" --scene sod --size 800x600 --record "$rec" --record-every 0.002 --record-size 64x48 \
    "${load[@]}" "${taps[@]}" "$@") >"$work/gui.out" 2>"$work/gui.err" &
  pid=$!
}
whole_pngs() {  # every frame_NNNNN.png in the folder ends with its IEND chunk
  python3 - "$rec" <<'PY'
import os, sys
d = sys.argv[1]
for n in os.listdir(d) if os.path.isdir(d) else []:
    if n.startswith("frame_") and n.endswith(".png"):
        assert open(os.path.join(d, n), "rb").read()[-8:-4] == b"IEND", n + " is not whole"
PY
}

for round in $(seq 20); do
  start
  sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 0.4 + 2.6 * r / 32767 }')"
  if ! kill -0 $pid 2>/dev/null; then  # it ended by itself: only a refused state would do that
    wait $pid; echo "FAIL [round $round]: sph-gui exited $? before the kill: $(head -c 300 "$work/gui.err")"
    fails=$((fails + 1)); continue
  fi
  kill -9 $pid; wait $pid 2>/dev/null
  ok "round $round: the frames are whole" whole_pngs
done
ok "some states were saved" test -e "$state"

# a last start runs to its end: the state loads, the recording goes on after the last frame
start --quit-at-end
wait $pid
check "the last start, from the saved state" 0 $?
ok "frames whole at the end" whole_pngs
ok "no temporaries left" test -z "$(ls "$rec" | grep -v '^frame_[0-9]*\.png$')"
ok "frames numbered without a gap" python3 - "$rec" <<'PY'
import os, sys
n = sorted(int(f[6:11]) for f in os.listdir(sys.argv[1]) if f.startswith("frame_"))
assert n and n == list(range(len(n))), n[:5]
print(len(n), "frames")
PY

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
