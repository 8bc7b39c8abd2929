// What the gravity benchmarks share: a wall-clock timer and direct-summation accelerations of sample
// targets (Plummer softening), the reference their force errors are measured against.
#pragma once
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "sph/particles.h"

namespace sph::bench {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Direct accelerations of the sample targets only.
inline std::vector<std::array<double, 3>> direct_at(const Particles& p, const std::vector<std::size_t>& targets, double eps2) {
  std::vector<std::array<double, 3>> a(targets.size());
  const auto& m = p[Field::Mass];
#pragma omp parallel for schedule(dynamic, 8)
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const std::size_t i = targets[t];
    double ax = 0, ay = 0, az = 0;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const double dx = p.x[0][i] - p.x[0][j], dy = p.x[1][i] - p.x[1][j], dz = p.x[2][i] - p.x[2][j];
      const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz + eps2), f = m[j] * inv * inv * inv;
      ax -= f * dx; ay -= f * dy; az -= f * dz;
    }
    a[t] = {ax, ay, az};
  }
  return a;
}


}  // namespace sph::bench
