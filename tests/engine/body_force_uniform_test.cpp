// The uniform body force (gravity near the ground): dv/dt += g for every fluid particle, nothing for the
// fixed walls, and the potential energy E_pot = -sum_fluid m g . x, whose change under any displacement
// is minus the work of g. A free fall integrated with leapfrog (exact for a constant force) then
// conserves E_kin + E_pot to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sph/integrator.h"
#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kFluid = 5, kWalls = 3;

/// 3D so that all three components of g are exercised; walls listed first, moved behind by partition.
test::StageBench bench() {
  Params prm;
  prm.physics.body_force = BodyForce::Uniform;
  prm.body.gx = 0.5;
  prm.body.gy = -9.81;
  prm.body.gz = 1.25;
  auto stage = make_body_force_uniform();
  test::StageBench b(prm, 3, kFluid + kWalls, stage->needs().add(Field::H));
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const double s = static_cast<double>(i);
    b.p.x[0][i] = 0.1 * s;
    b.p.x[1][i] = 1.0 - 0.07 * s * s;
    b.p.x[2][i] = -0.3 + 0.05 * s;
    b.p[Field::Mass][i] = 1.0 + 0.25 * s;  // unequal masses: the potential must weight by m
    b.p[Field::H][i] = 0.1;
    b.p.kind[i] = static_cast<std::uint8_t>(i < kWalls ? Kind::Wall : Kind::Fluid);
    for (int k = 0; k < 3; ++k) b.p.a[k][i] = 0.1 * (k + 1) * s;  // what earlier stages left
  }
  b.p.partition_by_kind();
  EXPECT_EQ(b.p.fluid(), kFluid);
  b.prepare(FieldSet{});
  return b;
}

Vec3 gravity(const Params& prm) { return {prm.body.gx, prm.body.gy, prm.body.gz}; }

TEST(BodyForceUniform, AddsGToTheFluidOnly) {
  test::StageBench b = bench();
  const auto before = b.p.a;
  auto stage = make_body_force_uniform();
  EXPECT_TRUE(b.run(*stage));
  const Vec3 g = gravity(b.prm);
  const double gk[3] = {g.x, g.y, g.z};
  for (std::size_t i = 0; i < b.p.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double expected = b.p.is_wall(i) ? before[k][i] : before[k][i] + gk[k];  // adds, does not set
      EXPECT_EQ(b.p.a[k][i], expected) << "particle " << i << " axis " << k;
    }
}

TEST(BodyForceUniform, PotentialIsMinusMassTimesGDotX) {
  test::StageBench b = bench();
  auto stage = make_body_force_uniform();
  const Vec3 g = gravity(b.prm);
  double expected = 0.0;
  for (std::size_t i = 0; i < b.p.fluid(); ++i) expected -= b.p[Field::Mass][i] * g.dot(b.p.pos(i));
  EXPECT_NEAR(stage->potential(b.context()), expected, 1e-14 * std::abs(expected));  // same sum, reordered
  // Walls are fixed: moving one changes nothing.
  b.p.x[1][b.p.fluid()] += 3.0;
  EXPECT_NEAR(stage->potential(b.context()), expected, 1e-14 * std::abs(expected));
}

TEST(BodyForceUniform, PotentialChangeIsMinusTheWork) {
  test::StageBench b = bench();
  auto stage = make_body_force_uniform();
  const Vec3 g = gravity(b.prm);
  const double U0 = stage->potential(b.context());
  double work = 0.0;  // W = sum m g . d over arbitrary displacements d_i
  for (std::size_t i = 0; i < b.p.fluid(); ++i) {
    const Vec3 d{0.3 - 0.1 * i, 0.02 * i * i - 0.5, 0.7};
    b.p.x[0][i] += d.x;
    b.p.x[1][i] += d.y;
    b.p.x[2][i] += d.z;
    work += b.p[Field::Mass][i] * g.dot(d);
  }
  const double U1 = stage->potential(b.context());
  EXPECT_GT(std::abs(work), 1.0);
  EXPECT_NEAR(U1 - U0, -work, 1e-13 * (std::abs(U0) + std::abs(work)));  // linear in x: rounding only
}

TEST(BodyForceUniform, FreeFallConservesEnergyWithLeapfrog) {
  // dv/dt = g exactly: kick-drift-kick reproduces x0 + v0 t + g t^2 / 2 without truncation error.
  test::StageBench b = bench();
  auto stage = make_body_force_uniform();
  Particles& p = b.p;
  const std::size_t n = p.fluid();
  for (std::size_t i = 0; i < n; ++i) p.v[0][i] = 0.2 * i;
  const auto x0 = p.x;
  const auto v0 = p.v;
  PhaseSpace s;
  s.dim = 3;
  s.n = n;
  for (int k = 0; k < 3; ++k) { s.x[k] = &p.x[k]; s.v[k] = &p.v[k]; s.a[k] = &p.a[k]; }
  const Evaluate eval = [&](double) {
    for (int k = 0; k < 3; ++k) std::fill(p.a[k].begin(), p.a[k].end(), 0.0);
    b.run(*stage);
  };
  auto kinetic = [&] {
    double e = 0.0;
    for (std::size_t i = 0; i < n; ++i) e += 0.5 * p[Field::Mass][i] * p.vel(i).norm2();
    return e;
  };
  const double E0 = kinetic() + stage->potential(b.context());
  auto integ = make_integrator(IntegratorType::Leapfrog);
  const double dt = 0.01;
  bool current = false;
  for (int step = 0; step < 50; ++step) current = integ->step(s, eval, dt, current);
  const double t = 50 * dt;
  const Vec3 g = gravity(b.prm);
  const double gk[3] = {g.x, g.y, g.z};
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p.x[k][i], x0[k][i] + v0[k][i] * t + 0.5 * gk[k] * t * t, 1e-13);  // 50 steps of rounding
  const double K = kinetic();
  EXPECT_GT(K, 10.0);  // it really fell: the kinetic energy grew from ~1 to ~70
  // E_kin + E_pot of a free fall is constant; rounding relative to the energies exchanged
  EXPECT_NEAR(K + stage->potential(b.context()), E0, 1e-12 * (K + std::abs(E0)));
}

}  // namespace
}  // namespace sph
