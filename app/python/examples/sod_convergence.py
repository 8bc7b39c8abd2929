# %% [markdown]
# # Sod shock tube: convergence of the density error with resolution
# A notebook-style script (cells marked `# %%` open as cells in Jupyter or VS Code). It runs the Sod tube
# (seed 000, section 4.1) at several resolutions through the engine's Python module, reads the L1 error of
# the density against the exact Riemann solution at t = 0.2, fits the observed order of convergence and
# plots it. Run it as a script:
#   PYTHONPATH=build/python /usr/bin/python3 app/python/examples/sod_convergence.py --out sod_convergence.png

# %%
import argparse
import math
import time

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np
import sphsandbox as sph

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--n", default="100,200,400,800", help="particles on the left of the membrane, comma-separated")
parser.add_argument("--t", type=float, default=0.2, help="time of the comparison")
parser.add_argument("--out", default="sod_convergence.png", help="the plot (PNG)")
args = parser.parse_args()
resolutions = [int(v) for v in args.n.split(",")]

# %% One run per resolution: the error norms of the reference at t
rows = []
for n in resolutions:
    start = time.perf_counter()
    world = sph.World("sod", set={"scene.n_left": n})
    world.run_to(args.t)
    e = world.errors()
    rows.append((n, e["L1_rho"], e["L1_v"], e["L1_p"], time.perf_counter() - start, world.steps))
    print("n = %5d  L1(rho) = %.3e  L1(v) = %.3e  L1(p) = %.3e  %.2f s  %d steps" % rows[-1])

# %% Observed order: the slope of log L1 against log n (least squares)
n = np.array([r[0] for r in rows], dtype=float)
l1 = np.array([r[1] for r in rows])
order = -np.polyfit(np.log(n), np.log(l1), 1)[0]
print("observed order of L1(rho): %.2f" % order)

# %% The plot: L1 against n on log axes, with the fitted slope
fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
ax.loglog(n, l1, "o-", label="L1(rho), SPH")
ax.loglog(n, l1[0] * (n / n[0]) ** -order, "--", label="slope -%.2f" % order)
ax.set_xlabel("particles left of the membrane, n")
ax.set_ylabel("L1 error of the density at t = %g" % args.t)
ax.set_title("Sod shock tube: convergence")
ax.legend()
fig.tight_layout()
fig.savefig(args.out)
print("plot: " + args.out)
print("order=%.4f" % order if math.isfinite(order) else "order=nan")
