// The interacting neighbours of one particle, compacted before the pair loop (issue 14): a list built
// with a skin holds about 1.7 candidates per interacting pair, and testing them inside the force loop
// costs a mispredicted branch each. Here every candidate is written and kept or not by its test.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "sph/particles.h"

namespace sph {

/// The j of `nb` with 0 < |r_ij| < support max(h_i, h_j), without wall particles when skip_walls, into
/// out[0..count) in list order; returns count. `out` grows as needed.
inline std::size_t interacting(const Particles& p, const double* h, std::size_t i, std::span<const std::uint32_t> nb,
                               double support, bool skip_walls, std::vector<std::uint32_t>& out) {
  if (out.size() < nb.size()) out.resize(nb.size());
  const double* x = p.x[0].data();
  const double* y = p.x[1].data();
  const double* z = p.x[2].data();
  const std::uint8_t* kind = p.kind.data();
  const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
  std::uint32_t* buf = out.data();
  std::size_t n = 0;
  for (const std::uint32_t j : nb) {
    const double dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
    const double r2 = dx * dx + dy * dy + dz * dz;
    const double R = support * std::max(hi, h[j]);
    const bool keep = (r2 < R * R) & (r2 > 0.0) & !(skip_walls & (kind[j] != 0));
    buf[n] = j;
    n += keep ? 1 : 0;
  }
  return n;
}

}  // namespace sph
