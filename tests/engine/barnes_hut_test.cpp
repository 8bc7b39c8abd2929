// The Barnes-Hut tree against direct summation (the required bounds: at theta = 0.5 the largest relative
// force error <= 1% and the RMS <= 0.1%; theta = 0 equals direct summation to round-off), the accuracy
// of the quadrupole far field, the structure of the tree, and bitwise identical results for 1 and 2
// threads. Direct summation conserves momentum to round-off (antisymmetric pair forces).
#include "gravity/barnes_hut.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

#include "gravity/direct_sum.h"
#include "gravity_test_util.h"

namespace sph::gravity {
namespace {

struct Errors {
  double max = 0.0, rms = 0.0, phi_max = 0.0;
};

Errors compare(const Result& a, const Result& b) {
  Errors e;
  const std::size_t n = a.phi.size();
  for (std::size_t i = 0; i < n; ++i) {
    double d2 = 0.0, b2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      d2 += (a.a[k][i] - b.a[k][i]) * (a.a[k][i] - b.a[k][i]);
      b2 += b.a[k][i] * b.a[k][i];
    }
    const double rel = std::sqrt(d2 / b2);
    e.max = std::max(e.max, rel);
    e.rms += rel * rel;
    e.phi_max = std::max(e.phi_max, std::abs(a.phi[i] / b.phi[i] - 1.0));
  }
  e.rms = std::sqrt(e.rms / static_cast<double>(n));
  return e;
}

PairLaw plummer(double eps) {
  PairLaw law;
  law.eps2 = eps * eps;
  return law;
}

struct Case {
  const char* name;
  bool plummer_sphere;
  double eps;
};

class TreeAgainstDirect : public ::testing::TestWithParam<Case> {};

TEST_P(TreeAgainstDirect, ThetaHalfWithinTheIssueBounds) {
  const Case c = GetParam();
  const Particles p = test::sphere(4000, c.plummer_sphere);
  const Sources s = Sources::of(p);
  Result direct, tree;
  direct_sum(s, plummer(c.eps), 1.0, direct);
  BarnesHutTree t;
  t.build(s);
  t.evaluate(s, plummer(c.eps), 1.0, 0.5, tree);
  const Errors e = compare(tree, direct);
  std::printf("%s, theta = 0.5: max %.3g, rms %.3g, potential %.3g; %zu cell and %zu pair terms\n", c.name, e.max,
              e.rms, e.phi_max, tree.node_terms, tree.pair_terms);
  EXPECT_LT(e.max, 0.01);
  EXPECT_LT(e.rms, 0.001);
  EXPECT_LT(tree.node_terms + tree.pair_terms, direct.pair_terms / 2);  // fewer terms already at N = 4000
}

TEST_P(TreeAgainstDirect, TheRelativeGuardBoundsTheErrorWhereTheFieldIsWeak) {
  // near the centre |a| -> 0: plain theta = 0.5 leaves a relative error there several times the guarded one
  const Case c = GetParam();
  const Particles p = test::sphere(4000, c.plummer_sphere);
  const Sources s = Sources::of(p);
  Result direct, plain, guarded;
  direct_sum(s, plummer(c.eps), 1.0, direct);
  BarnesHutTree t;
  t.build(s);
  t.evaluate(s, plummer(c.eps), 1.0, 0.5, plain, 0.0);
  t.evaluate(s, plummer(c.eps), 1.0, 0.5, guarded, 1e-3);
  const Errors ep = compare(plain, direct), eg = compare(guarded, direct);
  std::printf("%s, theta = 0.5: largest error %.3g plain, %.3g guarded\n", c.name, ep.max, eg.max);
  EXPECT_GT(ep.max, 3.0 * eg.max);
  EXPECT_GT(ep.max, 0.01);  // plain Barnes-Hut alone misses the required bound at this theta
}

TEST_P(TreeAgainstDirect, ThetaZeroIsDirectSummation) {
  const Case c = GetParam();
  const Particles p = test::sphere(1500, c.plummer_sphere);
  const Sources s = Sources::of(p);
  Result direct, tree;
  direct_sum(s, plummer(c.eps), 1.0, direct);
  BarnesHutTree t;
  t.build(s);
  t.evaluate(s, plummer(c.eps), 1.0, 0.0, tree);
  const Errors e = compare(tree, direct);
  EXPECT_LT(e.max, 1e-12);  // the same sums in another order
  EXPECT_LT(e.phi_max, 1e-12);
  EXPECT_EQ(tree.node_terms, 0u);
}

INSTANTIATE_TEST_SUITE_P(Spheres, TreeAgainstDirect,
                         ::testing::Values(Case{"Plummer sphere", true, 0.01}, Case{"Evrard sphere", false, 0.05}),
                         [](const auto& info) { return info.param.plummer_sphere ? "Plummer" : "Evrard"; });

TEST(BarnesHut, QuadrupoleFarFieldErrorFallsAsTheCubeOfSizeOverDistance) {
  // The field of one cell (a clump of radius 0.1) from its monopole and quadrupole against the direct sum
  // over its particles: the first term left out is the octupole, so the relative error falls as
  // (size/d)^3: by 8 when d doubles. Without the quadrupole it would fall as (size/d)^2 (by 4).
  Particles p = test::sphere(300, false, 3);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) p.x[k][i] = 0.1 * p.x[k][i] + (k == 0 ? 0.03 : 0.0);  // off-centre
  const Sources s = Sources::of(p);
  BarnesHutTree t;
  t.build(s, 1000);  // one leaf: the root holds every particle
  const TreeNode& root = t.nodes()[0];
  double err[3];
  for (int which = 0; which < 3; ++which) {
    const double d = 0.5 * std::pow(2.0, which);
    const double X[3] = {0.8 * d, 0.5 * d, -0.33 * d};
    double ax = 0, ay = 0, az = 0, phi = 0;
    multipole_field(root, X[0] - root.com[0], X[1] - root.com[1], X[2] - root.com[2], 0.0, ax, ay, az, phi);
    double b[3] = {0, 0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double r[3] = {X[0] - p.x[0][i], X[1] - p.x[1][i], X[2] - p.x[2][i]};
      const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
      for (int k = 0; k < 3; ++k) b[k] -= p[Field::Mass][i] * r[k] / (r2 * std::sqrt(r2));
    }
    err[which] = std::sqrt((ax - b[0]) * (ax - b[0]) + (ay - b[1]) * (ay - b[1]) + (az - b[2]) * (az - b[2])) /
                 std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  }
  std::printf("cell far field: relative error %.3g, %.3g, %.3g at d = 0.5, 1, 2\n", err[0], err[1], err[2]);
  EXPECT_NEAR(err[0] / err[1], 8.0, 1.5);
  EXPECT_NEAR(err[1] / err[2], 8.0, 1.0);
  EXPECT_LT(err[0], 1e-3);
}

TEST(BarnesHut, OneParticlesInteractionsSumToItsAccelerationAndCoverAllMassOnce) {
  // the overlay's cells are the walk: their multipoles and leaf pairs give evaluate()'s a_i exactly
  const Particles p = test::sphere(3000, true);
  const Sources s = Sources::of(p);
  const PairLaw law = plummer(0.01);
  BarnesHutTree t;
  t.build(s);
  Result r;
  t.evaluate(s, law, 1.0, 0.5, r);
  for (std::size_t i : {0u, 17u, 1234u, 2999u}) {
    const auto used = t.interactions(s, law, 0.5, BarnesHutTree::kDefaultTol, i);
    double a[3] = {0, 0, 0}, phi = 0.0, mass = 0.0;
    std::size_t whole = 0;
    for (const CellUse& u : used) {
      const TreeNode& nd = t.nodes()[u.node];
      mass += nd.mass;
      if (u.whole) {
        multipole_field(nd, p.x[0][i] - nd.com[0], p.x[1][i] - nd.com[1], p.x[2][i] - nd.com[2], law.eps2, a[0], a[1],
                        a[2], phi);
        ++whole;
        continue;
      }
      EXPECT_EQ(nd.n_child, 0);  // only leaves are summed pair by pair
      for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {
        const std::uint32_t j = t.order()[q];
        if (j == i) continue;
        const double d[3] = {p.x[0][i] - p.x[0][j], p.x[1][i] - p.x[1][j], p.x[2][i] - p.x[2][j]};
        double f, ph;
        law(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], p[Field::H][i], p[Field::H][j], f, ph);
        for (int k = 0; k < 3; ++k) a[k] -= p[Field::Mass][j] * f * d[k];
      }
    }
    EXPECT_GT(whole, 0u);
    EXPECT_NEAR(mass, 1.0, 1e-12);  // every particle, the probe's own included, exactly once
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], r.a[k][i], 1e-13 * std::abs(r.a[k][i]) + 1e-15) << "particle " << i;
  }
}

TEST(BarnesHut, CellsHoldTheirParticlesAndBmaxBoundsThem) {
  const Particles p = test::sphere(3000, true, 11);
  const Sources s = Sources::of(p);
  BarnesHutTree t;
  t.build(s, 8);
  const auto& nodes = t.nodes();
  EXPECT_NEAR(nodes[0].mass, 1.0, 1e-12);
  EXPECT_EQ(nodes[0].count, 3000u);
  for (const TreeNode& nd : nodes) {
    if (nd.n_child == 0) { EXPECT_TRUE(nd.count <= 8 || nd.depth >= 60); }
    for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {
      const std::uint32_t i = t.order()[q];
      double r2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        EXPECT_LE(std::abs(p.x[k][i] - nd.center[k]), nd.half * (1 + 1e-12));  // inside the cube
        r2 += std::pow(p.x[k][i] - nd.com[k], 2);
      }
      EXPECT_LE(std::sqrt(r2), nd.bmax * (1 + 1e-12));
    }
  }
}

TEST(DirectSum, MomentumIsConservedToRoundOff) {
  const Particles p = test::sphere(1000, true, 5);
  const Sources s = Sources::of(p);
  Result r;
  direct_sum(s, plummer(0.01), 1.0, r);
  double P[3] = {0, 0, 0}, scale = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      P[k] += p[Field::Mass][i] * r.a[k][i];
      scale += p[Field::Mass][i] * std::abs(r.a[k][i]);
    }
  for (double c : P) EXPECT_LT(std::abs(c), 1e-13 * scale);
  // and the potential of one particle is the brute-force sum
  double phi0 = 0.0;
  for (std::size_t j = 1; j < p.size(); ++j) {
    const double d2 = std::pow(p.x[0][0] - p.x[0][j], 2) + std::pow(p.x[1][0] - p.x[1][j], 2) +
                      std::pow(p.x[2][0] - p.x[2][j], 2);
    phi0 -= p[Field::Mass][j] / std::sqrt(d2 + 1e-4);
  }
  EXPECT_NEAR(r.phi[0], phi0, 1e-13 * std::abs(phi0));
}

TEST(Gravity, BitwiseIdenticalForOneAndTwoThreads) {
  const Particles p = test::sphere(6000, false, 9);
  const Sources s = Sources::of(p);
  const KernelSoftening ks(KernelType::M4);
  PairLaw kernel;
  kernel.kind = Softening::Kernel;
  kernel.kernel = &ks;
  for (const PairLaw& law : {plummer(0.05), kernel}) {
    Result r[2][2];
    for (int threads = 1; threads <= 2; ++threads) {
      omp_set_num_threads(threads);
      direct_sum(s, law, 1.0, r[threads - 1][0]);
      BarnesHutTree t;
      t.build(s);
      t.evaluate(s, law, 1.0, 0.6, r[threads - 1][1]);
    }
    for (int m = 0; m < 2; ++m)
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(0, std::memcmp(r[0][m].a[k].data(), r[1][m].a[k].data(), r[0][m].a[k].size() * sizeof(double)))
            << (m ? "tree" : "direct");
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace
}  // namespace sph::gravity
