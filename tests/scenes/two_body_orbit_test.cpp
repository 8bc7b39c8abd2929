// The tabulated two-body orbit of the colliding polytropes' reference against closed forms: the fall
// from rest (seed 003 eq. 2.17), the radial parabolic fall r^(3/2) = r0^(3/2) - 3/2 sqrt(2 mu) t, and
// the periapsis of an encounter with an impact parameter.
#include "reference/two_body_orbit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/nbody_reference.h"

namespace sph::scenes {
namespace {

TEST(TwoBodyOrbit, FallFromRestMatchesEquation217) {
  const double r0 = 4.0, mu = 2.0;
  const TwoBodyOrbit o({r0, 0, 0}, {0, 0, 0}, mu, 100.0, 0.1);
  for (double t : {0.5, 2.0, 4.0, 5.5})
    EXPECT_NEAR(o.separation(t), fall_separation(r0, mu, t), 1e-9 * r0) << t;
  // r = r0 cos^2(theta): half way at theta = pi/4
  EXPECT_NEAR(o.time_to(2.0), (std::numbers::pi / 4.0 + 0.5) / std::sqrt(2.0 * mu / (r0 * r0 * r0)), 1e-6);
  EXPECT_TRUE(std::isnan(o.separation(fall_time(r0, mu))));  // the table ends at r0/40
}

TEST(TwoBodyOrbit, RadialParabolaAndItsContactTime) {
  // d = 4, v = sqrt(2 mu / d) = 1: the colliding polytropes' head-on start
  const double mu = 2.0;
  const TwoBodyOrbit o({4, 0, 0}, {-1, 0, 0}, mu, 20.0, 0.1);
  auto exact = [&](double t) { return std::pow(8.0 - 1.5 * std::sqrt(2.0 * mu) * t, 2.0 / 3.0); };
  for (double t : {0.5, 1.0, 1.7, 2.3, 2.6}) EXPECT_NEAR(o.separation(t), exact(t), 1e-9) << t;
  EXPECT_NEAR(o.time_to(2.0), (8.0 - std::pow(2.0, 1.5)) / 3.0, 1e-6);  // surfaces of R = 1 stars touch
  EXPECT_NEAR(o.time_to(1.0), 7.0 / 3.0, 1e-6);
  EXPECT_EQ(o.time_to(4.0), 0.0);
}

TEST(TwoBodyOrbit, OffsetEncounterReachesItsPeriapsis) {
  // the scene's start with b = 1: h = b v = 1, mu = 2, E = v^2/2 - mu/sqrt(17) > 0 (a slight hyperbola);
  // periapsis q = p / (1 + e), p = h^2 / mu, e = sqrt(1 + 2 E h^2 / mu^2); then the bodies separate again
  const double mu = 2.0, E = 0.5 - mu / std::sqrt(17.0), p = 1.0 / mu, e = std::sqrt(1.0 + 2.0 * E / (mu * mu));
  const TwoBodyOrbit o({4, 1, 0}, {-1, 0, 0}, mu, 20.0, 0.01);
  double closest = 1e300;
  for (int k = 0; k <= 200000; ++k) closest = std::min(closest, o.separation(20.0 * k / 200000.0));
  EXPECT_NEAR(closest, p / (1.0 + e), 1e-7);
  EXPECT_GT(o.separation(20.0), 4.0);
}

}  // namespace
}  // namespace sph::scenes
