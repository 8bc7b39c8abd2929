// Dummy wall particles (Adami, Hu & Adams 2012, eq. 27): the pressure of a wall particle is the kernel
// average of the fluid pressures around it plus the hydrostatic step g . sum rho_f (x_w - x_f) W / sum W.
// For fluid at rest in hydrostatic equilibrium P = p0 + rho0 g (H - y), the extrapolation is exact for
// a uniform density, so each wall particle gets the hydrostatic pressure of its own depth; the Tait
// densities differ from rho0 by (P - p0)/c0^2, which bounds the error. Without gravity the average is a
// plain kernel average, exact at the kernel-weighted centroid of the fluid neighbours (P is linear).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sph/eos.h"
#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kNx = 10, kNy = 12, kLayers = 3;
constexpr double kDx = 0.05, kH = kNy * kDx, kG = 9.81;  // free surface at y = H = 0.6 m

Params dummy_params(bool gravity) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = ForceType::Standard;
  prm.physics.energy = Toggle::Off;
  prm.physics.walls = WallType::Dummy;
  prm.physics.body_force = gravity ? BodyForce::Uniform : BodyForce::None;
  prm.body.gy = -kG;
  prm.liquid.c0 = 10.0 * std::sqrt(kG * kH);  // weakly compressible practice: (P - p0)/(rho0 c0^2) <= 1 %
  prm.liquid.p0 = 1234.0;                     // nonzero, so a missing p0 shows
  return prm;
}

double hydrostatic(const Params& prm, double y) { return prm.liquid.p0 + prm.liquid.rho0 * kG * (kH - y); }

/// kNx x kNy fluid particles (periodic in x, free surface on top) above kLayers rows of wall particles,
/// listed first so that partition_by_kind must move them behind the fluid. `pressure(y)` sets the fluid's
/// pressure; its density is the Tait density of that pressure.
template <class Pressure>
test::StageBench tank(const Params& prm, Pressure pressure) {
  auto stage = make_walls_dummy();
  const std::size_t nw = kNx * kLayers, n = kNx * kNy + nw;
  test::StageBench b(prm, 2, n, stage->needs() | stage->writes());
  b.domain.lo = {0, -1, 0};
  b.domain.hi = {kNx * kDx, 1, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Open, Boundary::Open};
  for (std::size_t k = 0; k < n; ++k) {
    const bool wall = k < nw;
    const std::size_t i = k % kNx, row = wall ? k / kNx : (k - nw) / kNx;
    b.p.x[0][k] = (i + 0.5) * kDx;
    b.p.x[1][k] = wall ? -(row + 0.5) * kDx : (row + 0.5) * kDx;
    b.p.kind[k] = static_cast<std::uint8_t>(wall ? Kind::Wall : Kind::Fluid);
    b.p[Field::Mass][k] = prm.liquid.rho0 * kDx * kDx;
    b.p[Field::H][k] = 1.3 * kDx;
    if (!wall) {
      b.p[Field::Pressure][k] = pressure(b.p.x[1][k]);
      b.p[Field::Density][k] = eos::tait_density(b.p[Field::Pressure][k], prm.liquid);
      b.p[Field::SoundSpeed][k] = eos::tait_sound_speed(b.p[Field::Density][k], prm.liquid);
    }
  }
  b.p.partition_by_kind();
  EXPECT_EQ(b.p.fluid(), kNx * kNy);
  b.prepare(FieldSet{}.add(Field::Pressure).add(Field::Density));
  EXPECT_TRUE(b.run(*stage));
  return b;
}

/// Fluid neighbours of wall particle w within its support: kernel-weighted centroid height, the largest
/// |rho_f - rho0| |y_f - y_w| among them, and their count (brute force over real and ghost particles).
struct FluidAround {
  double ybar = 0.0, max_drho_dy = 0.0;
  int count = 0;
};
FluidAround around(const test::StageBench& b, std::size_t w) {
  const Particles& p = b.p;
  FluidAround out;
  double sw = 0.0, swy = 0.0;
  for (std::size_t f = 0; f < p.total(); ++f) {
    if (p.kind[f]) continue;
    const double r = (p.pos(w) - p.pos(f)).norm(), W = b.kernel.W(r, p[Field::H][w]);
    if (W <= 0.0) continue;
    ++out.count;
    sw += W;
    swy += W * p.x[1][f];
    out.max_drho_dy = std::max(out.max_drho_dy, std::abs(p[Field::Density][f] - b.prm.liquid.rho0) *
                                                    std::abs(p.x[1][f] - p.x[1][w]));
  }
  out.ybar = out.count ? swy / sw : 0.0;
  return out;
}

TEST(WallsDummy, WallPressureIsHydrostaticAtItsOwnDepth) {
  const Params prm = dummy_params(true);
  const test::StageBench b = tank(prm, [&](double y) { return hydrostatic(prm, y); });
  const Particles& p = b.p;
  int with_fluid = 0;
  double worst = 0.0;
  for (std::size_t w = p.fluid(); w < p.size(); ++w) {
    const FluidAround fa = around(b, w);
    if (fa.count == 0) continue;
    ++with_fluid;
    const double exact = hydrostatic(prm, p.x[1][w]);
    // P_w - exact = sum W (rho_f - rho0) g (y_f - y_w) / sum W: bounded by the largest term (plus rounding)
    const double bound = kG * fa.max_drho_dy + 1e-12 * exact;
    EXPECT_NEAR(p[Field::Pressure][w], exact, bound) << "wall particle at y = " << p.x[1][w];
    worst = std::max(worst, std::abs(p[Field::Pressure][w] - exact) / exact);
    EXPECT_GT(bound, 0.0);
    EXPECT_LT(bound, 2e-3 * exact);  // the bound itself is small: the extrapolation is hydrostatic
    // the density is the Tait density of that pressure, the sound speed that of the density
    EXPECT_NEAR(p[Field::Density][w], eos::tait_density(p[Field::Pressure][w], prm.liquid), 1e-12 * prm.liquid.rho0);
    EXPECT_EQ(p[Field::SoundSpeed][w], eos::tait_sound_speed(p[Field::Density][w], prm.liquid));
    EXPECT_GT(p[Field::Density][w], prm.liquid.rho0);  // compressed below the fluid
  }
  std::printf("max |P_wall - P_hydrostatic| / P_hydrostatic = %.3e\n", worst);
  EXPECT_EQ(with_fluid, static_cast<int>(2 * kNx));  // the two upper wall rows reach into the fluid
  // the ghosts of the walls (periodic images) carry the same state
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    const std::size_t s = p.ghost_src[g];
    EXPECT_EQ(p[Field::Pressure][p.size() + g], p[Field::Pressure][s]);
    EXPECT_EQ(p[Field::Density][p.size() + g], p[Field::Density][s]);
  }
}

TEST(WallsDummy, WithoutGravityTheWallGetsTheKernelAverage) {
  // No body force: P_w = sum P_f W / sum W, which for P linear in y is exactly P(ybar) with ybar the
  // kernel-weighted centroid of the fluid neighbours, and ybar > y_w: the wall sees a shallower pressure.
  const Params prm = dummy_params(false);
  const Params with_g = dummy_params(true);  // the same hydrostatic fluid
  const test::StageBench b = tank(prm, [&](double y) { return hydrostatic(with_g, y); });
  const Particles& p = b.p;
  for (std::size_t w = p.fluid(); w < p.size(); ++w) {
    const FluidAround fa = around(b, w);
    if (fa.count == 0) continue;
    const double P = p[Field::Pressure][w];
    EXPECT_NEAR(P, hydrostatic(with_g, fa.ybar), 1e-12 * P);  // a weighted mean of a linear function
    EXPECT_LT(P, hydrostatic(with_g, p.x[1][w]) - prm.liquid.rho0 * kG * kDx);  // centroid > 1 dx above
  }
}

TEST(WallsDummy, WallsOutOfReachOfTheFluidGetTheBackgroundPressure) {
  const Params prm = dummy_params(true);
  const test::StageBench b = tank(prm, [&](double y) { return hydrostatic(prm, y); });
  const Particles& p = b.p;
  int alone = 0;
  for (std::size_t w = p.fluid(); w < p.size(); ++w) {
    if (around(b, w).count > 0) continue;
    ++alone;  // the deepest row: 3 dx from the fluid, beyond the support 2.6 dx
    EXPECT_EQ(p[Field::Pressure][w], prm.liquid.p0);
    EXPECT_EQ(p[Field::Density][w], prm.liquid.rho0);  // tait_density(p0) = rho0 exactly
    EXPECT_EQ(p[Field::SoundSpeed][w], prm.liquid.c0);
  }
  EXPECT_EQ(alone, static_cast<int>(kNx));
}

TEST(WallsDummy, TensionIsNotPassedToTheWall) {
  // Fluid below the background pressure (in tension): the extrapolated wall pressure would be below p0
  // too and would pull the fluid onto the wall; it is held at p0.
  const Params prm = dummy_params(false);
  const test::StageBench b = tank(prm, [&](double) { return prm.liquid.p0 - 500.0; });
  for (std::size_t w = b.p.fluid(); w < b.p.size(); ++w) EXPECT_EQ(b.p[Field::Pressure][w], prm.liquid.p0);
}

}  // namespace
}  // namespace sph
