// Safeguarded Newton-Raphson for a scalar root (seed 000 App. B, eq. B.0.3: x_{k+1} = x_k - f/f').
// Used by the smoothing-length solve (seed 000 eq. 3.5.1). Header-only so it inlines into hot loops.
#pragma once
#include <cmath>

namespace sph {

struct NewtonResult {
  double x = 0.0;          ///< last accepted iterate (f was evaluated here)
  int iterations = 0;      ///< evaluations of f
  int bisections = 0;      ///< Newton steps replaced by bisection or bracket growth
  bool converged = false;  ///< |x_{k+1} - x_k| <= tol |x_k|
  bool hit_upper = false;  ///< the root lies above `upper_limit` (no sign change below it)
};

/// Finds a root of an increasing-through-the-root function f near x0 > 0. fn(x, f, df) evaluates f and
/// f'. Newton steps are accepted while they stay inside the known bracket and within [x/2, 2x];
/// otherwise the bracket is bisected, or grown towards upper_limit while no upper bound is known.
/// `on_eval(x)` is called for every evaluation (e.g. to record the sequence).
template <class Fn>
NewtonResult newton_bracketed(Fn&& fn, double x0, double upper_limit, double tol, int max_iter) {
  NewtonResult r;
  double x = x0, lo = 0.0, hi = upper_limit;
  bool have_hi = false;
  double evaluated = x0;
  while (r.iterations < max_iter) {
    double f = 0.0, df = 0.0;
    fn(x, f, df);
    evaluated = x;
    ++r.iterations;
    if (f == 0.0) { r.x = x; r.converged = true; return r; }
    if (f < 0.0) lo = x; else { hi = x; have_hi = true; }
    double xn = df > 0.0 ? x - f / df : -1.0;
    const double top = have_hi ? hi : upper_limit;
    const bool newton_ok = xn >= lo && xn <= top && xn <= 2.0 * x && xn >= 0.5 * x;
    if (!newton_ok) {
      if (!have_hi && x >= upper_limit * (1.0 - 1e-12)) { r.x = upper_limit; r.hit_upper = true; return r; }
      // bisect the bracket; with no upper bound yet, try the upper limit itself
      xn = have_hi ? 0.5 * (lo + hi) : std::fmin(2.0 * x, upper_limit);
      ++r.bisections;
    }
    if (std::fabs(xn - x) <= tol * std::fabs(x)) { r.x = x; r.converged = true; return r; }
    x = xn;
  }
  r.x = evaluated;  // not converged: the last point f was evaluated at
  return r;
}

/// Plain Newton-Raphson iteration x_{k+1} = x_k - f(x_k)/f'(x_k) (seed 000 eq. B.0.3), recording
/// each iterate in out[0..n). Returns the number of iterates written.
template <class F, class DF>
int newton_sequence(F&& f, DF&& df, double x0, double* out, int n) {
  double x = x0;
  for (int k = 0; k < n; ++k) {
    out[k] = x;
    x = x - f(x) / df(x);
  }
  return n;
}

}  // namespace sph
