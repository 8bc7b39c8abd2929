"""Writes a 1D Sod shock tube in the layout of SWIFT's examples (examples/HydroTests/SodShock_1D/makeIC.py:
/Header, /Units, /PartType0 with single-precision Velocities, Masses, SmoothingLength and InternalEnergy,
ids from 1), written here with h5py: the kind of file `sph run FILE.hdf5` must read.
Left rho = 1, P = 1 on [0, 1); right rho = 0.125, P = 0.1 on [1, 2); periodic box of side 2; gamma = 5/3.
usage: python3 make_swift_sod.py FILE.hdf5 N_LEFT"""
import sys

import h5py
import numpy as np

path, n_left = sys.argv[1], int(sys.argv[2])
gamma = 5.0 / 3.0
n_right = n_left // 8
dx_l, dx_r = 1.0 / n_left, 1.0 / n_right
x = np.concatenate([(np.arange(n_left) + 0.5) * dx_l, 1.0 + (np.arange(n_right) + 0.5) * dx_r])
n = x.size
coords = np.zeros((n, 3))
coords[:, 0] = x
m = np.concatenate([np.full(n_left, 1.0 * dx_l), np.full(n_right, 0.125 * dx_r)])
u = np.concatenate([np.full(n_left, 1.0 / (1.0 * (gamma - 1))), np.full(n_right, 0.1 / (0.125 * (gamma - 1)))])
h = np.concatenate([np.full(n_left, 1.2348 * dx_l), np.full(n_right, 1.2348 * dx_r)])
with h5py.File(path, "w") as f:
    g = f.create_group("Header")
    g.attrs["BoxSize"] = 2.0
    g.attrs["NumPart_Total"] = [n, 0, 0, 0, 0, 0]
    g.attrs["NumPart_Total_HighWord"] = [0] * 6
    g.attrs["NumPart_ThisFile"] = [n, 0, 0, 0, 0, 0]
    g.attrs["Time"] = 0.0
    g.attrs["NumFilesPerSnapshot"] = 1
    g.attrs["MassTable"] = [0.0] * 6
    g.attrs["Flag_Entropy_ICs"] = 0
    g.attrs["Dimension"] = 1
    units = f.create_group("Units")
    for name in ("length", "mass", "time", "current", "temperature"):
        units.attrs["Unit %s in cgs (U_%s)" % (name, {"length": "L", "mass": "M", "time": "t", "current": "I",
                                                      "temperature": "T"}[name])] = 1.0
    p = f.create_group("PartType0")
    p.create_dataset("Coordinates", data=coords, dtype="d")
    p.create_dataset("Velocities", data=np.zeros((n, 3)), dtype="f")
    p.create_dataset("Masses", data=m, dtype="f")
    p.create_dataset("SmoothingLength", data=h, dtype="f")
    p.create_dataset("InternalEnergy", data=u, dtype="f")
    p.create_dataset("ParticleIDs", data=np.arange(1, n + 1), dtype="L")
print("%s: %d + %d particles" % (path, n_left, n_right))
