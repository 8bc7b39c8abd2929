// walls.friction (terms/wall_friction.h): the share of the viscosity between fluid and dummy walls. A
// fluid layer sliding at a uniform U over a wall at rest feels viscosity only from the wall (fluid pairs
// have v_ab = 0, and the pressure forces act along y by symmetry), so its x-accelerations are linear in
// the share: exactly 0 at friction = 0 (free slip) and a drag against U at friction = 1 (no slip).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "sph/eos.h"
#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kNx = 10, kNy = 6, kLayers = 3;
constexpr double kDx = 0.05, kU = 1.0;

/// x-accelerations of the fluid particles [m/s^2] of a kNx x kNy layer (periodic in x) moving at U above
/// kLayers rows of dummy walls at rest, with the given viscosity and walls.friction.
std::vector<double> slide(ViscType visc, double friction) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = ForceType::Standard;
  prm.physics.viscosity = visc;
  prm.physics.energy = Toggle::Off;
  prm.physics.walls = WallType::Dummy;
  prm.liquid.c0 = 20.0;
  prm.visc.alpha = 0.1;
  prm.visc.nu = 1e-3;
  prm.walls.friction = friction;
  const std::size_t nw = kNx * kLayers, n = kNx * kNy + nw;
  test::StageBench b(prm, 2, n, test::pipeline_fields(prm, 2));
  b.domain.lo = {0, -1, 0};
  b.domain.hi = {kNx * kDx, 1, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Open, Boundary::Open};
  for (std::size_t k = 0; k < n; ++k) {
    const bool wall = k < nw;
    const std::size_t i = k % kNx, row = wall ? k / kNx : (k - nw) / kNx;
    b.p.x[0][k] = (i + 0.5) * kDx;
    b.p.x[1][k] = wall ? -(row + 0.5) * kDx : (row + 0.5) * kDx;
    b.p.v[0][k] = wall ? 0.0 : kU;
    b.p.kind[k] = static_cast<std::uint8_t>(wall ? Kind::Wall : Kind::Fluid);
    b.p[Field::Mass][k] = prm.liquid.rho0 * kDx * kDx;
    b.p[Field::H][k] = 1.3 * kDx;
    b.p[Field::Density][k] = prm.liquid.rho0;
  }
  b.p.partition_by_kind();
  b.prepare(FieldSet{}.add(Field::Density));
  b.run_pipeline();
  return {b.p.a[0].begin(), b.p.a[0].begin() + static_cast<long>(b.p.fluid())};
}

class WallFriction : public ::testing::TestWithParam<ViscType> {};

TEST_P(WallFriction, IsLinearInTheShareAndVanishesForFreeSlip) {
  const std::vector<double> none = slide(GetParam(), 0.0), half = slide(GetParam(), 0.5), full = slide(GetParam(), 1.0);
  double drag = 0.0, worst_free = 0.0, worst_half = 0.0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    drag += full[i];
    worst_free = std::max(worst_free, std::abs(none[i]));
    worst_half = std::max(worst_half, std::abs(half[i] - 0.5 * full[i]));
  }
  std::printf("mean a_x at friction 1: %.4e m/s^2; free slip: max |a_x| %.1e; half: max |a - a_1/2| %.1e\n",
              drag / full.size(), worst_free, worst_half);
  EXPECT_LT(drag, -1e-3 * full.size()) << "no-slip walls drag the sliding layer";
  EXPECT_LT(worst_free, 1e-12) << "free-slip walls exert no viscous force";
  EXPECT_LT(worst_half, 1e-12 * std::abs(drag)) << "the force is linear in walls.friction";
}

INSTANTIATE_TEST_SUITE_P(Viscosities, WallFriction, ::testing::Values(ViscType::Monaghan, ViscType::Laplacian));

}  // namespace
}  // namespace sph
