// Kernel correction by moving least squares (seed 001 eqs. 17-23): the corrected kernel
//   K*_m(x_a, x_b) = p(0)^T <p, p^T>_K^-1 p((x_b - x_a)/h) W_ab,  <f, g>_K = sum_b V_b W_ab f_b g_b,
// with the basis p = [1] (m = 0, Shepard) or [1, (x_b - x_a)/h] (m = 1), reproduces polynomials of
// degree <= m exactly: sum_b V_b K*_m(x_a, x_b) f_b = f(x_a) (eq. 23). Small dense systems, solved
// with Eigen; an ill-conditioned moment matrix (too few neighbours on one side) falls back to m = 0.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/particles.h"

namespace sph {

/// The weights w_b = V_b K*_m(x_a, x_b) of particle a's neighbours `nb` (same order), with V_b =
/// m_b / rho_b and h = h_a. Returns the order used (m, or 0 after a fallback: the (d+1) x (d+1) moment
/// matrix had a reciprocal condition number below min_rcond). Skips wall particles if skip_walls.
int corrected_kernel_weights(const Kernel& K, const Particles& p, std::size_t a, std::span<const std::uint32_t> nb,
                             int order, double min_rcond, bool skip_walls, std::vector<double>& weights);

}  // namespace sph
