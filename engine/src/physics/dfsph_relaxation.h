// How far DFSPH's Jacobi sweeps may step: the relaxation w of kappa_a <- kappa_a + w source_a alpha_a / dt^2
// (physics/dfsph_solver.h), from the kernel's width.
//
// On a periodic lattice (spacing 1, rho = rho0, g_ab = m grad W_ab) a pressure change kappa_b = e^{i k.x_b}
// changes the sources by -(dt^2/rho0) |G(k)|^2 kappa with G(k) = sum_b g_ab sin(k.(x_a - x_b)), and alpha =
// rho0 / sum_b |g_ab|^2, so a sweep multiplies that error mode by 1 - w lambda(k), lambda(k) = |G(k)|^2 /
// sum_b |g_ab|^2. The sweeps converge when w lambda < 2 for every k. Smooth modes have a small lambda (they
// converge slowly); the largest, at the lattice's own scale, grows with the neighbours a kernel reaches:
// M4 at h = 1.3 dx 2.88 (2D) and 4.91 (3D), at 1.6 dx 4.28 and 8.98; Wendland C4 at 2 dx 4.28 and 9.34.
// With the fixed w of IISPH (0.5 in 2D) and of this code before (0.3 in 3D), wider kernels diverged within a
// step (x = 7e285 at h = 2 dx with M4; the tank, the drop and the dam break at M4 1.55, M5 1.45, M6 1.3,
// Wendland C2 and C4 2.0 in 2D, M4 1.5, M5 1.35, Gaussian 1.3 in 3D), each where w lambda_max passes 2.
#pragma once
#include "sph/kernel.h"

namespace sph {

/// The largest lambda(k) over the lattice's Brillouin zone for kernel K (its dimension) at h = eta dx
/// [dimensionless]: the mode a Jacobi sweep amplifies most. A sum over the pairs at each of 25^3 wave
/// vectors in 3D (0.11 s for M6 at h = 1.3 dx, 2.3 s at the largest eta, 4); the solver keeps it until the
/// kernel or eta changes.
double dfsph_lattice_stiffness(const Kernel& K, double eta);

/// The sweeps' relaxation: 1.5 / lambda_max (w lambda_max = 1.5, a quarter below divergence), at most
/// 0.5 in 1D and 2D and 0.3 in 3D (the values tuned for M4 at h = 1.3 dx, where 1.5 / lambda_max is 0.52
/// and 0.31: the scenes' defaults step as before).
double dfsph_relaxation(const Kernel& K, double eta);

}  // namespace sph
