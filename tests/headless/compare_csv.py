"""Compares two particle CSV files of `sph run` row by row (same ids, every shared column within a relative
tolerance), or with --plateaus checks the densities of the SWIFT-style Sod IC (make_swift_sod.py): rho
within 1% of 1 on x in [0.1, 0.9] and of 0.125 on [1.2, 1.8].
usage: compare_csv.py A.csv B.csv TOL | compare_csv.py --plateaus FILE.csv"""
import csv
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


if sys.argv[1] == "--plateaus":
    worst = {}
    for r in rows(sys.argv[2]):
        x, rho = float(r["x"]), float(r["rho"])
        for lo, hi, want in ((0.1, 0.9, 1.0), (1.2, 1.8, 0.125)):
            if lo <= x <= hi:
                worst[want] = max(worst.get(want, 0.0), abs(rho / want - 1.0))
    print("largest relative deviation from the plateaus: %s" % worst)
    sys.exit(0 if len(worst) == 2 and max(worst.values()) < 0.01 else 1)

a, b, tol = rows(sys.argv[1]), rows(sys.argv[2]), float(sys.argv[3])
if len(a) != len(b):
    print("FAIL: %d rows against %d" % (len(a), len(b)))
    sys.exit(1)
worst = 0.0
for ra, rb in zip(a, b):
    if ra["id"] != rb["id"]:
        print("FAIL: id %s against %s" % (ra["id"], rb["id"]))
        sys.exit(1)
    for c in set(ra) & set(rb):
        va, vb = float(ra[c]), float(rb[c])
        err = abs(va - vb) / max(1.0, abs(va))
        worst = max(worst, err)
        if err > tol:
            print("FAIL: particle %s: %s = %r against %r" % (ra["id"], c, va, vb))
            sys.exit(1)
print("%d rows, largest relative difference %.2g" % (len(a), worst))
