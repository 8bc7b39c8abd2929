// The XSPH stage (seed 001 eq. 45 with Monaghan's sign, v_b - v_a): the correction
//   dv_a = eps sum_b m_b (v_b - v_a) / rho_ab W(r_ab, h_ab)
// is a smoothing of the velocity over the fluid neighbours: zero for a uniform flow, pulling a fast particle
// back towards its neighbours and them towards it, conserving momentum (the pair weights are symmetric),
// ignoring wall particles, and copied to mirror ghosts with the normal component reversed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kSide = 10;
constexpr double kDx = 0.1;

Params xsph_params() {
  Params prm;
  prm.physics.xsph = Toggle::On;
  prm.xsph.eps = 0.5;  // seed 001 §5: eps = 0.5
  return prm;
}

/// kSide^2 jittered fluid particles in [0, 1]^2 plus `walls` wall particles (positions set by the caller
/// after construction, then partitioned), with the XSPH fields.
test::StageBench bench(std::size_t walls = 0) {
  auto stage = make_xsph();
  test::StageBench b(xsph_params(), 2, kSide * kSide + walls, stage->needs() | stage->writes());
  test::jittered_lattice(b.p, kSide, kDx, 0.3, 1.3 * kDx, 1000.0);
  return b;
}

Vec3 correction(const Particles& p, std::size_t i) {
  return {p[Field::XsphX][i], p[Field::XsphY][i], p[Field::XsphZ][i]};
}

void run_xsph(test::StageBench& b) {
  b.prepare(FieldSet{}.add(Field::Density));
  auto stage = make_xsph();
  EXPECT_TRUE(b.run(*stage));
}

/// A smooth, non-uniform velocity field.
void swirl(Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.v[0][i] = std::sin(3.0 * p.x[1][i]) + 0.5 * p.x[0][i];
    p.v[1][i] = std::cos(2.0 * p.x[0][i]) - 0.3 * p.x[1][i] * p.x[1][i];
  }
}

TEST(Xsph, UniformFlowHasNoCorrection) {
  test::StageBench b = bench();
  for (std::size_t i = 0; i < b.p.size(); ++i) { b.p.v[0][i] = 0.3; b.p.v[1][i] = -0.7; }
  run_xsph(b);
  // every pair term has v_b - v_a = 0 exactly
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    EXPECT_EQ(b.p[Field::XsphX][i], 0.0);
    EXPECT_EQ(b.p[Field::XsphY][i], 0.0);
  }
}

TEST(Xsph, FastParticleIsPulledBackAndMomentumIsConserved) {
  test::StageBench b = bench();
  const std::size_t c = (kSide / 2) * kSide + kSide / 2;  // near the centre
  const Vec3 vc{1.0, 0.5, 0.0};
  b.p.v[0][c] = vc.x;
  b.p.v[1][c] = vc.y;
  run_xsph(b);
  const Particles& p = b.p;
  // brute force: S = sum_b m_b / rho_ab W(r, h_ab) over the other particles
  double S = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    if (j == c) continue;
    const double hm = 0.5 * (p[Field::H][c] + p[Field::H][j]);
    S += p[Field::Mass][j] / (0.5 * (p[Field::Density][c] + p[Field::Density][j])) *
         b.kernel.W((p.pos(c) - p.pos(j)).norm(), hm);
  }
  const Vec3 dv = correction(p, c);
  const double eps = b.prm.xsph.eps;
  // dv_c = -eps S v_c: opposite to v_c, with a weight between 0 and 1 (no overshoot past the neighbours)
  EXPECT_NEAR(dv.x, -eps * S * vc.x, 1e-14);  // the same sum in another order: rounding of ~20 terms
  EXPECT_NEAR(dv.y, -eps * S * vc.y, 1e-14);
  EXPECT_GT(eps * S, 0.1);
  EXPECT_LT(eps * S, 1.0);
  Vec3 momentum;  // sum_a m_a dv_a
  int pulled = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 d = correction(p, i);
    momentum += d * p[Field::Mass][i];
    if (i == c) continue;
    EXPECT_GE(d.dot(vc), 0.0) << "neighbour " << i << " must be pulled along with the fast particle";
    pulled += d.dot(vc) > 0.0;
  }
  EXPECT_GE(pulled, 12);  // ~pi (2 h)^2 / dx^2 - 1 = 20 particles lie inside the support
  // antisymmetric pair terms: sum m dv cancels to the rounding of ~20 terms of size m |dv_c|
  EXPECT_LT(momentum.norm(), 1e-13 * p[Field::Mass][c] * dv.norm());
}

TEST(Xsph, WallParticlesAreExcluded) {
  // The same fluid with and without a row of wall particles just below it, moving fast (which fixed
  // walls never do): the fluid's correction must not change, and the walls get none.
  const std::size_t nw = kSide;
  test::StageBench with = bench(nw);
  for (std::size_t k = 0; k < nw; ++k) {
    const std::size_t w = kSide * kSide + k;
    with.p.x[0][w] = (k + 0.5) * kDx;
    with.p.x[1][w] = -0.5 * kDx;
    with.p[Field::Mass][w] = with.p[Field::Mass][0];
    with.p[Field::H][w] = with.p[Field::H][0];
    with.p[Field::Density][w] = 1000.0;
    with.p.kind[w] = static_cast<std::uint8_t>(Kind::Wall);
    with.p.v[0][w] = 5.0;
    with.p.v[1][w] = -3.0;
  }
  with.p.partition_by_kind();
  swirl(with.p);
  for (std::size_t w = with.p.fluid(); w < with.p.size(); ++w) { with.p.v[0][w] = 5.0; with.p.v[1][w] = -3.0; }
  ASSERT_EQ(with.p.fluid(), kSide * kSide);
  test::StageBench without = bench();
  swirl(without.p);
  run_xsph(with);
  run_xsph(without);
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < without.p.size(); ++i) {
    scale = std::max(scale, correction(without.p, i).norm());
    diff = std::max(diff, (correction(with.p, i) - correction(without.p, i)).norm());
  }
  EXPECT_GT(scale, 1e-3);
  EXPECT_LE(diff, 1e-14 * scale);  // identical sums, at most summed in another order
  for (std::size_t w = with.p.fluid(); w < with.p.size(); ++w) EXPECT_EQ(correction(with.p, w).norm(), 0.0);
}

/// The bench in a box with mirror walls at y = 0 and y = 1 (x open).
test::StageBench mirrored() {
  test::StageBench b = bench();
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {1, 1, 1};
  b.domain.bc = {Boundary::Open, Boundary::Wall, Boundary::Open};
  return b;
}

TEST(Xsph, MirrorGhostsReverseTheNormalComponent) {
  test::StageBench b = mirrored();
  swirl(b.p);
  run_xsph(b);
  const Particles& p = b.p;
  const std::size_t n = p.size();
  ASSERT_GT(p.total(), n);
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    const std::size_t s = p.ghost_src[g];
    EXPECT_EQ(p.ghost_flip[g], 2u);  // mirrored across a y wall
    EXPECT_EQ(p[Field::XsphX][n + g], p[Field::XsphX][s]);   // tangential: unchanged
    EXPECT_EQ(p[Field::XsphY][n + g], -p[Field::XsphY][s]);  // normal: reversed, like v_y of the ghost
  }
}

TEST(Xsph, MirrorWallsSlowTheNormalApproach) {
  // Tangential flow (U, 0): the mirror images move alike, no correction anywhere (free slip).
  test::StageBench t = mirrored();
  for (std::size_t i = 0; i < t.p.size(); ++i) t.p.v[0][i] = 1.0;
  run_xsph(t);
  for (std::size_t i = 0; i < t.p.size(); ++i) EXPECT_EQ(correction(t.p, i).norm(), 0.0);
  // Normal flow (0, -V): images move with +V, so particles within a support of a wall are slowed
  // (correction along +y); the others see only their own uniform flow.
  test::StageBench b = mirrored();
  for (std::size_t i = 0; i < b.p.size(); ++i) b.p.v[1][i] = -1.0;
  run_xsph(b);
  const double R = b.kernel.support() * 1.3 * kDx;
  int slowed = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const double y = b.p.x[1][i], dvy = b.p[Field::XsphY][i];
    if (std::min(y, 1.0 - y) < R / 2) {  // its own image is inside the support: a nonzero correction
      EXPECT_GT(dvy, 0.0) << "particle " << i;
      ++slowed;
    }
    if (std::min(y, 1.0 - y) >= R) {
      EXPECT_EQ(dvy, 0.0);  // no image within the support
    }
    EXPECT_GE(dvy, 0.0);
    EXPECT_EQ(b.p[Field::XsphX][i], 0.0);
  }
  EXPECT_GE(slowed, 2 * static_cast<int>(kSide));  // the rows next to each wall
}

}  // namespace
}  // namespace sph
