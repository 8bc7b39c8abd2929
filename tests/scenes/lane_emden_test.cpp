// The Lane-Emden solver against its closed forms (n = 0, 1, 5) and the polytrope's scales.
#include "reference/lane_emden.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sph::scenes {
namespace {

TEST(LaneEmden, MatchesTheClosedForms) {
  const LaneEmden n0(0.0), n1(1.0), n5(5.0);
  EXPECT_NEAR(n0.xi1(), std::sqrt(6.0), 1e-8);
  EXPECT_NEAR(n1.xi1(), std::numbers::pi, 1e-8);
  EXPECT_GE(n5.xi1(), 50.0);  // infinite radius
  for (double xi : {0.01, 0.3, 1.0, 2.0, 2.4}) {
    EXPECT_NEAR(n0.theta(xi), 1.0 - xi * xi / 6.0, 1e-10) << xi;
    EXPECT_NEAR(n1.theta(xi), std::sin(xi) / xi, 1e-10) << xi;
    EXPECT_NEAR(n1.dtheta(xi), (xi * std::cos(xi) - std::sin(xi)) / (xi * xi), 1e-9) << xi;
  }
  for (double xi : {0.01, 1.0, 3.0, 10.0, 30.0}) EXPECT_NEAR(n5.theta(xi), 1.0 / std::sqrt(1.0 + xi * xi / 3.0), 1e-9) << xi;
  // mass: -xi^2 theta' at the surface is pi for n = 1 and 2 sqrt(6) for n = 0
  EXPECT_NEAR(n1.mass(n1.xi1()), std::numbers::pi, 1e-7);
  EXPECT_NEAR(n0.mass(n0.xi1()), 2.0 * std::sqrt(6.0), 1e-7);
}

TEST(LaneEmden, PolytropeScalesOfTheN1Star) {
  // n = 1, G = M = 1, K = 2/pi: R = 1 and rho_c = pi/4 (M = 4 pi alpha^3 rho_c pi, alpha = 1/pi)
  const LaneEmden n1(1.0);
  const PolytropeScales s = polytrope_scales(n1, 1.0, 2.0 / std::numbers::pi, 1.0);
  EXPECT_NEAR(s.R, 1.0, 1e-8);
  EXPECT_NEAR(s.rho_c, std::numbers::pi / 4.0, 1e-8);
}

}  // namespace
}  // namespace sph::scenes
