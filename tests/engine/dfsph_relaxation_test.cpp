// physics/dfsph_relaxation.h: the largest amplification of DFSPH's Jacobi sweeps on a lattice, from the
// Fourier symbol, against the eigenvalues of the same operator assembled particle by particle on a
// periodic lattice; and the relaxation it gives (the tuned 0.5 and 0.3 at the scenes' M4, h = 1.3 dx).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "physics/dfsph_relaxation.h"

namespace sph {
namespace {

/// lambda_max of D^-1 A on an n x n periodic lattice (spacing 1) in 2D, A x = the change of the sources
/// for a pressure change x (dv_a = -sum_b (x_a + x_b) g_ab, then sum_b (dv_a - dv_b) . g_ab, rho = m = 1,
/// dt = 1), D = sum_b |g_ab|^2 (DFSPH's alpha^-1): the matrix built one unit pressure at a time.
double brute_force(const Kernel& K, double eta, int n) {
  const double R = K.support() * eta;
  const int m = static_cast<int>(std::ceil(R));
  struct Nb {
    int di, dj;
    double gx, gy;
  };
  std::vector<Nb> nb;  // offsets x_a - x_b and g_ab (the same for every a)
  double D = 0.0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j) {
      const double r = std::hypot(i, j);
      if (r == 0.0 || r >= R) continue;
      const double f = K.dWdr(r, eta) / r;
      nb.push_back({i, j, f * i, f * j});
      D += f * f * r * r;
    }
  const int N = n * n;
  auto at = [n](int i, int j) { return ((i % n + n) % n) * n + (j % n + n) % n; };
  Eigen::MatrixXd A(N, N);
  std::vector<double> x(N), vx(N), vy(N);
  for (int c = 0; c < N; ++c) {
    std::fill(x.begin(), x.end(), 0.0);
    x[c] = 1.0;
    for (int a = 0; a < N; ++a) {
      const int ai = a / n, aj = a % n;
      vx[a] = vy[a] = 0.0;
      for (const Nb& b : nb) {
        const double s = x[a] + x[at(ai - b.di, aj - b.dj)];
        vx[a] -= s * b.gx;
        vy[a] -= s * b.gy;
      }
    }
    for (int a = 0; a < N; ++a) {
      const int ai = a / n, aj = a % n;
      double y = 0.0;
      for (const Nb& b : nb) {
        const int o = at(ai - b.di, aj - b.dj);
        y += (vx[a] - vx[o]) * b.gx + (vy[a] - vy[o]) * b.gy;
      }
      A(a, c) = -y / D;  // a sweep removes w times this from the source: 1 - w lambda
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

TEST(DfsphRelaxation, TheSymbolIsTheLargestEigenvalueOfTheAssembledSweep) {
  // a 32 x 32 lattice has the wave numbers 2 pi k / 32: its largest eigenvalue is at most the symbol's
  // maximum over the whole zone, and within the symbol's variation between those wave numbers of it
  for (KernelType t : {KernelType::M4, KernelType::M6, KernelType::WendlandC4})
    for (double eta : {1.3, 2.0}) {
      const Kernel K(t, 2);
      const double symbol = dfsph_lattice_stiffness(K, eta), matrix = brute_force(K, eta, 32);
      EXPECT_LE(matrix, symbol * (1.0 + 1e-9)) << static_cast<int>(t) << " eta " << eta;
      EXPECT_GE(matrix, 0.99 * symbol) << static_cast<int>(t) << " eta " << eta;  // measured 0.996 or more
    }
}

TEST(DfsphRelaxation, WiderKernelsRelaxMoreAndTheDefaultsKeepTheTunedValues) {
  // M4 at h = 1.3 dx: 1.5 / lambda_max is 0.52 (2D) and 0.31 (3D), above the tuned 0.5 and 0.3
  EXPECT_NEAR(dfsph_lattice_stiffness(Kernel(KernelType::M4, 2), 1.3), 2.88, 0.01);
  EXPECT_NEAR(dfsph_lattice_stiffness(Kernel(KernelType::M4, 3), 1.3), 4.91, 0.02);
  EXPECT_EQ(dfsph_relaxation(Kernel(KernelType::M4, 2), 1.3), 0.5);
  EXPECT_EQ(dfsph_relaxation(Kernel(KernelType::M4, 3), 1.3), 0.3);
  // wider: the sweeps that diverged (w lambda_max beyond 2 at the old w) now take w lambda_max = 1.5
  for (int dim : {2, 3})
    for (KernelType t : {KernelType::M4, KernelType::M6, KernelType::Gaussian, KernelType::WendlandC2}) {
      const Kernel K(t, dim);
      const double w = dfsph_relaxation(K, 2.0), lambda = dfsph_lattice_stiffness(K, 2.0);
      EXPECT_GT(lambda * (dim == 3 ? 0.3 : 0.5), 2.0) << dim << "D kernel " << static_cast<int>(t);
      EXPECT_NEAR(w * lambda, 1.5, 1e-12);
    }
  // and the amplification grows with the kernel's reach
  const Kernel m4(KernelType::M4, 2);
  EXPECT_LT(dfsph_lattice_stiffness(m4, 1.2), dfsph_lattice_stiffness(m4, 1.5));
  EXPECT_LT(dfsph_lattice_stiffness(m4, 1.5), dfsph_lattice_stiffness(m4, 2.0));
}

}  // namespace
}  // namespace sph
