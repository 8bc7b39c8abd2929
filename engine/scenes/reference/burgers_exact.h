// Exact solutions of Burgers' equation u_t + u u_x = eps u_xx (dimensionless: u a velocity, x a length,
// t a time) from the ramp data of seed 002 eq. 6c,
//   u0(x) = 1 (x <= 0),  1 - x/a (0 < x < a),  0 (x >= a),   a >= 0 (a = 0 is the step),
// and the seed's discrete L1 error (§4.3): the references of the FPM Burgers runs of seed 002 §4.
#pragma once
#include <functional>
#include <span>

namespace sph::scenes {

/// The ramp initial data u0 (seed 002 eq. 6c).
double burgers_initial(double x, double a);

/// Inviscid (entropy) solution: seed 002 eq. 22 for t < a; for t >= a the shock that forms at (x, t) = (a, a)
/// moves at the Rankine-Hugoniot speed 1/2 (u = 1 behind, 0 ahead, 1/2 exactly on it), x_s = a + (t - a)/2.
/// t <= 0 returns u0.
double burgers_inviscid(double x, double t, double a);

/// Viscous solution of u_t + u u_x = eps u_xx from the same data (Cole-Hopf transform):
///   u(x, t) = int ((x - y)/t) G(y) dy / int G(y) dy,  G = exp(-(E(y) - E_min) / (2 eps)),
///   E(y) = (x - y)^2 / (2 t) + U0(y),  U0(y) = int_0^y u0,
/// with E piecewise quadratic in y (pieces y < 0, 0 < y < a, y > a). Each piece's minimum is found in
/// closed form, E_min is the least of them (two pieces tie on the shock after it forms), and each piece is
/// integrated over the window where E - E_min <= 100 eps (G >= e^-50) by composite 20-point Gauss-Legendre
/// on sub-intervals across which the exponent changes by at most 8 (~3.5 us a call): absolute accuracy
/// ~1e-13 for eps >= 1e-4 (5e-15 against the erfc closed form of the step a = 0; a window of e^-80 and
/// sub-intervals of change 1 move u by < 4e-14). t <= 0 returns u0; eps <= 0 the inviscid solution.
double burgers_viscous(double x, double t, double a, double eps);

/// The seed's error e(h) = h_max * sum_i |u_i - u_exact(x_i)|, h_max = max_i |x_i - x_{i-1}| over the sorted
/// points (seed 002 §4.3). x and u have the same length (std::invalid_argument otherwise); fewer than two
/// points give 0.
double seed_error(std::span<const double> x, std::span<const double> u, const std::function<double(double)>& exact);

}  // namespace sph::scenes
