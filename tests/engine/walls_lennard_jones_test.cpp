// Lennard-Jones wall particles (seed 001 eq. 60; Monaghan 1994): a wall particle within r0 pushes a fluid
// particle away with f = D [(r0/r)^p1 - (r0/r)^p2] r_vec / r^2 per unit mass. The pure functions are
// checked against their closed forms and f = -dphi/dr; the stage against a hand-summed configuration and
// against minus the finite-difference gradient of its own potential (it is conservative).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sph/walls.h"
#include "stage_test_util.h"

namespace sph {
namespace {

// Seed 001 §7.2: p1 = 4, p2 = 2, r0 = the initial spacing, D ~ 5 g H (here H = 0.3 m).
constexpr double kD = 5 * 9.81 * 0.3, kR0 = 0.01, kP1 = 4.0, kP2 = 2.0;

double factor(double r) { return walls::lennard_jones_factor(r, kD, kR0, kP1, kP2); }
double potential(double r) { return walls::lennard_jones_potential(r, kD, kR0, kP1, kP2); }

TEST(WallsLennardJones, RepulsiveInsideTheCutOffAndZeroFromIt) {
  for (double s : {0.1, 0.3, 0.5, 0.8, 0.99, 0.999999}) EXPECT_GT(factor(s * kR0), 0.0) << "r/r0 = " << s;
  for (double s : {1.0, 1.000001, 1.5, 10.0}) {
    EXPECT_EQ(factor(s * kR0), 0.0) << "r/r0 = " << s;  // q^p1 - q^p2 = 1 - 1 at r0: exactly 0
    EXPECT_EQ(potential(s * kR0), 0.0) << "r/r0 = " << s;
  }
  // closed form at r = r0/2 (q = 2): D (2^4 - 2^2) / (r0/2)^2 = 48 D / r0^2, phi = D (15/4 - 3/2)
  EXPECT_NEAR(factor(0.5 * kR0) / (48.0 * kD / (kR0 * kR0)), 1.0, 1e-15);
  EXPECT_NEAR(potential(0.5 * kR0) / (2.25 * kD), 1.0, 1e-15);
}

TEST(WallsLennardJones, ForceIsMinusTheGradientOfThePotential) {
  for (double p2 : {kP2, 0.0}) {  // p2 = 0 takes the logarithmic limit of (q^p2 - 1)/p2
    for (double s : {0.3, 0.5, 0.7, 0.9, 0.99}) {
      const double r = s * kR0, dr = 1e-6 * r;
      const double phi_p = walls::lennard_jones_potential(r + dr, kD, kR0, kP1, p2);
      const double phi_m = walls::lennard_jones_potential(r - dr, kD, kR0, kP1, p2);
      const double f = walls::lennard_jones_factor(r, kD, kR0, kP1, p2) * r;  // |f| = factor |r_vec|
      // central difference: truncation (dr/r)^2 p1^2 ~ 1e-11; rounding eps phi / dr ~ 1e-10 of f
      EXPECT_NEAR(-(phi_p - phi_m) / (2 * dr) / f, 1.0, 1e-7) << "p2 = " << p2 << ", r/r0 = " << s;
    }
  }
  // The p2 -> 0 limit is continuous: (q^p2 - 1)/p2 = ln q + O(p2 ln^2 q).
  const double r = 0.5 * kR0;
  EXPECT_NEAR(walls::lennard_jones_potential(r, kD, kR0, kP1, 1e-7) / walls::lennard_jones_potential(r, kD, kR0, kP1, 0.0),
              1.0, 1e-6);
}

/// One fluid particle of mass 2 at `fluid` above a line of wall particles at y = 0 spaced r0/2, which
/// are listed first and must be moved behind the fluid by partition_by_kind.
test::StageBench bench(Vec3 fluid) {
  Params prm;
  prm.physics.walls = WallType::LennardJones;
  prm.walls.D = kD;
  prm.walls.r0 = kR0;
  prm.walls.p1 = kP1;
  prm.walls.p2 = kP2;
  const int half = 20;
  const std::size_t nw = 2 * half + 1;
  auto stage = make_walls_lennard_jones();
  test::StageBench b(prm, 2, nw + 1, stage->needs().add(Field::H));
  for (int k = -half; k <= half; ++k) {
    const std::size_t w = static_cast<std::size_t>(k + half);
    b.p.x[0][w] = k * 0.5 * kR0;
    b.p.kind[w] = static_cast<std::uint8_t>(Kind::Wall);
    b.p[Field::Mass][w] = 1.0;
  }
  b.p.x[0][nw] = fluid.x;
  b.p.x[1][nw] = fluid.y;
  b.p[Field::Mass][nw] = 2.0;
  for (std::size_t i = 0; i <= nw; ++i) b.p[Field::H][i] = kR0;  // neighbour lists reach 2.4 r0 > r0
  b.p.partition_by_kind();
  EXPECT_EQ(b.p.fluid(), 1u);
  b.prepare(FieldSet{});
  return b;
}

struct Result {
  Vec3 a;
  double potential;
};

Result run(Vec3 fluid) {
  test::StageBench b = bench(fluid);
  auto stage = make_walls_lennard_jones();
  EXPECT_TRUE(b.run(*stage));
  for (std::size_t w = 1; w < b.p.size(); ++w) EXPECT_EQ(b.p.a[1][w], 0.0);  // walls do not move
  return {{b.p.a[0][0], b.p.a[1][0], b.p.a[2][0]}, stage->potential(b.context())};
}

TEST(WallsLennardJones, StagePushesANearParticleAwayFromTheWall) {
  const Result r = run({0.0, 0.5 * kR0, 0.0});
  // Three walls are within r0: the one below (r = r0/2, factor 48 D/r0^2) and two at r = r0/sqrt2
  // (factor 4 D/r0^2); their y-distance is r0/2, so a_y = (48 + 2 * 4) D/r0^2 * r0/2 = 28 D/r0.
  EXPECT_GT(r.a.y, 0.0);
  EXPECT_NEAR(r.a.y / (28.0 * kD / kR0), 1.0, 1e-13);  // rounding of three terms
  EXPECT_NEAR(r.a.x, 0.0, 1e-13 * r.a.y);  // mirror-symmetric walls: the x parts cancel
  // potential m sum phi = 2 D [(15/4 - 3/2) + 2 ((4 - 1)/4 - (2 - 1)/2)] = 2 * 2.75 D
  EXPECT_NEAR(r.potential / (2.0 * 2.75 * kD), 1.0, 1e-13);
}

TEST(WallsLennardJones, StageLeavesAParticleBeyondTheCutOffAlone) {
  const Result r = run({0.1 * kR0, 1.5 * kR0, 0.0});  // nearest wall at 1.5 r0
  EXPECT_EQ(r.a.x, 0.0);
  EXPECT_EQ(r.a.y, 0.0);
  EXPECT_EQ(r.potential, 0.0);
}

TEST(WallsLennardJones, StageForceIsMinusTheGradientOfItsPotential) {
  // An off-centre position with three walls inside r0 (at x = -r0/2, 0, r0/2); a = -grad(E_pot)/m by central differences.
  const Vec3 x{0.13 * kR0, 0.6 * kR0, 0.0};
  const Result r = run(x);
  const double d = 1e-6 * kR0, m = 2.0;
  const double ax = -(run({x.x + d, x.y, 0}).potential - run({x.x - d, x.y, 0}).potential) / (2 * d * m);
  const double ay = -(run({x.x, x.y + d, 0}).potential - run({x.x, x.y - d, 0}).potential) / (2 * d * m);
  // truncation (d/r)^2 p1^2 ~ 1e-10; rounding eps E / d ~ 1e-10 of |a|
  EXPECT_NEAR(ax, r.a.x, 1e-7 * r.a.norm());
  EXPECT_NEAR(ay, r.a.y, 1e-7 * r.a.norm());
  EXPECT_GT(r.a.y, 0.0);
  EXPECT_GT(std::abs(r.a.x), 0.01 * r.a.norm());  // off-centre: the x derivative is exercised too (~3.6 %)
}

}  // namespace
}  // namespace sph
