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

}  // namespace

MlsFit mls_fit(double xbar, std::span<const double> x, std::span<const double> f, const MlsOptions& opt) {
  MlsFit out;
  const double h = opt.h, alpha = opt.alpha;
  if (!(h > 0.0) || !std::isfinite(h) || !(alpha >= 0.0)) return out;
  const std::size_t m = std::min(x.size(), f.size());

  // pass 1: the nearest admitted point (the first one on ties); it has the largest weight
  std::size_t nearest = m;
  double dmin = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const double d = x[j] - xbar;
    if (!admitted(d, h, opt.side)) continue;
    if (nearest == m || std::abs(d) < dmin) {
      nearest = j;
      dmin = std::abs(d);
    }
  }
  if (nearest == m) return out;
  const double fn = f[nearest];

  // pass 2: weighted moments in s = d/h (seed 002 eq. 9 weights), data shifted by fn
  double m0 = 0, m1 = 0, m2 = 0, m3 = 0, m4 = 0, r0 = 0, r1 = 0, r2 = 0;
  int used = 0, distinct = 0;
  double s_a = 0.0, s_b = 0.0;  // the first two distinct positions seen
  for (std::size_t j = 0; j < m; ++j) {
    const double d = x[j] - xbar;
    if (!admitted(d, h, opt.side)) continue;
    const double s = d / h, s2 = s * s;
    const double w = std::exp(-alpha * s2);
    if (!(w > 0.0)) continue;
    ++used;
    if (distinct == 0) {
      s_a = s;
      distinct = 1;
    } else if (distinct == 1 && s != s_a) {
      s_b = s;
      distinct = 2;
    } else if (distinct == 2 && s != s_a && s != s_b) {
      distinct = 3;
    }
    const double g = f[j] - fn, ws = w * s, ws2 = w * s2;
    m0 += w;
    m1 += ws;
    m2 += ws2;
    m3 += ws2 * s;
    m4 += ws2 * s2;
    r0 += w * g;
    r1 += ws * g;
    r2 += ws2 * g;
  }
  out.used = used;
  if (used == 0) return out;

  if (distinct >= 3) {  // quadratic: basis (1, s, s^2/2), seed 002 eq. 10 in scaled form
    Eigen::Matrix3d A;
    A << m0, m1, 0.5 * m2,  //
        m1, m2, 0.5 * m3,   //
        0.5 * m2, 0.5 * m3, 0.25 * m4;
    const Eigen::Vector3d b(r0, r1, 0.5 * r2);
    if (rcond<3>(A) >= opt.min_rcond) {
      const Eigen::Vector3d c = A.ldlt().solve(b);
      if (c.allFinite()) {
        out.f = fn + c[0];
        out.df = c[1] / h;
        out.d2f = c[2] / (h * h);
        out.order = 2;
        return out;
      }
    }
  }
  if (distinct >= 2) {  // linear fallback: basis (1, s)
    Eigen::Matrix2d A;
    A << m0, m1, m1, m2;
    const Eigen::Vector2d b(r0, r1);
    if (rcond<2>(A) >= opt.min_rcond) {
      const Eigen::Vector2d c = A.ldlt().solve(b);
      if (c.allFinite()) {
        out.f = fn + c[0];
        out.df = c[1] / h;
        out.order = 1;
        return out;
      }
    }
  }
  out.f = fn + r0 / m0;  // constant fallback: the weighted mean
  out.order = 0;
  return out;
}

}  // namespace sph::fpm
