#include "io/swift_softening.h"

#include <cmath>
#include <vector>

namespace sph {
namespace {

/// -phi r_0 of SWIFT's softened law for one pair at r [length], H = 3 eps_S: the Wendland C2 potential
/// kernel (3u^7 - 15u^6 + 28u^5 - 21u^4 + 7u^2 - 3) / H inside H, -1/r beyond.
double swift_phi(double r, double H) {
  if (r >= H) return -1.0 / r;
  const double u = r / H, u2 = u * u, u4 = u2 * u2;
  return (3.0 * u4 * u2 * u - 15.0 * u4 * u2 + 28.0 * u4 * u - 21.0 * u4 + 7.0 * u2 - 3.0) / H;
}

/// sum over pairs of m_i m_j phi(r_ij) for SWIFT's law (H > 0) or Plummer's (H = 0, eps2 used): rows in
/// parallel, then summed in order, so the result (and the exported eps) is the same for any thread count.
double pair_sum(const Particles& p, std::size_t n, double H, double eps2) {
  const auto& m = p[Field::Mass];
  std::vector<double> rows(n, 0.0);
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 xi = p.pos(i);
    double row = 0.0;
    for (std::size_t j = i + 1; j < n; ++j) {
      const double r2 = (p.pos(j) - xi).norm2();
      row += m[j] * (H > 0.0 ? swift_phi(std::sqrt(r2), H) : -1.0 / std::sqrt(r2 + eps2));
    }
    rows[i] = m[i] * row;
  }
  double sum = 0.0;
  for (double r : rows) sum += r;
  return sum;
}

}  // namespace

double swift_softening_matching_plummer(const Particles& p, std::size_t n, double eps) {
  if (n > kSoftMatchMaxN || !(eps > 0.0)) return 0.0;
  const double target = pair_sum(p, n, 0.0, eps * eps);
  // SWIFT's sum rises (less bound) with eps_S; at eps_S = eps it is below Plummer's (less softened)
  double lo = eps, hi = 2.0 * eps;
  for (int k = 0; k < 8 && pair_sum(p, n, 3.0 * hi, 0.0) < target; ++k) lo = hi, hi *= 2.0;
  for (int k = 0; k < 30; ++k) {  // bisection to 2^-30 of the bracket
    const double mid = 0.5 * (lo + hi);
    (pair_sum(p, n, 3.0 * mid, 0.0) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace sph
