// The osculating two-body orbit against exact values: a circular orbit (e = 0, q = r), an orbit seen
// at any true anomaly (r = p / (1 + e cos f)), a nearly radial one, an unbound one, and the leapfrog's
// expected energy error and the timestep that keeps it within a bound.
#include "gravity/osculating_orbit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sph::gravity {
namespace {

constexpr double kMu = 4.0 * std::numbers::pi * std::numbers::pi;  // G Msun in AU^3 / yr^2

TEST(GravityOsculatingOrbit, CircularOrbitHasNoEccentricityAndItsRadiusAsPericentre) {
  const double r = 2.0, v = std::sqrt(kMu / r);
  const OsculatingOrbit o = osculating_orbit({0, r, 0}, {-v, 0, 0}, kMu);
  EXPECT_NEAR(o.e, 0.0, 1e-7);  // sqrt of a round-off difference
  EXPECT_NEAR(o.q, r, 1e-12 * r);
  EXPECT_NEAR(o.energy, -kMu / (2.0 * r), 1e-12 * kMu / r);
  EXPECT_NEAR(o.L, std::sqrt(kMu * r), 1e-12 * std::sqrt(kMu * r));
  EXPECT_NEAR(o.t_q, std::sqrt(r * r * r / kMu), 1e-12);
  EXPECT_TRUE(o.bound());
  EXPECT_NEAR(leapfrog_energy_error(o, 0.01), 0.0, 1e-9);  // a circle at a fixed dt keeps its energy
}

TEST(GravityOsculatingOrbit, AnyPointOfAnEllipseGivesItsElements) {
  const double a = 1.5, e = 0.6, p = a * (1.0 - e * e);
  for (double f : {0.0, 0.7, 2.0, std::numbers::pi, 4.5}) {
    const double r = p / (1.0 + e * std::cos(f)), s = std::sqrt(kMu / p);
    const double vr = s * e * std::sin(f), vt = s * (1.0 + e * std::cos(f));
    const Vec3 x{r * std::cos(f), r * std::sin(f), 0.0};
    const Vec3 v{vr * std::cos(f) - vt * std::sin(f), vr * std::sin(f) + vt * std::cos(f), 0.0};
    const OsculatingOrbit o = osculating_orbit(x, v, kMu);
    EXPECT_NEAR(o.energy, -kMu / (2.0 * a), 1e-12 * kMu) << f;  // vis-viva
    EXPECT_NEAR(o.L, std::sqrt(kMu * p), 1e-12 * std::sqrt(kMu * p)) << f;
    EXPECT_NEAR(o.e, e, 1e-12) << f;
    EXPECT_NEAR(o.q, a * (1.0 - e), 1e-12) << f;
  }
}

TEST(GravityOsculatingOrbit, NearlyRadialOrbitFromAphelion) {
  // the kepler scene's start: r0 = 1 at aphelion, v = sqrt(mu (1 - e) / r0); q = r0 (1 - e) / (1 + e)
  const double e = 0.99, v = std::sqrt(kMu * (1.0 - e));
  const OsculatingOrbit o = osculating_orbit({1, 0, 0}, {0, v, 0}, kMu);
  const double q = (1.0 - e) / (1.0 + e);
  EXPECT_NEAR(o.e, e, 1e-12);
  EXPECT_NEAR(o.q, q, 1e-12 * q);
  EXPECT_NEAR(o.t_q, std::sqrt(q * q * q / kMu), 1e-12 * o.t_q);
  // released at rest: a radial orbit (q = 0) no fixed dt resolves
  const OsculatingOrbit fall = osculating_orbit({1, 0, 0}, {0, 0, 0}, kMu);
  EXPECT_NEAR(fall.e, 1.0, 1e-12);
  EXPECT_EQ(fall.q, 0.0);
  EXPECT_TRUE(std::isinf(leapfrog_energy_error(fall, 1e-6)));
}

TEST(GravityOsculatingOrbit, FasterThanEscapeIsUnbound) {
  const double r = 1.0, v = 1.01 * std::sqrt(2.0 * kMu / r);
  const OsculatingOrbit o = osculating_orbit({r, 0, 0}, {0, v, 0}, kMu);
  EXPECT_FALSE(o.bound());
  EXPECT_GT(o.e, 1.0);
  EXPECT_NEAR(o.q, r, 1e-12);  // started at its pericentre
}

TEST(GravityOsculatingOrbit, TimestepForABoundInvertsTheExpectedError) {
  const double e = 0.9, v = std::sqrt(kMu * (1.0 - e));
  const OsculatingOrbit o = osculating_orbit({1, 0, 0}, {0, v, 0}, kMu);
  const double dt = 0.002, err = leapfrog_energy_error(o, dt);
  EXPECT_NEAR(err, kLeapfrogEnergyC * e * (dt / o.t_q) * (dt / o.t_q), 1e-12 * err);
  EXPECT_NEAR(leapfrog_dt_for(o, err), dt, 1e-12);
  EXPECT_NEAR(leapfrog_energy_error(o, leapfrog_dt_for(o, 1e-4)), 1e-4, 1e-16);
}

}  // namespace
}  // namespace sph::gravity
