"""Opens the HDF5 files `sph` writes in yt (README "Outputs", "Initial conditions for SWIFT and GADGET-4") and
checks yt's units and per-particle density, positions and smoothing lengths against the CSV files of the same
states, matched by ParticleIDs. Every file is opened with yt.load(path) alone; two things a file cannot give yt
4.1 (nor yt's main branch) without saying something false, so the check adds them (see open_swift and
check_gadget4): three periodicity flags for a 1D/2D SWIFT file, the units and open box of a GADGET-4 file.
usage: /usr/bin/python3 check_yt.py SPH_BINARY WORK_DIR
Exit 0: every check holds; 1: one failed (the message names the file and the quantity); 77: yt or h5py cannot be
imported (skipped)."""
import csv
import os
import shutil
import subprocess
import sys

try:
    import h5py
    import numpy as np
    import yt
except ImportError as e:
    print("SKIP: yt/h5py not importable (%s); Debian: apt-get install python3-yt python3-h5py" % e)
    sys.exit(77)

TOL = 1e-6  # relative, per particle: yt's values against the CSV's (17 digits each; measured at most 5e-15)
UNITS = (("length", "cm", "Unit length in cgs (U_L)"), ("mass", "g", "Unit mass in cgs (U_M)"),
         ("time", "s", "Unit time in cgs (U_t)"))
sph, work = sys.argv[1], sys.argv[2]
yt.set_log_level(40)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "ics"))
worst = {}


def fail(msg):
    print("FAIL " + msg)
    sys.exit(1)


def run(*args):
    r = subprocess.run([sph, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        fail("sph %s: exit %d: %s" % (" ".join(args), r.returncode, r.stderr.strip()[-400:]))


def read_csv(path):
    """The rows of a particle CSV file by id (0-based; the HDF5 ParticleIDs are id + 1)."""
    with open(path) as c:
        rows = [r for r in csv.DictReader(line for line in c if not line.startswith("#"))]
    return {int(r["id"]): {k: float(v) for k, v in r.items()} for r in rows}


def compare(path, what, got, want, scale):
    """Largest |got - want| / scale over the particles; fails above TOL."""
    err = float(np.max(np.abs(got - want) / scale))
    worst[what] = max(worst.get(what, 0.0), err)
    if not err <= TOL:
        fail("%s: %s differs from the CSV by %.3g (relative; tolerance %g)" % (path, what, err, TOL))


def check_units(ds, f, path):
    """yt's code units are the file's /Units (cgs), its time the header's Time."""
    for name, cgs, key in UNITS:
        want = float(f["Units"].attrs[key])
        got = float(getattr(ds, name + "_unit").to(cgs).v)
        if abs(got - want) > 1e-12 * want:
            fail("%s: yt's %s_unit is %r %s, /Units %s says %r" % (path, name, got, cgs, key, want))
    t = float(f["Header"].attrs["Time"])
    if abs(float(ds.current_time.to("code_time").v) - t) > 1e-12 * max(1.0, t):
        fail("%s: yt's current_time %s, /Header Time %r" % (path, ds.current_time, t))


def open_swift(path, gamma_k):
    """yt.load(path) with no other argument: the SWIFT frontend, the file's units, box and kernel gamma_K."""
    try:
        ds = yt.load(path)
    except Exception as e:  # yt's own error, whatever its type: the file is not one yt can open alone
        fail("%s: yt.load: %s: %s" % (path, type(e).__name__, e))
    if type(ds).__name__ != "SwiftDataset":
        fail("%s: yt chose %s, not its SWIFT frontend" % (path, type(ds).__name__))
    if len(ds.periodicity) < 3:
        # yt's SWIFT frontend makes one periodicity flag per /Header Dimension (yt/frontends/swift/
        # data_structures.py:113-121 in 4.1.4) and nothing else in the file changes that count, while
        # ParticleBitmap.__init__ (yt/geometry/particle_oct_container.pyx) reads three: IndexError at the first
        # field. Dimension must stay 2: it says the density is mass per area, and SWIFT refuses an IC whose
        # Dimension is not its hydro dimension (its common_io.c); SWIFT's own 2D snapshots fail in yt alike.
        # yt's public force_periodicity() gives three flags; the box is periodic or four times the scene's
        # domain, so no kernel reaches across it either way.
        ds.force_periodicity()
    with h5py.File(path, "r") as f:
        box = f["Header"].attrs["BoxSize"]
        if not np.allclose(ds.domain_right_edge.to("code_length").v, box, rtol=1e-15, atol=0):
            fail("%s: yt's domain %s, BoxSize %s" % (path, ds.domain_right_edge, box))
        if ds.dimensionality != int(f["Header"].attrs["Dimension"]):
            fail("%s: yt's dimensionality %d" % (path, ds.dimensionality))
        check_units(ds, f, path)
        gamma = float(f["HydroScheme"].attrs["Kernel gamma"])
        if abs(gamma - gamma_k) > 1e-12:
            fail("%s: /HydroScheme Kernel gamma %r, expected %r" % (path, gamma, gamma_k))
    return ds


def check_particles(ds, path, rows, h_factor, cgs=True):
    """Density (code units and, if cgs, g/cm^3), positions (less the file's shift) and smoothing lengths (over
    h_factor, the file's h per this code's h) by id."""
    with h5py.File(path, "r") as f:
        shift = f["SPHSandbox"].attrs["coordinate_shift"]
        dim = int(f["Header"].attrs["Dimension"])
        u = {key: float(f["Units"].attrs[key]) for _, _, key in UNITS}
    ad = ds.all_data()
    ids = ad["PartType0", "ParticleIDs"].v.astype(np.int64) - 1
    if sorted(ids.tolist()) != sorted(rows):
        fail("%s: yt reads %d particles, ids not those of the CSV (%d rows)" % (path, len(ids), len(rows)))
    want = {k: np.array([rows[i][k] for i in ids]) for k in ("rho", "h", "x", "y", "z")}
    rho = ad["gas", "density"]
    compare(path, "density [code]", rho.to("code_mass/code_length**3").v, want["rho"], np.abs(want["rho"]))
    if cgs:
        rho_cgs = want["rho"] * u["Unit mass in cgs (U_M)"] / u["Unit length in cgs (U_L)"] ** 3
        compare(path, "density [g/cm^3]", rho.to("g/cm**3").v, rho_cgs, np.abs(rho_cgs))
    pos = ad["PartType0", "particle_position"].to("code_length").v
    width = ds.domain_width.to("code_length").v
    for k, c in enumerate("xyz"[:dim]):
        compare(path, "position / box side", pos[:, k] - shift[k], want[c], width[k])
    hsml = ad["PartType0", "smoothing_length"].to("code_length").v
    compare(path, "smoothing length", hsml / h_factor, want["h"], np.abs(want["h"]))
    return len(ids)


def check_run(name, scene, gamma_k, *sets):
    """A short run's --hdf5 snapshots against its CSVs; returns BoxSize and shift of each snapshot."""
    out = os.path.join(work, name)
    run("run", scene, "--hdf5", "--out", out, *sets)
    frames = []
    snaps = sorted(s for s in os.listdir(out) if s.startswith("particles_") and s.endswith(".hdf5"))
    if len(snaps) < 2:
        fail("%s: %d snapshots, expected at least 2" % (out, len(snaps)))
    for s in snaps:
        path = os.path.join(out, s)
        n = check_particles(open_swift(path, gamma_k), path, read_csv(path[:-5] + ".csv"), 2.0 / gamma_k)
        with h5py.File(path, "r") as f:
            frames.append((tuple(f["Header"].attrs["BoxSize"]), tuple(f["SPHSandbox"].attrs["coordinate_shift"])))
    print("%s: %d snapshots of %d particles open in yt" % (out, len(snaps), n))
    return frames


def check_gadget4(path, rows, h_factor):
    """yt.load(path) alone takes a GADGET-4 file with its Gadget frontend and reads every value right in code
    units, but its units are never the file's: GadgetDataset keeps unit_base from yt.load's argument only
    (yt/frontends/gadget/data_structures.py:289 in 4.1.4) and without it takes 1 kpc, 1e10 Msun, 1 km/s
    (:446-454, :486, :501; sedov3d's density 6.7e-22 g/cm^3 for 1); /Header and /Parameters attributes go to
    ds.parameters only (:616-633), /Units is read by the OWLS/EAGLE frontends alone, which need OWLS's groups
    and take the file for a comoving cosmological run. With BoxSize 0 (an open box, GADGET-4's convention) yt
    infers a box from the particles (yt/geometry/particle_geometry_handler.py:118-141). So the values are
    checked in code units with yt.load alone, and in cgs with unit_base from /Units and a bounding box."""
    alone = yt.load(path)
    check_particles(alone, path, rows, h_factor, cgs=False)
    print("note: yt.load(%s) alone: %s with length_unit %s (yt reads no units from a GADGET file)"
          % (os.path.basename(path), type(alone).__name__, alone.length_unit.to("cm")))
    with h5py.File(path, "r") as f:
        u = {key: float(f["Units"].attrs[key]) for _, _, key in UNITS}
        side = float(f["Header"].attrs["BoxSize"])  # 0: open; the coordinates are >= 0 (shifted), any cube holds them
        side = side if side > 0 else 2.0 * float(np.max(f["PartType0"]["Coordinates"][:]))
    base = {"UnitLength_in_cm": u["Unit length in cgs (U_L)"], "UnitMass_in_g": u["Unit mass in cgs (U_M)"],
            "UnitVelocity_in_cm_per_s": u["Unit length in cgs (U_L)"] / u["Unit time in cgs (U_t)"]}
    ds = yt.load(path, unit_base=base, bounding_box=[[0.0, side]] * 3)
    with h5py.File(path, "r") as f:
        check_units(ds, f, path)
    return check_particles(ds, path, rows, h_factor)


def check_ics(scene, gamma_k, *sets):
    """The scene's SWIFT and GADGET-4 initial conditions against its CSV at t = 0."""
    run("run", scene, "--until", "0", "--out", os.path.join(work, scene + "0"), *sets)
    rows = read_csv(os.path.join(work, scene + "0", "particles_00000.csv"))
    swift, gadget = (os.path.join(work, "ics", scene + s) for s in (".hdf5", "_g4.hdf5"))
    run("export-ics", scene, "--format", "swift", "--out", swift, *sets)
    run("export-ics", scene, "--format", "gadget4", "--out", gadget, *sets)
    n = check_particles(open_swift(swift, gamma_k), swift, rows, 2.0 / gamma_k)
    check_gadget4(gadget, rows, 2.0)  # GADGET-4's h is the support radius, 2h for M4
    print("%s: %d particles of the SWIFT and the GADGET-4 IC in yt" % (scene, n))


# SWIFT's gamma_K = H/h of the cubic spline (M4, support 2h here): 2D 1.778002, 3D 1.825742 (Dehnen & Aly 2012).
# dam_break: 2D, SI units (U_L = 100 cm, U_M = 1000 g), walls; evrard: 3D, open; the tank: 3D, SI, walls.
check_run("dam_break", "dam_break", 1.778002, "--until", "0.004", "--set", "scene.dx=0.05", "--set", "time.dt_out=0.002")
frames = check_run("evrard", "evrard", 1.825742, "--until", "0.02", "--set", "scene.n=400", "--set", "time.dt_out=0.01")
if len(set(frames)) != 1:
    fail("evrard (open box): BoxSize and coordinate_shift differ between snapshots: %s" % frames)
check_ics("hydrostatic_tank_3d", 1.825742)
check_ics("sedov3d", 1.825742, "--set", "scene.n_side=12")
print("largest relative differences: " + ", ".join("%s %.2g" % kv for kv in sorted(worst.items())))
