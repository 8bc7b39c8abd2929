// Moving least squares in 1D (see fpm/mls.h; seed 002 eqs. 7-12, Program 1). Two passes over the
// points: the nearest admitted point (its value f_n is subtracted, Program 1's fmin), then the weighted
// moments sum w s^k (k = 0..4) and sum w s^k (f_j - f_n) (k = 0..2) in s = d/h, from which the
// quadratic, linear and constant normal equations are all assembled.
#include "fpm/mls.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace sph::fpm {
namespace {

bool admitted(double d, double h, Side side) {
  if (!(std::abs(d) <= h)) return false;  // also rejects NaN
  switch (side) {
    case Side::Left: return d <= 0.0;
    case Side::Right: return d >= 0.0;
    default: return true;
  }
}

// lambda_min / lambda_max of a symmetric matrix (closed-form eigenvalues; 0 if not positive definite)
template <int N>
double rcond(const Eigen::Matrix<double, N, N>& A) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es;
  es.computeDirect(A, Eigen::EigenvaluesOnly);
  const auto& ev = es.eigenvalues();  // ascending
  const double r = ev[N - 1] > 0.0 ? ev[0] / ev[N - 1] : 0.0;
  return std::isfinite(r) ? r : 0.0;
}

/// Pass 1: the nearest admitted point (the first one on ties); it has the largest weight. m if none.
std::size_t nearest_admitted(double xbar, std::span<const double> x, std::size_t m, const MlsOptions& opt) {
  std::size_t nearest = m;
  double dmin = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const double d = x[j] - xbar;
    if (!admitted(d, opt.h, opt.side)) continue;
    if (nearest == m || std::abs(d) < dmin) {
      nearest = j;
      dmin = std::abs(d);
    }
  }
  return nearest;
}

/// The weighted moments sum w s^k (k = 0..4) and sum w s^k (f_j - f_n) (k = 0..2), the points with
/// nonzero weight and how many distinct positions they have (counted up to 3).
struct Moments {
  double m0 = 0, m1 = 0, m2 = 0, m3 = 0, m4 = 0, r0 = 0, r1 = 0, r2 = 0;
  int used = 0, distinct = 0;
};

/// Pass 2: the moments in s = d/h (seed 002 eq. 9 weights), data shifted by fn.
Moments moments(double xbar, std::span<const double> x, std::span<const double> f, std::size_t m, double fn,
                const MlsOptions& opt) {
  const double h = opt.h, alpha = opt.alpha;
  Moments o;
  double s_a = 0.0, s_b = 0.0;  // the first two distinct positions seen
  for (std::size_t j = 0; j < m; ++j) {
    const double d = x[j] - xbar;
    if (!admitted(d, h, opt.side)) continue;
    const double s = d / h, s2 = s * s;
    const double w = std::exp(-alpha * s2);
    if (!(w > 0.0)) continue;
    ++o.used;
    if (o.distinct == 0) {
      s_a = s;
      o.distinct = 1;
    } else if (o.distinct == 1 && s != s_a) {
      s_b = s;
      o.distinct = 2;
    } else if (o.distinct == 2 && s != s_a && s != s_b) {
      o.distinct = 3;
    }
    const double g = f[j] - fn, ws = w * s, ws2 = w * s2;
    o.m0 += w;
    o.m1 += ws;
    o.m2 += ws2;
    o.m3 += ws2 * s;
    o.m4 += ws2 * s2;
    o.r0 += w * g;
    o.r1 += ws * g;
    o.r2 += ws2 * g;
  }
  return o;
}

/// The quadratic fit, basis (1, s, s^2/2) (seed 002 eq. 10 in scaled form), into out if its normal
/// matrix passes the rcond test and the solution is finite.
bool fit_quadratic(const Moments& o, double fn, const MlsOptions& opt, MlsFit& out) {
  const double h = opt.h;
  Eigen::Matrix3d A;
  A << o.m0, o.m1, 0.5 * o.m2,  //
      o.m1, o.m2, 0.5 * o.m3,   //
      0.5 * o.m2, 0.5 * o.m3, 0.25 * o.m4;
  const Eigen::Vector3d b(o.r0, o.r1, 0.5 * o.r2);
  if (!(rcond<3>(A) >= opt.min_rcond)) return false;
  const Eigen::Vector3d c = A.ldlt().solve(b);
  if (!c.allFinite()) return false;
  out.f = fn + c[0];
  out.df = c[1] / h;
  out.d2f = c[2] / (h * h);
  out.order = 2;
  return true;
}

/// The linear fallback, basis (1, s), under the same conditions.
bool fit_linear(const Moments& o, double fn, const MlsOptions& opt, MlsFit& out) {
  Eigen::Matrix2d A;
  A << o.m0, o.m1, o.m1, o.m2;
  const Eigen::Vector2d b(o.r0, o.r1);
  if (!(rcond<2>(A) >= opt.min_rcond)) return false;
  const Eigen::Vector2d c = A.ldlt().solve(b);
  if (!c.allFinite()) return false;
  out.f = fn + c[0];
  out.df = c[1] / opt.h;
  out.order = 1;
  return true;
}

}  // namespace

MlsFit mls_fit(double xbar, std::span<const double> x, std::span<const double> f, const MlsOptions& opt) {
  MlsFit out;
  const double h = opt.h, alpha = opt.alpha;
  if (!(h > 0.0) || !std::isfinite(h) || !(alpha >= 0.0)) return out;
  const std::size_t m = std::min(x.size(), f.size());
  const std::size_t nearest = nearest_admitted(xbar, x, m, opt);
  if (nearest == m) return out;
  const double fn = f[nearest];
  const Moments o = moments(xbar, x, f, m, fn, opt);
  out.used = o.used;
  if (o.used == 0) return out;
  if (o.distinct >= 3 && fit_quadratic(o, fn, opt, out)) return out;
  if (o.distinct >= 2 && fit_linear(o, fn, opt, out)) return out;
  out.f = fn + o.r0 / o.m0;  // constant fallback: the weighted mean
  out.order = 0;
  return out;
}

}  // namespace sph::fpm
