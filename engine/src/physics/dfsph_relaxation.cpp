// The Jacobi relaxation of DFSPH's sweeps from the lattice's Fourier symbol (physics/dfsph_relaxation.h).
#include "physics/dfsph_relaxation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace sph {

double dfsph_lattice_stiffness(const Kernel& K, double eta) {
  const int dim = K.dim();
  const double R = K.support() * eta;  // in lattice spacings
  const int m = static_cast<int>(std::ceil(R));
  struct Pair {
    double d[3], f;  ///< offset x_a - x_b and dW/dr / r (the mass and rho0 cancel in lambda)
  };
  std::vector<Pair> pairs;
  double norm = 0.0;  // sum_b |g_ab|^2
  const int my = dim >= 2 ? m : 0, mz = dim == 3 ? m : 0;
  for (int i = -m; i <= m; ++i)
    for (int j = -my; j <= my; ++j)
      for (int l = -mz; l <= mz; ++l) {
        const double r = std::sqrt(static_cast<double>(i * i + j * j + l * l));
        if (r == 0.0 || r >= R) continue;
        const double f = K.dWdr(r, eta) / r;
        pairs.push_back({{double(i), double(j), double(l)}, f});
        norm += f * f * r * r;
      }
  if (norm <= 0.0) return 0.0;
  // lambda(k) is even in each component of k (the lattice's mirror symmetry): [0, pi]^d suffices, on a
  // grid fine enough for the smooth maximum (pi/24 in 3D, pi/96 below: within 0.2% of grids 2 and 4 times
  // finer for the six kernels at h = 1 ... 2 dx)
  const int nk = dim == 3 ? 24 : 96;
  const int ny = dim >= 2 ? nk : 0, nz = dim == 3 ? nk : 0;
  double best = 0.0;
  for (int a = 0; a <= nk; ++a)
    for (int b = 0; b <= ny; ++b)
      for (int c = 0; c <= nz; ++c) {
        const double k[3] = {std::numbers::pi * a / nk, std::numbers::pi * b / nk, std::numbers::pi * c / nk};
        double G[3] = {0.0, 0.0, 0.0};
        for (const Pair& p : pairs) {
          const double s = p.f * std::sin(k[0] * p.d[0] + k[1] * p.d[1] + k[2] * p.d[2]);
          for (int q = 0; q < 3; ++q) G[q] += s * p.d[q];
        }
        best = std::max(best, (G[0] * G[0] + G[1] * G[1] + G[2] * G[2]) / norm);
      }
  return best;
}

double dfsph_relaxation(const Kernel& K, double eta) {
  const double cap = K.dim() == 3 ? 0.3 : 0.5;
  const double lambda = dfsph_lattice_stiffness(K, eta);
  return lambda > 0.0 ? std::min(cap, 1.5 / lambda) : cap;
}

}  // namespace sph
