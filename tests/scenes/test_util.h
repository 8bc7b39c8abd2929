// Helpers for the scene tests: run a configured world to a time, sample particles.
#pragma once
#include <string>
#include <vector>

#include "sph/world.h"

namespace sph::test {

/// Mean of f over real particles with lo < x < hi (1D scenes).
template <class F>
double mean_over(const World& w, double lo, double hi, F&& f, std::size_t* count = nullptr) {
  const Particles& p = w.particles();
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[0][i];
    if (x <= lo || x >= hi) continue;
    sum += f(i);
    ++n;
  }
  if (count) *count = n;
  return n ? sum / n : 0.0;
}

/// FNV-1a hash of the bytes of the particle state (positions, velocities, u, rho, h).
inline std::uint64_t state_hash(const Particles& p) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const std::vector<double>& a) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto* b = reinterpret_cast<const unsigned char*>(&a[i]);
      for (int k = 0; k < 8; ++k) { h ^= b[k]; h *= 1099511628211ull; }
    }
  };
  for (int k = 0; k < p.dim(); ++k) { mix(p.x[k]); mix(p.v[k]); }
  for (Field f : {Field::Energy, Field::Density, Field::H})
    if (p.has(f)) mix(p[f]);
  return h;
}

}  // namespace sph::test
