// The Cartesian expansions of the fast multipole method: Taylor coefficients against their closed forms
// and finite differences, the shifts (M2M, L2L) against direct moments and the unshifted expansion, the
// far field converging with the order as (size / distance)^P, and the four-lane M2L equal to four single
// ones.
#include "gravity/expansion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gravity_test_util.h"

namespace sph::gravity {
namespace {

struct Cluster {
  std::vector<std::array<double, 3>> x;
  std::vector<double> m;
  std::array<double, 3> com{};
};

/// n masses in a cube of half-side `half` about c, their centre of mass set.
Cluster cluster(int n, double half, std::array<double, 3> c, std::uint64_t seed) {
  test::Uniform u{seed};
  Cluster k;
  double M = 0.0;
  for (int i = 0; i < n; ++i) {
    k.x.push_back({c[0] + half * (2 * u() - 1), c[1] + half * (2 * u() - 1), c[2] + half * (2 * u() - 1)});
    k.m.push_back(0.5 + u());
    M += k.m.back();
    for (int d = 0; d < 3; ++d) k.com[d] += k.m.back() * k.x.back()[d];
  }
  for (int d = 0; d < 3; ++d) k.com[d] /= M;
  return k;
}

std::vector<double> moments(const Expansion& ex, const Cluster& k, const std::array<double, 3>& z) {
  std::vector<double> M(ex.size(), 0.0);
  for (std::size_t i = 0; i < k.m.size(); ++i) ex.p2m(k.m[i], k.x[i][0] - z[0], k.x[i][1] - z[1], k.x[i][2] - z[2], M.data());
  return M;
}

/// Direct potential and acceleration at p (per unit G, softened by e2).
std::array<double, 4> direct(const Cluster& k, const std::array<double, 3>& p, double e2) {
  std::array<double, 4> f{};
  for (std::size_t i = 0; i < k.m.size(); ++i) {
    const double d[3] = {p[0] - k.x[i][0], p[1] - k.x[i][1], p[2] - k.x[i][2]};
    const double inv = 1.0 / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + e2);
    f[0] -= k.m[i] * inv;
    for (int c = 0; c < 3; ++c) f[1 + c] -= k.m[i] * inv * inv * inv * d[c];
  }
  return f;
}

TEST(Expansion, CoefficientsMatchTheirClosedFormsAndFiniteDifferences) {
  const auto ex = make_expansion(4);
  const double x = 0.7, y = -0.4, z = 0.3, e2 = 0.01, s = x * x + y * y + z * z + e2;
  std::vector<double> a(ex->size());
  ex->coefficients(x, y, z, e2, a.data());
  EXPECT_NEAR(a[0], 1.0 / std::sqrt(s), 1e-15);
  EXPECT_NEAR(a[1], -x / std::pow(s, 1.5), 1e-14);                       // a_(1,0,0) = dg/dx
  EXPECT_NEAR(a[4], (3 * x * x - s) / (2 * std::pow(s, 2.5)), 1e-14);    // a_(2,0,0) = g_xx / 2
  EXPECT_NEAR(a[5], 3 * x * y / std::pow(s, 2.5), 1e-14);                // a_(1,1,0) = g_xy
  // every coefficient of order n+1 by a central difference of the order-n ones: a_(k+e_x) (k_x + 1) = d a_k/dx
  const double d = 1e-5;
  std::vector<double> ap(ex->size()), am(ex->size());
  ex->coefficients(x + d, y, z, e2, ap.data());
  ex->coefficients(x - d, y, z, e2, am.data());
  const int up_x[10] = {1, 4, 5, 6, 10, 11, 12, 13, 14, 15};  // (0,0,0)->(1,0,0), (1,0,0)->(2,0,0), ...
  const int from[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};       // the degree <= 2 ones, in table order
  const int kx[10] = {0, 1, 0, 0, 2, 1, 1, 0, 0, 0};
  for (int q = 0; q < 10; ++q) {
    const double fd = (ap[from[q]] - am[from[q]]) / (2 * d);
    EXPECT_NEAR(a[up_x[q]] * (kx[q] + 1), fd, 1e-7 * (1 + std::abs(fd))) << "coefficient " << up_x[q];
  }
}

TEST(Expansion, ShiftedMultipolesAreTheMomentsAboutTheNewCentre) {
  const auto ex = make_expansion(5);
  const Cluster k = cluster(30, 0.1, {0.2, -0.1, 0.05}, 3);
  const std::array<double, 3> z1 = k.com, z2 = {0.25, -0.2, 0.1};
  const std::vector<double> M1 = moments(*ex, k, z1), M2 = moments(*ex, k, z2);
  std::vector<double> shifted(ex->size(), 0.0);
  ex->m2m(M1.data(), z1[0] - z2[0], z1[1] - z2[1], z1[2] - z2[2], shifted.data());
  for (std::size_t c = 0; c < ex->size(); ++c) EXPECT_NEAR(shifted[c], M2[c], 1e-13 * (1 + std::abs(M2[c])));
}

TEST(Expansion, TheFarFieldConvergesWithTheOrderAndTheShiftsKeepIt) {
  const Cluster k = cluster(40, 0.1, {0, 0, 0}, 5);
  const std::array<double, 3> zb = {0.8, 0.45, -0.3}, y = {0.04, -0.05, 0.03}, p = {zb[0] + y[0], zb[1] + y[1], zb[2] + y[2]};
  const double e2 = 1e-4;
  const auto exact = direct(k, p, e2);
  double last = 1e300;
  for (int P = 1; P <= Expansion::kMaxOrder; ++P) {
    const auto ex = make_expansion(P);
    const std::vector<double> M = moments(*ex, k, k.com);
    // M2L into a parent centre zb, L2L to a child centre zb + t, L2P at the particle
    std::vector<double> Lp(ex->size(), 0.0), Lc(ex->size(), 0.0);
    ex->m2l(M.data(), zb[0] - k.com[0], zb[1] - k.com[1], zb[2] - k.com[2], e2, Lp.data());
    const std::array<double, 3> t = {0.02, -0.03, 0.01};
    ex->l2l(Lp.data(), t[0], t[1], t[2], Lc.data());
    double f1[4] = {}, f2[4] = {};
    ex->l2p(Lp.data(), y[0], y[1], y[2], f1[0], f1[1], f1[2], f1[3]);
    ex->l2p(Lc.data(), y[0] - t[0], y[1] - t[1], y[2] - t[2], f2[0], f2[1], f2[2], f2[3]);
    double err = 0.0, scale = 0.0;
    for (int c = 1; c < 4; ++c) {
      err += (f1[c] - exact[c]) * (f1[c] - exact[c]);
      scale += exact[c] * exact[c];
      EXPECT_NEAR(f2[c], f1[c], 1e-12 * std::abs(exact[c]) + 1e-13) << "L2L changes the field, P = " << P;
    }
    err = std::sqrt(err / scale);
    // the pair's size ratio (r_A + r_B)/R is about 0.25: each order gains a factor of about 4
    if (P >= 3) {
      EXPECT_LT(err, 0.5 * last) << "P = " << P;
    }
    last = err;
  }
  EXPECT_LT(last, 1e-4);
}

TEST(Expansion, FourLaneM2LIsTheSumOfFourSingleOnes) {
  for (int P : {2, 5}) {
    const auto ex = make_expansion(P);
    std::vector<std::vector<double>> M;
    double R[4][3];
    for (int v = 0; v < 4; ++v) {
      const Cluster k = cluster(10, 0.1, {0, 0, 0}, 11 + v);
      M.push_back(moments(*ex, k, k.com));
      R[v][0] = 0.9 + 0.1 * v;
      R[v][1] = 0.3 - 0.2 * v;
      R[v][2] = 0.1 * v;
    }
    const double* Ms[4] = {M[0].data(), M[1].data(), M[2].data(), M[3].data()};
    std::vector<double> L4(ex->size(), 0.0), L1(ex->size(), 0.0);
    ex->m2l4(Ms, R, 0.0, L4.data());
    for (int v = 0; v < 4; ++v) ex->m2l(M[v].data(), R[v][0], R[v][1], R[v][2], 0.0, L1.data());
    for (std::size_t c = 0; c < ex->size(); ++c) EXPECT_NEAR(L4[c], L1[c], 1e-13 * std::abs(L1[c]) + 1e-300);
  }
  EXPECT_THROW(make_expansion(Expansion::kMaxOrder + 1), std::invalid_argument);
}

TEST(Expansion, FourLaneM2PHasTheBitsOfFourSingleOnes) {
  for (int P = Expansion::kMinOrder; P <= Expansion::kMaxOrder; ++P) {
    const auto ex = make_expansion(P);
    const Cluster k = cluster(10, 0.1, {0, 0, 0}, 5);
    const std::vector<double> M = moments(*ex, k, k.com);
    double R[4][3], phi4[4] = {0.5, 0.5, 0.5, 0.5}, a4[3][4] = {}, phi1[4] = {0.5, 0.5, 0.5, 0.5}, a1[3][4] = {};
    for (int v = 0; v < 4; ++v) {
      R[v][0] = 0.9 + 0.1 * v;
      R[v][1] = 0.3 - 0.2 * v;
      R[v][2] = 0.1 * v - 0.05;
      ex->m2p(M.data(), R[v][0], R[v][1], R[v][2], 1e-4, phi1[v], a1[0][v], a1[1][v], a1[2][v]);
    }
    ex->m2p4(M.data(), R, 1e-4, phi4, a4[0], a4[1], a4[2]);
    for (int v = 0; v < 4; ++v) {
      EXPECT_EQ(0, std::memcmp(&phi4[v], &phi1[v], sizeof(double))) << "P = " << P << ", lane " << v;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(0, std::memcmp(&a4[c][v], &a1[c][v], sizeof(double))) << "P = " << P;
    }
    EXPECT_NE(phi1[0], 0.5);
  }
}

}  // namespace
}  // namespace sph::gravity
