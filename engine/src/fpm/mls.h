// Moving least squares in 1D, the approximation at the heart of the finite pointset method (seed 002
// §3.1, eqs. 7-12 and Program 1): at a point xbar, f(xbar), f'(xbar) and f''(xbar) are the coefficients
// c of the local quadratic p(x) = c0 + c1 (x - xbar) + c2 (x - xbar)^2 / 2 that minimises the residual
// sum_j w_j (f_j - p(x_j))^2 over the given points (eq. 8), with the Gaussian weight of eq. 9,
//   w_j = exp(-alpha (d_j/h)^2) for |d_j| <= h, 0 otherwise, d_j = x_j - xbar
// (the closed bound |d| <= h is Program 1's; eq. 9 prints |d| < h). c solves the normal equations
// (P^T W P) c = P^T W f (eq. 10). For conditioning the offsets are scaled, s = d/h (c1 and c2 then carry
// factors h and h^2, undone on output), and the value f_n of the nearest point is subtracted from the
// data (Program 1's fmin; exact, since the basis contains the constants).
// Side::Left / Right keep only neighbours with d < 0 / d > 0 (and a point at d = 0): the one-sided
// (upwind) fits of seed 002 §3.4, which zero the weights of the other side.
//
// Guard (seed 002 Theorem 3.1 assumes it silently: P^T W P is invertible only when at least three
// distinct points carry weight). Let "used" be the points with nonzero weight:
//  - order 2 (quadratic) needs >= 3 distinct used positions and a reciprocal condition number
//    lambda_min / lambda_max >= opt.min_rcond (default 1e-10) of the scaled 3x3 normal matrix;
//  - otherwise order 1 (linear, d2f = 0): the weighted linear fit, with >= 2 distinct used positions and
//    the same rcond test on its scaled 2x2 normal matrix;
//  - otherwise order 0 (constant, df = d2f = 0): the weighted mean of the used values (>= 1 point,
//    coincident points included);
//  - otherwise (no used point, or h <= 0 or not finite) order -1 and f = df = d2f = 0.
// One-sided fits with few neighbours and fits at the ends of the domain fall back this way.
// The call allocates nothing (fixed-size Eigen matrices) and sums in the order of the input, so it is
// deterministic; points with zero weight do not enter any sum, so adding them changes nothing, bitwise.
#pragma once
#include <span>

namespace sph::fpm {

enum class Side { Both, Left, Right };

struct MlsOptions {
  double h = 0;              ///< smoothing length [length]: the support of the weight
  double alpha = 8.0;        ///< weight exponent (seed 002: alpha in [2, 8]; Program 1 uses 8)
  Side side = Side::Both;    ///< Left / Right: the one-sided (upwind) fits of seed 002 §3.4
  double min_rcond = 1e-10;  ///< lowest lambda_min / lambda_max of a scaled normal matrix that is solved
};

struct MlsFit {
  double f = 0, df = 0, d2f = 0;  ///< f [f], f' [f/length], f'' [f/length^2] at xbar
  int order = -1;                 ///< 2 quadratic, 1 linear fallback, 0 constant fallback, -1 failed (see the guard)
  int used = 0;                   ///< points with nonzero weight
};

/// Approximations of f, f', f'' at xbar from points x[0..m) with values f[0..m), weights exp(-alpha
/// (d/h)^2) for |d| <= h (d = x_j - xbar), zero otherwise or on the excluded side (seed 002 eqs. 7-12,
/// Program 1). x and f must have the same length (the shorter one bounds m).
MlsFit mls_fit(double xbar, std::span<const double> x, std::span<const double> f, const MlsOptions& opt);

}  // namespace sph::fpm
