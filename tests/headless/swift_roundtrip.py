#!/usr/bin/python3
"""SWIFT's run of an exported Sedov blast against this code's run of the same scene (swift_roundtrip.sh).

usage: swift_roundtrip.py IC_FILE SWIFT_DIR ERRORS_CSV ENERGY_TOL
Reads the initial conditions and SWIFT's last snapshot in SWIFT_DIR, prints SWIFT's energy drift and
shock radius and this code's (the last row of ERRORS_CSV), and exits 1 when SWIFT's |E(t)/E(0) - 1|
exceeds ENERGY_TOL or the radii differ by more than 1%. The shock radius is measured as this code's
Sedov reference does: the shell-mean density in shells of half the lattice spacing, and where it falls
half way from its peak to rho1.
"""
import csv
import glob
import json
import sys

import h5py
import numpy as np

RADIUS_TOL = 0.01  # |R_swift / R_here - 1|


def snapshot(path):
    """Time, radius from the blast centre, density and total energy of a SWIFT snapshot."""
    with h5py.File(path, "r") as f:
        t = float(np.ravel(f["Header"].attrs["Time"])[0])
        box = np.ravel(f["Header"].attrs["BoxSize"])
        g = f["PartType0"]
        x = g["Coordinates"][:]
        m = g["Masses"][:]
        u = g["InternalEnergies"][:] if "InternalEnergies" in g else g["InternalEnergy"][:]
        v = g["Velocities"][:]
        rho = g["Densities"][:] if "Densities" in g else g["Density"][:]
    return t, x, box, rho, float(np.sum(m * (u + 0.5 * np.sum(v * v, axis=1))))


def shock_radius(r, rho, dr, r_max, rho1):
    """Where the shell-mean density falls half way from its peak to rho1 (engine/scenes/reference)."""
    bins = int(r_max / dr)
    k = (r / dr).astype(int)
    keep = k < bins
    count = np.bincount(k[keep], minlength=bins)
    total = np.bincount(k[keep], weights=rho[keep], minlength=bins)
    mean = np.where(count > 0, total / np.maximum(count, 1), 0.0)
    centre = (np.arange(bins) + 0.5) * dr
    peaks = [j for j in range(bins) if count[j] >= 3]
    peak = max(peaks, key=lambda j: (mean[j], -j))
    level = 0.5 * (mean[peak] + rho1)
    r_prev, v_prev = centre[peak], mean[peak]
    for j in range(peak + 1, bins):
        if count[j] == 0:
            continue
        if mean[j] < level:
            return r_prev + (v_prev - level) / (v_prev - mean[j]) * (centre[j] - r_prev)
        r_prev, v_prev = centre[j], mean[j]
    return 0.0


def main():
    ic_file, swift_dir, errors_csv = sys.argv[1:4]
    energy_tol = float(sys.argv[4])  # |E(t)/E(0) - 1| of SWIFT's run
    with h5py.File(ic_file, "r") as f:
        sandbox = f["SPHSandbox"].attrs
        scene = json.loads(sandbox["scene_json"])
        shift = np.ravel(sandbox["coordinate_shift"])
        dim = int(np.ravel(f["Header"].attrs["Dimension"])[0])
    prm = scene["params"]
    half, n_side, rho1 = prm["scene.half"], prm["scene.n_side"], prm["scene.rho1"]
    dr = 0.5 * 2.0 * half / n_side  # the reference's shells: half the lattice spacing
    snaps = sorted(glob.glob(swift_dir + "/" + scene["scene"] + "_[0-9]*.hdf5"))
    if len(snaps) < 2:
        print("FAIL: SWIFT wrote %d snapshots in %s" % (len(snaps), swift_dir))
        return 1
    # E(0) from the initial conditions: SWIFT's t = 0 output extrapolates velocities half a step back
    _, _, _, _, e0 = snapshot(ic_file)
    t0 = snapshot(snaps[0])[0]
    t1, x, box, rho, e1 = snapshot(snaps[-1])
    d = x[:, :dim] - shift[:dim]  # from the blast centre, nearest periodic image
    d -= box[:dim] * np.round(d / box[:dim])
    r_swift = shock_radius(np.sqrt(np.sum(d * d, axis=1)), rho, dr, half, rho1)
    with open(errors_csv) as f:
        last = list(csv.DictReader(f))[-1]
    r_here, t_here, de_here = float(last["R"]), float(last["t"]), float(last["dE_rel"])
    de_swift = abs(e1 / e0 - 1.0)
    print("%dD Sedov  SWIFT t = %g: |dE/E| = %.3g, R = %.5f   here t = %g: |dE/E| = %.3g, R = %.5f"
          "   R ratio - 1 = %+.4f" % (dim, t1, de_swift, r_swift, t_here, de_here, r_here, r_swift / r_here - 1.0))
    fails = 0
    if abs(t1 - t_here) > 1e-6 * max(t_here, 1.0) or t0 != 0.0:
        print("FAIL: SWIFT's snapshots span t = %g .. %g, this code's ended at %g" % (t0, t1, t_here))
        fails += 1
    if not de_swift <= energy_tol:
        print("FAIL: SWIFT's energy drift %.3g > %g" % (de_swift, energy_tol))
        fails += 1
    if not abs(r_swift / r_here - 1.0) <= RADIUS_TOL:
        print("FAIL: shock radii differ by more than %g" % RADIUS_TOL)
        fails += 1
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
