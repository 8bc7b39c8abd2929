#!/usr/bin/env python3
"""The reference guard's sweep: every scene value of every scene at (at least) three values of its
documented range, each run checked against the scene's bounds as `sph help SCENE` prints them.

A run that exits 0 while an error norm (errors.csv, rows where the reference applies, from the bound's
start time) or its energy drift (diagnostics.csv, against |E_kin| + |E_int| + |E_pot| after step 1) is
beyond the scene's bound, without a warning of that kind in warnings.csv, is a FAILURE (exit 1).

Values: the range's lower end, the default and the upper end; resolution values (counts, spacings) and
times are held to about twice the default's cost (a count at most 2^(1/dim) x the default, a spacing at
least the default / 2^(1/dim), a time at most 2 x the default) so the sweep ends in about an hour on two
cores. A run that takes longer than --timeout is listed as such.

usage: param_sweep.py SPH OUTDIR [--scenes a,b] [--jobs 2] [--timeout 120]
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys
import time

VALUE = re.compile(r"^  scene\.(\S+)\s+= \S+\s+(.*?), range \[(\S+), (\S+)\](, integer)?, default (\S+)$")
BOUND = re.compile(r"^    (\S+)\s+<= (\S+)(?: from t = (\S+))?$")
ENERGY = re.compile(r"^Energy: E_tot stays within (\S+) ")
DIM = re.compile(r"^\S+ \((\d)D,")


def describe(sph, scene):
    """Dimension, scene values (name, unit, lo, hi, integer, default), bounds and energy bound."""
    text = subprocess.run([sph, "help", scene], capture_output=True, text=True, check=True).stdout
    dim, values, bounds, energy, in_bounds = 1, [], [], 0.0, False
    for line in text.splitlines():
        if (m := DIM.match(line)):
            dim = int(m.group(1))
        elif (m := VALUE.match(line)):
            values.append((m.group(1), m.group(2), float(m.group(3)), float(m.group(4)), bool(m.group(5)),
                           float(m.group(6))))
        elif (m := ENERGY.match(line)):
            energy = float(m.group(1))
        elif line.startswith("  bounds a correct run keeps"):
            in_bounds = True
        elif in_bounds and (m := BOUND.match(line)):
            bounds.append((m.group(1), float(m.group(2)), float(m.group(3) or 0.0)))
        else:
            in_bounds = False
    return dim, values, bounds, energy


def choices(name, unit, lo, hi, integer, default, dim):
    """The range's ends and the default, with resolution values and times held near the default's cost."""
    grow = 2.0 ** (1.0 / dim)
    if unit in ("count", "particles per length") or name in ("n", "n_left", "n_side", "count"):
        hi = min(hi, math.floor(default * grow))
    elif name == "dx":
        lo = max(lo, default / grow)
    elif unit == "time":
        hi = min(hi, 2.0 * default)
    out = []
    for v in (lo, default, hi):
        v = float(round(v)) if integer else v
        if v not in out:
            out.append(v)
    return out


def rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def judge(out, bounds, energy):
    """(failures, notes) of a finished run's files."""
    kinds = {r["kind"] for r in rows(os.path.join(out, "warnings.csv"))}
    failures, notes = [], []
    err = rows(os.path.join(out, "errors.csv"))
    for column, bound, start in bounds:
        vals = [float(r[column]) for r in err
                if r.get("valid", "1") == "1" and float(r["t"]) >= start and column in r]
        vals = [v for v in vals if not math.isnan(v)]
        worst = max(vals, default=0.0)
        if worst > bound:
            (notes if "accuracy:" + column in kinds else failures).append(f"{column} {worst:.3g} > {bound:g}")
    diag = rows(os.path.join(out, "diagnostics.csv"))
    if energy > 0.0 and len(diag) > 1:
        d1 = diag[1]
        scale = abs(float(d1["E_kin"])) + abs(float(d1["E_int"])) + abs(float(d1["E_pot"]))
        e0 = float(d1["E_tot"])
        drift = max(abs(float(r["E_tot"]) - e0) for r in diag[1:]) / scale if scale > 0 else 0.0
        if drift > energy:
            (notes if "energy" in kinds else failures).append(f"energy drift {drift:.3g} > {energy:g}")
    return failures, notes, sorted(kinds)


def run_one(sph, root, scene, key, value, bounds, energy, timeout):
    tag = f"{scene}__{key}={value:g}" if key else f"{scene}__defaults"
    out = os.path.join(root, tag)
    cmd = [sph, "run", scene, "--threads", "1", "--out", out]
    if key:
        cmd += ["--set", f"scene.{key}={value:.17g}"]
    start = time.time()
    try:
        rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        return tag, "timeout", time.time() - start, [], [], []
    failures, notes, kinds = judge(out, bounds, energy) if rc == 0 else ([], [], [])
    return tag, rc, time.time() - start, failures, notes, kinds


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sph")
    ap.add_argument("outdir")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120.0)
    a = ap.parse_args()
    listing = subprocess.run([a.sph, "list"], capture_output=True, text=True, check=True).stdout
    scenes = [line.split()[0] for line in listing.splitlines() if line.strip()]
    if a.scenes:
        scenes = [s for s in scenes if s in a.scenes.split(",")]
    jobs = []
    for s in scenes:
        dim, values, bounds, energy = describe(a.sph, s)
        jobs.append((s, "", 0.0, bounds, energy))
        for name, unit, lo, hi, integer, default in values:
            for v in choices(name, unit, lo, hi, integer, default, dim):
                if v != default:
                    jobs.append((s, name, v, bounds, energy))
    os.makedirs(a.outdir, exist_ok=True)
    bad = 0
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(run_one, a.sph, a.outdir, *j, a.timeout) for j in jobs]
        for f in futures:
            tag, rc, secs, failures, notes, kinds = f.result()
            bad += bool(failures)
            status = "FAIL " + "; ".join(failures) if failures else "ok"
            extra = (" warned: " + "; ".join(notes)) if notes else ""
            print(f"{tag:58s} exit {rc!s:7s} {secs:7.1f} s  {status}{extra}  [{' '.join(kinds)}]", flush=True)
    print(f"{len(jobs)} runs, {bad} exit 0 beyond a bound without its warning")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
