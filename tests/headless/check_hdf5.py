"""Reads HDF5 files written by `sph` with h5py and checks every dataset and attribute a SWIFT (or GADGET-4)
initial condition must have, their shapes, and their values against the run's CSV file.
usage: python3 check_hdf5.py FILE.hdf5 PARTICLES.csv LAYOUT(swift|gadget4) H_FACTOR [TIME]
  H_FACTOR: SmoothingLength / this code's h expected, a number or A/B (SWIFT: support/gamma_K, GADGET-4:
  the support)"""
import csv
import sys

import h5py
import numpy as np


def fail(msg):
    print("FAIL %s: %s" % (sys.argv[1], msg))
    sys.exit(1)


path, csv_path, layout = sys.argv[1], sys.argv[2], sys.argv[3]
num, _, den = sys.argv[4].partition("/")
h_factor = float(num) / (float(den) if den else 1.0)
f = h5py.File(path, "r")
header = f["Header"].attrs
for name in ("NumPart_ThisFile", "NumPart_Total", "NumPart_Total_HighWord", "MassTable", "Time", "Redshift",
             "BoxSize", "NumFilesPerSnapshot", "Flag_Entropy_ICs", "Dimension"):
    if name not in header:
        fail("/Header has no %s" % name)
for name in ("Unit length in cgs (U_L)", "Unit mass in cgs (U_M)", "Unit time in cgs (U_t)",
             "Unit current in cgs (U_I)", "Unit temperature in cgs (U_T)"):
    if name not in f["Units"].attrs:
        fail("/Units has no %s" % name)
counts = list(header["NumPart_ThisFile"])
if len(counts) != 6 or list(header["NumPart_Total"]) != counts or any(header["NumPart_Total_HighWord"]):
    fail("NumPart_ThisFile %s, NumPart_Total %s" % (counts, list(header["NumPart_Total"])))
if header["NumFilesPerSnapshot"] != 1 or header["Flag_Entropy_ICs"] != 0:
    fail("NumFilesPerSnapshot %s, Flag_Entropy_ICs %s" % (header["NumFilesPerSnapshot"], header["Flag_Entropy_ICs"]))
box = np.atleast_1d(header["BoxSize"])
if layout == "swift" and box.shape != (3,):
    fail("SWIFT BoxSize should have 3 sides, has %s" % box)
if layout == "gadget4" and box.shape != (1,):
    fail("GADGET-4 BoxSize should be one number, is %s" % box)

with open(csv_path) as c:
    rows = list(csv.DictReader(c))
ptype = 0 if counts[0] else 1
group = f["PartType%d" % ptype]
n = counts[ptype]
if n != len(rows):
    fail("%d particles, the CSV has %d" % (n, len(rows)))
required = ["Coordinates", "Velocities", "Masses", "ParticleIDs"]
if ptype == 0:
    required += ["SmoothingLength", "InternalEnergy", "Density"]
for name in required:
    if name not in group:
        fail("/PartType%d/%s is missing" % (ptype, name))
    shape = group[name].shape
    if shape != ((n, 3) if name in ("Coordinates", "Velocities") else (n,)):
        fail("/PartType%d/%s has shape %s" % (ptype, name, shape))
ids = group["ParticleIDs"][:]
if sorted(ids) != list(range(1, n + 1)):
    fail("ParticleIDs are not 1..N")
shift = f["SPHSandbox"].attrs["coordinate_shift"]
x = group["Coordinates"][:]
dim = int(header["Dimension"])
if layout == "swift" and np.any(x[:, :dim] < 0) | np.any(x[:, :dim] > box[:dim]):
    fail("coordinates outside [0, BoxSize]")
order = {int(r["id"]): r for r in rows}
worst = 0.0


def compare(value, expected, what, i):
    global worst
    err = abs(value - expected) / max(1.0, abs(expected))
    worst = max(worst, err)
    if err > 1e-12:
        fail("particle %d: %s = %r, CSV %r" % (i, what, value, expected))


v = group["Velocities"][:]
m = group["Masses"][:]
h = group["SmoothingLength"][:] if "SmoothingLength" in group else None
for k in range(n):
    r = order[int(ids[k]) - 1]
    for a, c in enumerate("xyz"):
        if a < dim:
            compare(x[k][a] - shift[a], float(r[c]), c, k)
        compare(v[k][a], float(r["v" + c]), "v" + c, k)
    compare(m[k], float(r["m"]), "Masses", k)
    if ptype == 0:
        compare(h[k] / h_factor, float(r["h"]), "SmoothingLength / factor", k)
        compare(group["Density"][k], float(r["rho"]), "Density", k)
        if "u" in r:
            compare(group["InternalEnergy"][k], float(r["u"]), "InternalEnergy", k)
if len(sys.argv) > 5 and abs(float(header["Time"]) - float(sys.argv[5])) > 1e-12:
    fail("Time = %r, expected %s" % (header["Time"], sys.argv[5]))
print("%s: %d particles of PartType%d, every dataset present, largest relative difference %.2g" % (path, n, ptype, worst))
