#include "gravity/direct_sum.h"

#include <algorithm>

namespace sph::gravity {

void direct_sum(const Sources& s, const PairLaw& law, double G, Result& out) {
  const std::size_t n = s.n;
  const std::uint8_t* active = out.begin(s) ? s.active : nullptr;
  std::size_t sinks = 0;
  for (std::size_t i = 0; i < n; ++i) sinks += active && !active[i] ? 0 : 1;
  const auto &x = s.x[0], &y = s.x[1], &z = s.x[2];
#pragma omp parallel for schedule(dynamic, 16) if (n >= 512)  // O(N) work per particle: a team pays off early
  for (std::size_t i = 0; i < n; ++i) {
    if (active && !active[i]) continue;  // not a sink: its results are kept from before
    double ax = 0.0, ay = 0.0, az = 0.0, phi = 0.0, re2_min = 1e300, msum_max = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      double f, p;
      law(r2, s.h[i], s.h[j], f, p);
      const double mf = s.m[j] * f;
      ax -= mf * dx;
      ay -= mf * dy;
      az -= mf * dz;
      phi += s.m[j] * p;
      re2_min = std::min(re2_min, r2 + law.soft2(s.h[i], s.h[j]));
      msum_max = std::max(msum_max, s.m[j]);
    }
    out.a[0][i] = G * ax;
    out.a[1][i] = G * ay;
    out.a[2][i] = G * az;
    out.phi[i] = G * phi;
    // a lower bound of min_j r_eff^3 / (G (m_i + m_j)) without a division per pair
    out.t2_pair[i] = msum_max > 0.0 ? re2_min * std::sqrt(re2_min) / (G * (s.m[i] + msum_max)) : 1e300;
  }
  out.pair_terms = sinks * (n - 1);
}

}  // namespace sph::gravity
