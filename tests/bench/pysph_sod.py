#!/usr/bin/python3
"""Reference benchmark: PySPH on the 1D Sod shock tube.

Runs PySPH's stock example pysph.examples.gas_dynamics.sod_shocktube
(default ADKE scheme, Gaussian kernel, fixed dt = 1e-4, domain [-0.5, 0.5],
mirror boundaries, diaphragm at x = 0) single-threaded with the given
left-side particle count and end time, then compares the final particle
state with the exact Riemann solution (Toro, ch. 4) and prints one CSV line:

    code,nl,N_total,tf,run_seconds,L1_rho,L1_v,L1_p

run_seconds is PySPH's own "Run took" time (time stepping incl. writing the
first and last output files; Cython compilation and setup are excluded).
L1_q = mean over particles of |q - q_exact|, over all particles, or only
over particles with |x| <= W if --window W is given.

Requires the Debian package python3-pysph; run with /usr/bin/python3.
Usage: /usr/bin/python3 pysph_sod.py --nl 640 --tf 0.15 [--window 0.4]
"""
import argparse
import contextlib
import io
import json
import shutil
import tempfile

import numpy as np

GAMMA = 1.4
LEFT = (1.0, 0.0, 1.0)     # rho, v, p for x < 0
RIGHT = (0.125, 0.0, 0.1)  # rho, v, p for x > 0
X0 = 0.0


def exact_riemann(x, t, left=LEFT, right=RIGHT, g=GAMMA, x0=X0):
    """Exact solution (rho, v, p) of the 1D Euler Riemann problem at x, t."""
    rl, ul, pl = left
    rr, ur, pr = right
    cl, cr = np.sqrt(g * pl / rl), np.sqrt(g * pr / rr)

    def f(p, rk, pk, ck):  # Toro (4.6)-(4.7) and derivative
        if p > pk:  # shock
            a, b = 2.0 / ((g + 1) * rk), (g - 1) / (g + 1) * pk
            q = np.sqrt(a / (p + b))
            return (p - pk) * q, q * (1 - 0.5 * (p - pk) / (p + b))
        r = (p / pk) ** ((g - 1) / (2 * g))  # rarefaction
        return 2 * ck / (g - 1) * (r - 1), r / (rk * ck) * (pk / p)

    # star pressure by Newton iteration from the two-rarefaction guess
    z = (g - 1) / (2 * g)
    p = ((cl + cr - 0.5 * (g - 1) * (ur - ul)) /
         (cl / pl ** z + cr / pr ** z)) ** (1 / z)
    for _ in range(100):
        fl, dl = f(p, rl, pl, cl)
        fr, dr = f(p, rr, pr, cr)
        pn = max(p - (fl + fr + ur - ul) / (dl + dr), 1e-12)
        done = abs(pn - p) < 1e-14 * (pn + p)
        p = pn
        if done:
            break
    us = 0.5 * (ul + ur) + 0.5 * (f(p, rr, pr, cr)[0] - f(p, rl, pl, cl)[0])

    s = (np.asarray(x, dtype=float) - x0) / t
    rho, v, pr_ = np.empty_like(s), np.empty_like(s), np.empty_like(s)
    gm = (g - 1) / (g + 1)
    for side, (rk, uk, pk, ck, sg) in enumerate(((rl, ul, pl, cl, -1.0),
                                                 (rr, ur, pr, cr, 1.0))):
        m = s <= us if side == 0 else s > us
        if p > pk:  # shock on this side
            rs = rk * (p / pk + gm) / (gm * p / pk + 1)
            S = uk + sg * ck * np.sqrt((g + 1) / (2 * g) * p / pk
                                       + (g - 1) / (2 * g))
            out = m & (sg * (s - S) > 0)
            rho[m], v[m], pr_[m] = rs, us, p
            rho[out], v[out], pr_[out] = rk, uk, pk
        else:  # rarefaction on this side
            cs = ck * (p / pk) ** ((g - 1) / (2 * g))
            head, tail = uk + sg * ck, us + sg * cs
            rho[m], v[m], pr_[m] = rk * (p / pk) ** (1 / g), us, p
            out = m & (sg * (s - head) > 0)
            fan = m & ~out & (sg * (s - tail) > 0)
            rho[out], v[out], pr_[out] = rk, uk, pk
            sf = s[fan]
            w = 2 / (g + 1) - sg * gm / ck * (uk - sf)
            rho[fan] = rk * w ** (2 / (g - 1))
            v[fan] = 2 / (g + 1) * (-sg * ck + 0.5 * (g - 1) * uk + sf)
            pr_[fan] = pk * w ** (2 * g / (g - 1))
    return rho, v, pr_


def run_pysph(nl, tf, outdir):
    """Run the stock example in-process (no plotting post-processing);
    return (PySPH's "Run took" seconds, final output file)."""
    from pysph.examples.gas_dynamics.sod_shocktube import SodShockTube
    app = SodShockTube()
    with contextlib.redirect_stdout(io.StringIO()):  # keep stdout to 1 line
        app.run(['--nl', str(nl), '--tf', str(tf), '-d', outdir,
                 '--pfreq', '100000000', '-q'])
    with open(app.info_filename) as fp:  # cpu_time is the "Run took" value
        run_s = json.load(fp)['cpu_time']
    return run_s, app.output_files[-1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--nl', type=int, default=640,
                    help='particles in the left half (right half: nl/8)')
    ap.add_argument('--tf', type=float, default=0.15, help='end time')
    ap.add_argument('--window', type=float, default=None,
                    help='only count particles with |x| <= WINDOW')
    ap.add_argument('--keep', default=None,
                    help='keep PySPH output in this directory')
    args = ap.parse_args()

    from pysph.solver.utils import load

    outdir = args.keep or tempfile.mkdtemp(prefix='pysph_sod_')
    try:
        run_s, last = run_pysph(args.nl, args.tf, outdir)
        data = load(last)
    finally:
        if args.keep is None:
            shutil.rmtree(outdir, ignore_errors=True)

    pa = data['arrays']['fluid']
    t = float(data['solver_data']['t'])
    x, rho, v, p = pa.x, pa.rho, pa.u, pa.p
    re_, ve, pe = exact_riemann(x, t)
    sel = np.ones_like(x, bool) if args.window is None \
        else np.abs(x) <= args.window
    l1 = [np.mean(np.abs(a[sel] - b[sel]))
          for a, b in ((rho, re_), (v, ve), (p, pe))]
    print('pysph-adke,%d,%d,%g,%.4f,%.6e,%.6e,%.6e'
          % (args.nl, len(x), t, run_s, *l1))


if __name__ == '__main__':
    main()
