#!/usr/bin/env bash
# Atomic outputs of `sph run`: manifest.json lists every completed file with its size and CRC-32; a kill
# leaves only complete files (plus NAME.part / NAME.tmp.PID, never listed); a full disk, a vanished folder
# or a folder that cannot be made gives exit 4, one message naming the file, and no partial file; the
# same for the frames of --frames (a full disk, the folder removed mid-run).
# Runs as root too: chmod cannot stop root, so a full disk is simulated with `ulimit -f` (SIGXFSZ
# ignored: write(2) then fails with EFBIG) and /dev/full behind a symlink.
# usage: outputs_test.sh SPH_BINARY
set -u
sph=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/test_lib.sh"

# manifest_ok DIR [lag]: every listed file exists with its listed size and CRC-32, and every particle file
# is listed (lag: a kill or a full disk may come between a file's rename and the manifest's update, so the
# newest one may be missing; it must still be whole: as many lines as the first, a PNG's IEND chunk)
manifest_ok() {
  python3 - "$1" "${2:-}" <<'PY'
import json, os, sys, zlib
d, lag = sys.argv[1], sys.argv[2] == "lag"
m = json.load(open(os.path.join(d, "manifest.json")))
names = {f["name"] for f in m["files"]}
for f in m["files"]:
    b = open(os.path.join(d, f["name"]), "rb").read()
    assert len(b) == f["bytes"] and "%08x" % zlib.crc32(b) == f["crc32"], f
for n in os.listdir(d):
    if n.startswith(("particles_", "frame_")) and not (".tmp." in n or n.endswith(".part")):
        if lag and n.endswith(".csv"):
            count = lambda f: sum(1 for _ in open(os.path.join(d, f)))
            assert count(n) == count("particles_00000.csv"), n + " is not whole"
        elif lag and n.endswith(".png"):  # whole: it ends with the IEND chunk
            assert open(os.path.join(d, n), "rb").read()[-8:-4] == b"IEND", n + " is not whole"
        else:
            assert n in names, n + " not in the manifest"
PY
}
no_partial() {  # no_partial DIR: no temporary or .part left
  ! ls "$1" 2>/dev/null | grep -qE '\.tmp\.[0-9]+|\.part$'
}

# 1. a complete run: every file listed and intact, no temporaries, the growing files renamed
"$sph" run sod --until 0.05 --vtu --splash --out "$work/ok" --frames "$work/ok/frames" --size 64x48 --every 0.02 \
  --quiet >/dev/null 2>&1
check "complete run" 0 $?
ok "complete run: manifest" manifest_ok "$work/ok"
ok "complete run: frames manifest" manifest_ok "$work/ok/frames"
ok "complete run: no temporaries" no_partial "$work/ok"
ok "complete run: diagnostics listed" grep -q '"diagnostics.csv"' "$work/ok/manifest.json"
ok "complete run: errors listed" grep -q '"errors.csv"' "$work/ok/manifest.json"

# 2. killed mid-run (SIGKILL, no chance to clean up): what is listed is complete, diagnostics still .part
"$sph" run sod --until 0.2 --set time.dt_out=0.002 --out "$work/killed" --quiet >/dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [ -e "$work/killed/particles_00003.csv" ] && break; sleep 0.05; done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
ok "killed: some output" test -e "$work/killed/particles_00003.csv"
ok "killed: manifest lists complete files only" manifest_ok "$work/killed" lag
ok "killed: diagnostics not final" test ! -e "$work/killed/diagnostics.csv"

# 3. a full disk (a file size limit): exit 4, the file named, no partial file
(trap '' XFSZ; ulimit -f 20; exec "$sph" run sod --until 0.05 --out "$work/full" --quiet) >/dev/null 2>"$work/full.err"
check "full disk" 4 $?
ok "full disk: one message naming the file" test "$(grep -c 'cannot write .*full/particles_00000.csv' "$work/full.err")" = 1
ok "full disk: no particle file" test -z "$(ls "$work/full" | grep particles_)"
ok "full disk: no temporaries" no_partial "$work/full"
ok "full disk: manifest intact" manifest_ok "$work/full"

# 4. /dev/full as the file (behind a symlink with the name export-ics wants)
ln -s /dev/full "$work/full.hdf5"
"$sph" export-ics sod --out "$work/full.hdf5" >/dev/null 2>"$work/devfull.err"
check "/dev/full" 4 $?
ok "/dev/full: message" grep -q "cannot write $work/full.hdf5: No space left on device" "$work/devfull.err"
ok "/dev/full: no parameter file" test ! -e "$work/full.yml"

# 5. the folder removed mid-run: exit 4 naming a file in it, nothing recreated
"$sph" run sod --until 0.3 --set time.dt_out=0.001 --out "$work/gone" --quiet >/dev/null 2>"$work/gone.err" &
pid=$!
for _ in $(seq 200); do [ -e "$work/gone/particles_00002.csv" ] && break; sleep 0.05; done
mv "$work/gone" "$work/gone.moved"  # one atomic step (rm -rf races the writer)
wait $pid
check "vanished folder" 4 $?
ok "vanished folder: message" grep -q "cannot write $work/gone/" "$work/gone.err"
ok "vanished folder: not recreated" test ! -e "$work/gone"

# 6. a folder that cannot be made (its parent is a regular file)
touch "$work/plain"
"$sph" run sod --until 0.01 --out "$work/plain/out" --quiet >/dev/null 2>"$work/plain.err"
check "parent is a file" 4 $?
ok "parent is a file: message" grep -q "$work/plain/out" "$work/plain.err"

# 7. the disk fills while frames are written (a file size limit the frames' manifest outgrows after about
# 130 frames): exit 4 naming the file, no partial file, the frames written so far and their manifest intact
(trap '' XFSZ; ulimit -f 8; exec "$sph" run sod --until 0.2 --frames "$work/ffull" --every 0.001 --size 64x48 \
  --quiet) >/dev/null 2>"$work/ffull.err"
check "full disk, frames" 4 $?
ok "full disk, frames: one message naming the file" test "$(grep -c "cannot write $work/ffull/" "$work/ffull.err")" = 1
ok "full disk, frames: frames before it" test -e "$work/ffull/frame_00050.png"
ok "full disk, frames: no temporaries" no_partial "$work/ffull"
ok "full disk, frames: manifest intact" manifest_ok "$work/ffull" lag  # the last frame may be unlisted

# 8. the frames folder removed mid-run: exit 4 naming a file in it, nothing recreated
"$sph" run sod --until 0.3 --frames "$work/fgone" --every 0.001 --size 64x48 --quiet >/dev/null 2>"$work/fgone.err" &
pid=$!
for _ in $(seq 200); do [ -e "$work/fgone/frame_00002.png" ] && break; sleep 0.05; done
mv "$work/fgone" "$work/fgone.moved"
wait $pid
check "vanished frames folder" 4 $?
ok "vanished frames folder: message" grep -q "cannot write $work/fgone/" "$work/fgone.err"
ok "vanished frames folder: not recreated" test ! -e "$work/fgone"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
