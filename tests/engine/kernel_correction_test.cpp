// The moving-least-squares kernel correction (seed 001 eqs. 17-23, sph/kernel_correction.h): with the
// basis [1, (x_b - x_a)/h] the corrected weights reproduce every linear field exactly (eq. 23, m = 1) at
// every particle of a disordered set, also where the kernel support is cut by a free boundary; the
// Shepard weights (m = 0) reproduce constants only; the plain SPH sum reproduces neither at the boundary.
#include "sph/kernel_correction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kSide = 20;
constexpr double kDx = 1.0 / kSide;

/// A jittered 20 x 20 lattice in [0, 1]^2, no ghosts (open domain): a free boundary on all four sides.
test::StageBench free_set() {
  Params prm;
  test::StageBench b(prm, 2, kSide * kSide, FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::H));
  test::jittered_lattice(b.p, kSide, kDx, 0.4, 1.3 * kDx, 1000.0);
  b.prepare(FieldSet{}.add(Field::Density));
  return b;
}

/// Within one kernel support of the free boundary (its support is truncated).
bool near_boundary(const test::StageBench& b, std::size_t i) {
  const double R = b.kernel.support() * b.p[Field::H][i];
  const double x = b.p.x[0][i], y = b.p.x[1][i];
  return std::min({x, y, 1.0 - x, 1.0 - y}) < R;
}

/// The linear field f = c0 + g . x.
struct Linear {
  double c0, gx, gy;
  double operator()(const Particles& p, std::size_t j) const { return c0 + gx * p.x[0][j] + gy * p.x[1][j]; }
};

struct Reproduction {
  double boundary = 0.0;  ///< max |sum_b w_b f_b - f_a| / |f_a| over particles near the boundary
  double interior = 0.0;  ///< the same inside
  int orders_used = 0;    ///< sum of the returned orders
};

/// Max relative error of sum_b w_b f_b against f(x_a), with the corrected weights of `order`.
Reproduction corrected(const test::StageBench& b, const Linear& f, int order, double min_rcond) {
  Reproduction r;
  std::vector<double> w;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const auto nb = b.nl.of(i);
    r.orders_used += corrected_kernel_weights(b.kernel, b.p, i, nb, order, min_rcond, false, w);
    double s = 0.0;
    for (std::size_t k = 0; k < nb.size(); ++k) s += w[k] * f(b.p, nb[k]);
    const double err = std::abs(s - f(b.p, i)) / std::abs(f(b.p, i));
    double& slot = near_boundary(b, i) ? r.boundary : r.interior;
    slot = std::max(slot, err);
  }
  return r;
}

/// The same for the uncorrected SPH sum, sum_b V_b W_ab f_b (seed 001 eq. 8).
Reproduction plain(const test::StageBench& b, const Linear& f) {
  Reproduction r;
  const Particles& p = b.p;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double s = 0.0;
    for (std::uint32_t j : b.nl.of(i)) {
      const double rr = (p.pos(i) - p.pos(j)).norm();
      s += p[Field::Mass][j] / p[Field::Density][j] * b.kernel.W(rr, p[Field::H][i]) * f(p, j);
    }
    const double err = std::abs(s - f(p, i)) / std::abs(f(p, i));
    double& slot = near_boundary(b, i) ? r.boundary : r.interior;
    slot = std::max(slot, err);
  }
  return r;
}

const Linear kConstant{7.0, 0.0, 0.0};
const Linear kSlope{7.0, 3.0, -2.0};  // f in [5, 10] on the unit square: relative errors are meaningful

TEST(KernelCorrection, FirstOrderReproducesLinearFieldsEverywhere) {
  const test::StageBench b = free_set();
  const Reproduction c = corrected(b, kConstant, 1, 0.0);
  const Reproduction l = corrected(b, kSlope, 1, 0.0);
  std::printf("order 1: constant %.2e / %.2e, linear %.2e / %.2e (boundary / interior)\n", c.boundary, c.interior,
              l.boundary, l.interior);
  EXPECT_EQ(c.orders_used, static_cast<int>(b.p.size()));  // min_rcond = 0: no particle falls back
  // eq. 23 is an identity of the 3x3 solve: round-off of a moment matrix with condition number < ~100
  EXPECT_LT(c.boundary, 1e-12);
  EXPECT_LT(c.interior, 1e-12);
  EXPECT_LT(l.boundary, 1e-12);
  EXPECT_LT(l.interior, 1e-12);
}

TEST(KernelCorrection, ShepardReproducesConstantsButNotSlopesAtTheBoundary) {
  const test::StageBench b = free_set();
  const Reproduction c = corrected(b, kConstant, 0, 0.0);
  const Reproduction l = corrected(b, kSlope, 0, 0.0);
  std::printf("order 0: constant %.2e / %.2e, linear %.2e / %.2e (boundary / interior)\n", c.boundary, c.interior,
              l.boundary, l.interior);
  EXPECT_EQ(c.orders_used, 0);
  EXPECT_LT(c.boundary, 1e-14);  // sum_b W_ab / sum_b W_ab = 1: one division, ~20 additions
  EXPECT_LT(c.interior, 1e-14);
  // At the boundary the Shepard weights average over a one-sided neighbourhood whose centroid lies
  // ~0.5 h inside: f is off by |grad f| 0.5 h ~ 0.1, 1 % of f. Demand 0.2 %, far above round-off.
  EXPECT_GT(l.boundary, 2e-3);
}

TEST(KernelCorrection, PlainSphSumReproducesNeitherAtTheBoundary) {
  const test::StageBench b = free_set();
  const Reproduction c = plain(b, kConstant);
  const Reproduction l = plain(b, kSlope);
  std::printf("plain SPH: constant %.2e / %.2e, linear %.2e / %.2e (boundary / interior)\n", c.boundary, c.interior,
              l.boundary, l.interior);
  // a support cut in half at an edge (a quarter at a corner) misses ~half of sum V W = 1
  EXPECT_GT(c.boundary, 0.3);
  EXPECT_GT(l.boundary, 0.3);
  // inside, only the disorder (jitter 0.4 dx) breaks sum V W = 1 (measured 0.18): the boundary is worse
  EXPECT_GT(c.boundary, 1.5 * c.interior);
}

TEST(KernelCorrection, ImpossibleConditionFallsBackToShepard) {
  // rcond = (d+1)/(|A|_F |A^-1|_F) <= 1, with equality only for a multiple of an orthogonal matrix,
  // which a moment matrix [S, S x; S x, S x x^T] on a disordered set never is: 1.0 cannot be met.
  const test::StageBench b = free_set();
  std::vector<double> w1, w0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const auto nb = b.nl.of(i);
    EXPECT_EQ(corrected_kernel_weights(b.kernel, b.p, i, nb, 1, 1.0, false, w1), 0) << "particle " << i;
    EXPECT_EQ(corrected_kernel_weights(b.kernel, b.p, i, nb, 0, 1.0, false, w0), 0);
    ASSERT_EQ(w1.size(), nb.size());
    for (std::size_t k = 0; k < nb.size(); ++k) EXPECT_EQ(w1[k], w0[k]);  // exactly the Shepard weights
  }
  const Reproduction c = corrected(b, kConstant, 1, 1.0);
  EXPECT_EQ(c.orders_used, 0);
  EXPECT_LT(c.boundary, 1e-14);  // the fallback still reproduces constants
}

TEST(KernelCorrection, WallParticlesAreSkippedOnRequest) {
  // Marking the bottom rows as walls and skipping them is the same as removing them: the weights of the
  // remaining particles reproduce linear fields (the walls' weights are exactly 0).
  test::StageBench b = free_set();
  for (std::size_t i = 0; i < b.p.size(); ++i)
    if (b.p.x[1][i] < 2 * kDx) b.p.kind[i] = static_cast<std::uint8_t>(Kind::Wall);
  std::vector<double> w;
  double worst = 0.0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    if (b.p.is_wall(i)) continue;
    const auto nb = b.nl.of(i);
    corrected_kernel_weights(b.kernel, b.p, i, nb, 1, 0.0, true, w);
    double s = 0.0;
    for (std::size_t k = 0; k < nb.size(); ++k) {
      if (b.p.is_wall(nb[k])) {
        EXPECT_EQ(w[k], 0.0);
      }
      s += w[k] * kSlope(b.p, nb[k]);
    }
    worst = std::max(worst, std::abs(s - kSlope(b.p, i)) / kSlope(b.p, i));
  }
  EXPECT_LT(worst, 1e-12);  // as in FirstOrderReproducesLinearFieldsEverywhere
}

}  // namespace
}  // namespace sph
