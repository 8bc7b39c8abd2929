// The Tait/Cole equation of state (seed 001 eq. 3, sph/eos.h): P = B [(rho/rho0)^gamma - 1] + p0 with
// B = rho0 c0^2/gamma. Checked against its defining properties: P(rho0) = p0, dP/drho = c^2 (c0^2 at
// rho0) by finite differences, the inverse rho(P), and the elastic energy e(rho) with de/drho = P/rho^2.
// Values of seed 001 §7.1: rho0 = 1000 kg/m^3, gamma = 7, B = 285.714 MN/m^2 (c0 = 1414.2 m/s). The
// stage (eos_tait.cpp) applies them to the fluid and reports the elastic energy sum m e(rho).
#include <gtest/gtest.h>

#include <cmath>

#include "sph/eos.h"
#include "stage_test_util.h"

namespace sph {
namespace {

/// The seed's water, with background pressure p0 [Pa].
LiquidParams seed_water(double p0) {
  LiquidParams l;
  l.rho0 = 1000.0;
  l.gamma = 7.0;
  l.c0 = std::sqrt(l.gamma * 285.714e6 / l.rho0);  // c0 = sqrt(gamma B / rho0) = 1414.2 m/s
  l.p0 = p0;
  return l;
}

/// Central finite difference of f at x with step dx.
template <class F>
double central(F f, double x, double dx) {
  return (f(x + dx) - f(x - dx)) / (2.0 * dx);
}

// Background pressures: none, and one atmosphere (P then never vanishes, so a missing p0 shows).
const double kP0[] = {0.0, 101325.0};

TEST(EosTait, SeedConstants) {
  const LiquidParams l = seed_water(0.0);
  EXPECT_NEAR(l.c0, 1414.2, 0.05);                      // seed 001 §7.1 quotes c0 = 1414.2 m/s
  EXPECT_NEAR(eos::tait_B(l) / 285.714e6, 1.0, 1e-14);  // B recovered from c0: only rounding of sqrt^2
}

TEST(EosTait, ReferenceDensityGivesBackgroundPressure) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    EXPECT_EQ(eos::tait_pressure(l.rho0, l), p0);  // (1)^gamma - 1 = 0 exactly: no rounding at all
    EXPECT_EQ(eos::tait_sound_speed(l.rho0, l), l.c0);
  }
}

TEST(EosTait, OnePercentCompression) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    double r7 = 1.0;  // 1.01^7 by repeated products, independently of std::pow
    for (int k = 0; k < 7; ++k) r7 *= 1.01;
    const double B = l.rho0 * l.c0 * l.c0 / l.gamma;
    const double expected = B * (r7 - 1.0) + p0;  // ~20.61 MPa (+ p0)
    // a few ulps of r7 (~1) multiplied by B/(B (r7-1)) ~ 14: 1e-13 relative
    EXPECT_NEAR(eos::tait_pressure(1.01 * l.rho0, l) / expected, 1.0, 1e-13);
    EXPECT_NEAR(expected - p0, 20.61e6, 0.01e6);  // the number itself, 0.0721 B
  }
}

TEST(EosTait, SlopeAtReferenceDensityIsC0Squared) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    const auto P = [&](double rho) { return eos::tait_pressure(rho, l); };
    // step 1e-4 rho0: truncation (gamma-1)(gamma-2)/6 (dx/rho0)^2 = 5e-8 relative; rounding eps B/dx ~ 1e-13 c0^2
    const double slope = central(P, l.rho0, 1e-4 * l.rho0);
    EXPECT_NEAR(slope / (l.c0 * l.c0), 1.0, 1e-6);
  }
}

TEST(EosTait, SoundSpeedSquaredIsTheSlopeOfPressure) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    const auto P = [&](double rho) { return eos::tait_pressure(rho, l); };
    for (double s : {0.95, 0.99, 1.0, 1.003, 1.02, 1.1}) {
      const double rho = s * l.rho0;
      const double c = eos::tait_sound_speed(rho, l);
      const double slope = central(P, rho, 1e-4 * rho);
      EXPECT_NEAR(slope / (c * c), 1.0, 1e-6) << "rho/rho0 = " << s;  // same budget as at rho0
    }
  }
}

TEST(EosTait, DensityInvertsPressure) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    for (double s : {0.9, 0.99, 0.9999, 1.0, 1.0001, 1.01, 1.1, 1.5}) {
      const double rho = s * l.rho0;
      // (P - p0)/B + 1 = (rho/rho0)^gamma to a few ulps; the 1/gamma root divides that error by 7
      EXPECT_NEAR(eos::tait_density(eos::tait_pressure(rho, l), l) / rho, 1.0, 1e-14) << "rho/rho0 = " << s;
    }
    for (double P : {-1e7, 0.0, 1e3, 1e6, 1e8}) {
      const double back = eos::tait_pressure(eos::tait_density(P, l), l);
      // absolute: rounding of B (rho/rho0)^gamma, B ~ 3e8, a few ulps
      EXPECT_NEAR(back, P, 1e-6 * eos::tait_B(l)) << "P = " << P;
    }
    // Below p0 - B no density gives that pressure (the liquid would need rho < 0).
    EXPECT_EQ(eos::tait_density(p0 - 2.0 * eos::tait_B(l), l), 0.0);
  }
}

TEST(EosTait, ElasticEnergyIsTheIntegralOfPOverRhoSquared) {
  for (double p0 : kP0) {
    const LiquidParams l = seed_water(p0);
    EXPECT_EQ(eos::tait_energy(l.rho0, l), 0.0);  // e(rho0) = 0 by definition; both terms vanish exactly
    const auto e = [&](double rho) { return eos::tait_energy(rho, l); };
    // away from rho0 (where P - p0 = 0): |P| >= 0.03 B there, so a relative check is meaningful
    for (double s : {0.95, 0.99, 1.005, 1.01, 1.05}) {
      const double rho = s * l.rho0;
      const double P = eos::tait_pressure(rho, l);
      // step 1e-4 rho: truncation ~ gamma^2/6 (dx/rho)^2 ~ 1e-7; rounding of e (terms ~ B/rho) ~ 1e-9 of P/rho^2
      const double slope = central(e, rho, 1e-4 * rho);
      EXPECT_NEAR(slope / (P / (rho * rho)), 1.0, 1e-6) << "rho/rho0 = " << s;
    }
    // 1 % compression or expansion stores energy: the quadratic term c0^2 (drho/rho0)^2/2 dominates p0 drho/rho0^2.
    EXPECT_GT(e(1.01 * l.rho0), 0.0);
    EXPECT_GT(e(0.99 * l.rho0), 0.0);
  }
}

TEST(EosTait, StageSetsFluidPressureAndReportsElasticEnergy) {
  Params prm;
  prm.physics.eos = EosType::Tait;
  prm.liquid = seed_water(101325.0);
  auto stage = make_eos_tait();
  test::StageBench b(prm, 1, 6, stage->needs() | stage->writes() | FieldSet{}.add(Field::Mass).add(Field::H));
  for (std::size_t i = 0; i < 6; ++i) {
    b.p.x[0][i] = 0.1 * i;
    b.p[Field::Mass][i] = 1.0 + i;
    b.p[Field::H][i] = 0.1;
    b.p[Field::Density][i] = prm.liquid.rho0 * (1.0 + 0.01 * i);  // compressed: P >= p0, no tension floor
    b.p.kind[i] = static_cast<std::uint8_t>(i >= 4 ? Kind::Wall : Kind::Fluid);
    b.p[Field::Pressure][i] = -1.0;  // a marker: walls are not the EOS stage's business
  }
  b.p.partition_by_kind();
  b.prepare(FieldSet{});
  EXPECT_TRUE(b.run(*stage));
  double energy = 0.0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const double rho = b.p[Field::Density][i];
    if (b.p.is_wall(i)) {
      EXPECT_EQ(b.p[Field::Pressure][i], -1.0);
      continue;
    }
    EXPECT_EQ(b.p[Field::Pressure][i], eos::tait_pressure(rho, prm.liquid));
    EXPECT_EQ(b.p[Field::SoundSpeed][i], eos::tait_sound_speed(rho, prm.liquid));
    energy += b.p[Field::Mass][i] * eos::tait_energy(rho, prm.liquid);
  }
  EXPECT_GT(energy, 0.0);
  EXPECT_NEAR(stage->internal_energy(b.context()), energy, 1e-14 * energy);  // the same four terms
}

}  // namespace
}  // namespace sph
