// The continuity stage (seed 001 eq. 39): drho_a/dt = rho_a sum_b V_b v_ab . grad_a W_ab. For a uniform
// rho this is exactly the time derivative of the summation density sum_b m_b W_ab (seed 000 eq. 3.2.17)
// along the particle paths, which a finite difference in time checks without repeating the stage's
// algebra. The delta-SPH diffusion term (Molteni & Colagrossi 2009) vanishes for a uniform density,
// conserves sum_a V_a rho_a, lowers a density peak and approximates delta h c0 lap(rho).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "stage_test_util.h"

namespace sph {
namespace {

constexpr std::size_t kSide = 24;
constexpr double kDx = 1.0 / kSide;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

Params continuity_params(double diffusion) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = ForceType::None;  // not fused into a force loop (fuses_continuity)
  prm.physics.viscosity = ViscType::None;
  prm.physics.energy = Toggle::Off;
  prm.density.diffusion = diffusion;
  return prm;
}

/// A periodic unit square of kSide^2 particles (jitter in units of dx) with the continuity stage's fields;
/// `state` sets v and rho of particle i at (x, y) before the ghosts are made.
template <class State>
test::StageBench periodic_bench(const Params& prm, double jitter, State state) {
  auto stage = make_density_continuity(prm.physics, 2);
  FieldSet fields = stage->needs() | stage->writes();
  for (const EvolvedPair& e : stage->evolves()) fields.add(e.first).add(e.second);
  test::StageBench b(prm, 2, kSide * kSide, fields);
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {1, 1, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  test::jittered_lattice(b.p, kSide, kDx, jitter, 1.3 * kDx, prm.liquid.rho0);
  for (std::size_t i = 0; i < b.p.size(); ++i) state(b.p, i, b.p.x[0][i], b.p.x[1][i]);
  b.prepare(FieldSet{}.add(Field::Density));
  return b;
}

/// Shear plus a divergent part (both periodic): v = U (sin 2pi y, cos 2pi x) + A (sin 2pi x, sin 2pi y).
constexpr double kU = 1.0, kA = 0.5;
void swirl(Particles& p, std::size_t i, double x, double y) {
  p.v[0][i] = kU * std::sin(kTwoPi * y) + kA * std::sin(kTwoPi * x);
  p.v[1][i] = kU * std::cos(kTwoPi * x) + kA * std::sin(kTwoPi * y);
}

/// The continuity rate of every particle from the stage.
std::vector<double> stage_rate(test::StageBench& b) {
  auto stage = make_density_continuity(b.prm.physics, 2);
  EXPECT_FALSE(fuses_continuity(b.prm.physics));
  EXPECT_TRUE(b.run(*stage));
  const auto& r = b.p[Field::DensityRate];
  return {r.begin(), r.begin() + static_cast<std::ptrdiff_t>(b.p.size())};
}

/// Summation density of particle a after every particle has moved by v s (ghosts with their source).
double summation_after(const test::StageBench& b, std::size_t a, double s) {
  const Particles& p = b.p;
  const double h = p[Field::H][a];
  double rho = 0.0;
  for (std::uint32_t j : b.nl.of(a)) {
    const Vec3 r = p.pos(a) - p.pos(j) + (p.vel(a) - p.vel(j)) * s;
    rho += p[Field::Mass][j] * b.kernel.W(r.norm(), h);
  }
  return rho;
}

TEST(DensityContinuity, RateIsTheDerivativeOfTheSummationDensity) {
  test::StageBench b = periodic_bench(continuity_params(0.0), 0.3, swirl);
  const std::vector<double> rate = stage_rate(b);
  // s |v_ab| ~ 3e-5 h: the central difference's truncation ~ (s v/h)^2 ~ 1e-9 relative; rounding of
  // rho ~ 1e3 (~1e-13) over 2 s = 2e-6 is ~5e-8 absolute against rates ~ 3e3 (2e-11 relative)
  const double s = 1e-6;
  double worst = 0.0, scale = 0.0;
  for (std::size_t a = 0; a < b.p.size(); ++a) {
    const double fd = (summation_after(b, a, s) - summation_after(b, a, -s)) / (2 * s);
    worst = std::max(worst, std::abs(rate[a] - fd));
    scale = std::max(scale, std::abs(fd));
  }
  std::printf("max |drho/dt - d(sum m W)/dt| = %.3e of max %.3e\n", worst, scale);
  EXPECT_GT(scale, 1e3);  // rho0 div v ~ 1e3 * 2 pi A: the field is not trivially zero
  // uniform rho: the two forms are algebraically equal, so only the finite difference errs (see above)
  EXPECT_LT(worst, 1e-8 * scale);
}

TEST(DensityContinuity, RateIsMinusRhoTimesTheDivergenceOnALattice) {
  // drho/dt = -rho div v with div v = 2 pi A (cos 2 pi x + cos 2 pi y) (the shear part is divergence free)
  const Params prm = continuity_params(0.0);
  test::StageBench b = periodic_bench(prm, 0.0, swirl);
  const std::vector<double> rate = stage_rate(b);
  double worst = 0.0;
  const double scale = prm.liquid.rho0 * kTwoPi * kA * 2.0;
  for (std::size_t a = 0; a < b.p.size(); ++a) {
    const double div = kTwoPi * kA * (std::cos(kTwoPi * b.p.x[0][a]) + std::cos(kTwoPi * b.p.x[1][a]));
    worst = std::max(worst, std::abs(rate[a] + prm.liquid.rho0 * div) / scale);
  }
  std::printf("max |drho/dt + rho div v| / (rho max|div v|) = %.3e\n", worst);
  // the SPH divergence on a regular lattice is a kernel-smoothed divergence, second order in k h = 0.34
  // (k = 2 pi, h = 1.3/24): measured 8.3e-3; a wrong sign or a missing V_b errs by O(1)
  EXPECT_LT(worst, 0.02);
}

TEST(DensityContinuity, DiffusionVanishesForAUniformDensity) {
  test::StageBench plain = periodic_bench(continuity_params(0.0), 0.3, swirl);
  test::StageBench diffused = periodic_bench(continuity_params(0.1), 0.3, swirl);
  const std::vector<double> r0 = stage_rate(plain), r1 = stage_rate(diffused);
  // rho_a - rho_b = 0 exactly in every pair term, so the rates agree bit for bit
  for (std::size_t a = 0; a < r0.size(); ++a) EXPECT_EQ(r0[a], r1[a]) << "particle " << a;
}

TEST(DensityContinuity, DiffusionLowersADensityPeakAndConservesVolumeWeightedDensity) {
  const Params prm = continuity_params(0.1);
  const double rho0 = prm.liquid.rho0, w = 0.1;
  std::size_t peak = 0;
  double best = 1e300;
  test::StageBench b = periodic_bench(prm, 0.0, [&](Particles& p, std::size_t i, double x, double y) {
    const double r2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
    p[Field::Density][i] = rho0 * (1.0 + 0.01 * std::exp(-r2 / (w * w)));  // v = 0: only diffusion acts
    if (r2 < best) { best = r2; peak = i; }
  });
  const std::vector<double> rate = stage_rate(b);
  const double expected_scale = 0.1 * 1.3 * kDx * prm.liquid.c0 * 0.01 * rho0 * 4.0 / (w * w);  // delta h c0 |lap rho|
  std::printf("peak rate %.3e, delta h c0 |lap rho| at the peak %.3e\n", rate[peak], expected_scale);
  // it lowers the peak, at about the rate of a Laplacian: the kernel smooths the bump (width w = 1.8 h),
  // so the sum reaches ~70 % of the pointwise value (measured 72 %); with the seed's sign misprint it would rise
  EXPECT_LT(rate[peak], -0.5 * expected_scale);
  double net = 0.0, gross = 0.0;
  for (std::size_t a = 0; a < b.p.size(); ++a) {
    const double V = b.p[Field::Mass][a] / b.p[Field::Density][a];
    net += V * rate[a];
    gross += V * std::abs(rate[a]);
  }
  // the pair terms V_a V_b (rho_a - rho_b) F_ab are antisymmetric (equal h): the sum cancels to rounding
  EXPECT_LT(std::abs(net), 1e-12 * gross);
}

TEST(DensityContinuity, DiffusionApproximatesTheLaplacian) {
  // rho = rho0 (1 + eps sin 2 pi x), v = 0: drho/dt = 2 delta h c0 sum V_b (rho_a - rho_b) F_ab
  // ~ delta h c0 lap(rho) = -delta h c0 (2 pi)^2 eps rho0 sin 2 pi x (Brookshaw's Laplacian)
  const Params prm = continuity_params(0.1);
  const double eps = 1e-3, rho0 = prm.liquid.rho0;
  test::StageBench b = periodic_bench(prm, 0.0, [&](Particles& p, std::size_t i, double x, double) {
    p[Field::Density][i] = rho0 * (1.0 + eps * std::sin(kTwoPi * x));
  });
  const std::vector<double> rate = stage_rate(b);
  const double h = b.p[Field::H][0], amp = 0.1 * h * prm.liquid.c0 * kTwoPi * kTwoPi * eps * rho0;
  double worst = 0.0;
  for (std::size_t a = 0; a < b.p.size(); ++a)
    worst = std::max(worst, std::abs(rate[a] + amp * std::sin(kTwoPi * b.p.x[0][a])) / amp);
  std::printf("max |diffusion - delta h c0 lap rho| / amplitude = %.3e\n", worst);
  EXPECT_LT(worst, 0.01);  // second order in k h = 0.34, measured 2.0e-3; a factor 2 lost would give 0.5
}

TEST(DensityContinuity, ReportsNeighbourCounts) {
  test::StageBench b = periodic_bench(continuity_params(0.0), 0.3, swirl);
  stage_rate(b);
  const Particles& p = b.p;
  double sum = 0.0;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const double R = b.kernel.support() * p[Field::H][a];
    int count = 0;  // brute force over real and ghost particles, itself included
    for (std::size_t j = 0; j < p.total(); ++j) count += (p.pos(a) - p.pos(j)).norm() < R;
    EXPECT_EQ(p[Field::Neighbours][a], count) << "particle " << a;
    sum += count;
  }
  const double mean = sum / static_cast<double>(p.size());
  EXPECT_NEAR(b.stats.density.mean_neighbours, mean, 1e-12 * mean);  // the same integers, summed in another order
  // pi (2 h)^2 / dx^2 = 21.2 expected for h = 1.3 dx
  EXPECT_NEAR(mean, std::numbers::pi * 4.0 * 1.3 * 1.3, 1.5);
}

}  // namespace
}  // namespace sph
