#!/usr/bin/env python3
"""Writes the checkpoint fuzzer's seed corpus (tests/fuzz/corpus/checkpoint/) from a checkpoint file.

usage: make_checkpoint_corpus.py CHECKPOINT OUTDIR
The checkpoint should come from `sph run sod --set scene.n_left=20 --until 0.004 --checkpoint-every 0.002
--out D` (fuzz_checkpoint.cpp restores world states into that scene). Layout (engine/include/sph/checkpoint.h):
magic "SPHCHKPT" | u32 version | u32 0 | u64 file size | 4 x (u64 length + bytes) | u64 checksum | "ENDCHKPT".
"""
import pathlib
import struct
import sys


def sections(data):
    """The four sections of a checkpoint: config, run options, world, extra."""
    if data[:8] != b"SPHCHKPT":
        sys.exit("not a checkpoint")
    pos, out = 24, []
    for _ in range(4):
        (n,) = struct.unpack_from("<Q", data, pos)
        out.append(data[pos + 8:pos + 8 + n])
        pos += 8 + n
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    data = pathlib.Path(sys.argv[1]).read_bytes()
    _, options, world, extra = sections(data)
    out = pathlib.Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    (out / "container").write_bytes(b"\x00" + data)
    (out / "world").write_bytes(b"\x01" + world)
    (out / "run").write_bytes(b"\x02" + options + b"\n" + extra)


if __name__ == "__main__":
    main()
