#!/usr/bin/env python3
"""Major and minor semi-axes of PySPH's elliptical drop output at its last time, measured like this
project does (the extent of the particles: max |y| and max |x|), against the incompressible ODE.
usage: pysph_drop_axes.py OUTPUT_DIR   (the -d directory of `python3 -m pysph.examples.elliptical_drop`)
prints: code,N,t,minor,major,err_major,ab"""
import math
import sys

from pysph.solver.utils import get_files, load


def ode(t, A0=100.0, h=1e-7):
    """dA/dt = A^2 (a^4 - 1)/(a^4 + 1), da/dt = -a A by classical RK4 (Monaghan 1994)."""
    def f(A, a):
        a4 = a ** 4
        return A * A * (a4 - 1.0) / (a4 + 1.0), -a * A
    A, a = A0, 1.0
    n = max(1, int(math.ceil(t / h)))
    h = t / n
    for _ in range(n):
        k1 = f(A, a)
        k2 = f(A + 0.5 * h * k1[0], a + 0.5 * h * k1[1])
        k3 = f(A + 0.5 * h * k2[0], a + 0.5 * h * k2[1])
        k4 = f(A + h * k3[0], a + h * k3[1])
        A += h / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        a += h / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    return a


files = get_files(sys.argv[1], 'elliptical_drop')
data = load(files[-1])
pa = data['arrays']['fluid']
t = data['solver_data']['t']
minor, major = abs(pa.x).max(), abs(pa.y).max()
exact = 1.0 / ode(t)
print("pysph,%d,%g,%.6f,%.6f,%.4e,%.6f" % (pa.get_number_of_particles(), t, minor, major, abs(major / exact - 1.0),
                                          minor * major))
